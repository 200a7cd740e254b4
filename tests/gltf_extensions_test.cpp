// glTF material extensions -> OpenPBR parameters (src/scene/gltf_material_table.cpp), alpha
// modes, KHR_texture_transform, TEXCOORD_1 and the handling of unsupported extensions.
#include <gtest/gtest.h>

#include <fstream>

#include <cmath>

#include "core/error.h"
#include "gltf_document.h"
#include "hipr/scene_loader.h"
#include "image/image_io.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using test::Document;

struct Loaded {
  Scene scene;
  std::string warnings;
  const MaterialParameters& material() const { return scene.materials[0].params; }
};

// The triangle document with `material` as its one material, two textures on one image
// (textures 0 and 1) and `extensions_used`; loaded with stderr captured.
Loaded load_with(const json& material, const std::vector<std::string>& extensions_used = {}) {
  Document doc = test::triangle_document();
  doc.gltf["materials"] = json::array({material});
  doc.gltf["images"] = json::array({{{"uri", "grey.png"}}});
  doc.gltf["textures"] = json::array({{{"source", 0}}, {{"source", 0}}});
  if (!extensions_used.empty()) doc.gltf["extensionsUsed"] = extensions_used;
  const fs::path dir = test::temp_dir("gltf-extensions");
  write_image(dir / "grey.png", ImageRGB{1, 1, {0.5f, 0.5f, 0.5f}});
  test::write_document(dir / "scene.gltf", doc);
  testing::internal::CaptureStderr();
  Loaded loaded;
  try {
    loaded.scene = load_scene(dir / "scene.gltf");
  } catch (...) {
    testing::internal::GetCapturedStderr();
    throw;
  }
  loaded.warnings = testing::internal::GetCapturedStderr();
  return loaded;
}

json texture(int index) { return {{"index", index}}; }

TEST(GltfExtensions, IorSpecularAndEmissiveStrength) {
  const Loaded l =
      load_with({{"extensions",
                  {{"KHR_materials_ior", {{"ior", 1.7}}},
                   {"KHR_materials_specular",
                    {{"specularFactor", 0.5},
                     {"specularColorFactor", {0.2, 0.3, 0.4}},
                     {"specularTexture", texture(0)},
                     {"specularColorTexture", texture(1)}}},
                   {"KHR_materials_emissive_strength", {{"emissiveStrength", 6.0}}}}}});
  const MaterialParameters& m = l.material();
  EXPECT_FLOAT_EQ(m.specular_ior, 1.7f);
  EXPECT_FLOAT_EQ(m.specular_weight, 0.5f);
  EXPECT_EQ(m.specular_color, glm::vec3(0.2f, 0.3f, 0.4f));
  EXPECT_FLOAT_EQ(m.emission_luminance, 6.0f);
  ASSERT_NE(m.specular_texture, abi::kInvalidIndex);
  ASSERT_NE(m.specular_color_texture, abi::kInvalidIndex);
  // The colour texture is sRGB, the factor texture linear; both read the one image's texels.
  EXPECT_TRUE(l.scene.textures[m.specular_color_texture].flags & abi::kTextureSrgb);
  EXPECT_FALSE(l.scene.textures[m.specular_texture].flags & abi::kTextureSrgb);
  EXPECT_EQ(l.scene.images.size(), 1u);
}

TEST(GltfExtensions, TransmissionWithVolumeIsThick) {
  const Loaded l =
      load_with({{"extensions",
                  {{"KHR_materials_transmission",
                    {{"transmissionFactor", 0.8}, {"transmissionTexture", texture(0)}}},
                   {"KHR_materials_volume",
                    {{"thicknessFactor", 0.1},
                     {"attenuationColor", {0.9, 0.5, 0.1}},
                     {"attenuationDistance", 0.25}}}}}});
  const MaterialParameters& m = l.material();
  EXPECT_FLOAT_EQ(m.transmission_weight, 0.8f);
  EXPECT_NE(m.transmission_texture, abi::kInvalidIndex);
  EXPECT_FALSE(m.flags & abi::kMaterialThinWalled);
  EXPECT_EQ(m.transmission_color, glm::vec3(0.9f, 0.5f, 0.1f));
  EXPECT_FLOAT_EQ(m.transmission_depth, 0.25f);
}

TEST(GltfExtensions, TransmissionWithoutVolumeIsThinAndTintedByBaseColour) {
  const Loaded l =
      load_with({{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}}},
                 {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}});
  EXPECT_TRUE(l.material().flags & abi::kMaterialThinWalled);
  EXPECT_EQ(l.material().transmission_color, glm::vec3(0.2f, 0.4f, 0.6f));
  EXPECT_EQ(l.material().transmission_depth, 0.0f);
  // A volume of zero thickness is thin too; an infinite attenuation distance absorbs nothing.
  const Loaded zero =
      load_with({{"extensions", {{"KHR_materials_volume", {{"thicknessFactor", 0.0}}}}}});
  EXPECT_TRUE(zero.material().flags & abi::kMaterialThinWalled);
  const Loaded clear =
      load_with({{"extensions", {{"KHR_materials_volume", {{"thicknessFactor", 1.0}}}}}});
  EXPECT_FALSE(clear.material().flags & abi::kMaterialThinWalled);
  EXPECT_EQ(clear.material().transmission_color, glm::vec3(1.0f));
  EXPECT_EQ(clear.material().transmission_depth, 0.0f);
}

TEST(GltfExtensions, ClearcoatBecomesCoat) {
  const Loaded l = load_with({{"extensions",
                               {{"KHR_materials_clearcoat",
                                 {{"clearcoatFactor", 0.7},
                                  {"clearcoatRoughnessFactor", 0.2},
                                  {"clearcoatTexture", texture(0)},
                                  {"clearcoatRoughnessTexture", texture(0)},
                                  {"clearcoatNormalTexture", {{"index", 1}, {"scale", 0.5}}}}}}}});
  const MaterialParameters& m = l.material();
  EXPECT_FLOAT_EQ(m.coat_weight, 0.7f);
  EXPECT_FLOAT_EQ(m.coat_roughness, 0.2f);
  EXPECT_FLOAT_EQ(m.coat_ior, 1.5f);
  EXPECT_EQ(m.coat_color, glm::vec3(1.0f));
  EXPECT_EQ(m.coat_darkening, 0.0f);
  EXPECT_FLOAT_EQ(m.coat_normal_scale, 0.5f);
  EXPECT_NE(m.clearcoat_texture, abi::kInvalidIndex);
  EXPECT_EQ(m.clearcoat_roughness_texture, m.clearcoat_texture)
      << "equal references share one entry";
  EXPECT_NE(m.clearcoat_normal_texture, abi::kInvalidIndex);
}

TEST(GltfExtensions, SheenBecomesFuzz) {
  const Loaded l = load_with({{"extensions",
                               {{"KHR_materials_sheen",
                                 {{"sheenColorFactor", {0.5, 0.25, 0.1}},
                                  {"sheenRoughnessFactor", 0.3},
                                  {"sheenColorTexture", texture(0)},
                                  {"sheenRoughnessTexture", texture(1)}}}}}});
  const MaterialParameters& m = l.material();
  EXPECT_EQ(m.fuzz_weight, 1.0f);
  EXPECT_EQ(m.fuzz_color, glm::vec3(0.5f, 0.25f, 0.1f));
  EXPECT_FLOAT_EQ(m.fuzz_roughness, 0.3f);
  EXPECT_TRUE(l.scene.textures[m.sheen_color_texture].flags & abi::kTextureSrgb);
  EXPECT_FALSE(l.scene.textures[m.sheen_roughness_texture].flags & abi::kTextureSrgb);
  // Black sheen (glTF's default colour) is no sheen.
  EXPECT_EQ(
      load_with({{"extensions", {{"KHR_materials_sheen", json::object()}}}}).material().fuzz_weight,
      0.0f);
}

TEST(GltfExtensions, IridescenceBecomesThinFilmInNanometres) {
  const Loaded l = load_with({{"extensions",
                               {{"KHR_materials_iridescence",
                                 {{"iridescenceFactor", 0.9},
                                  {"iridescenceIor", 1.8},
                                  {"iridescenceThicknessMinimum", 200.0},
                                  {"iridescenceThicknessMaximum", 650.0},
                                  {"iridescenceTexture", texture(0)},
                                  {"iridescenceThicknessTexture", texture(1)}}}}}});
  const MaterialParameters& m = l.material();
  EXPECT_FLOAT_EQ(m.thin_film_weight, 0.9f);
  EXPECT_FLOAT_EQ(m.thin_film_ior, 1.8f);
  EXPECT_FLOAT_EQ(m.thin_film_thickness_min, 200.0f);
  EXPECT_FLOAT_EQ(m.thin_film_thickness, 650.0f);
  EXPECT_NE(m.iridescence_texture, abi::kInvalidIndex);
  EXPECT_NE(m.iridescence_thickness_texture, abi::kInvalidIndex);
  // glTF's defaults: 100-400 nm, ior 1.3.
  const MaterialParameters d =
      load_with({{"extensions", {{"KHR_materials_iridescence", json::object()}}}}).material();
  EXPECT_FLOAT_EQ(d.thin_film_thickness_min, 100.0f);
  EXPECT_FLOAT_EQ(d.thin_film_thickness, 400.0f);
  EXPECT_FLOAT_EQ(d.thin_film_ior, 1.3f);
}

TEST(GltfExtensions, AnisotropyKeepsRadians) {
  const Loaded l = load_with({{"extensions",
                               {{"KHR_materials_anisotropy",
                                 {{"anisotropyStrength", 0.6},
                                  {"anisotropyRotation", 1.25},
                                  {"anisotropyTexture", texture(0)}}}}}});
  EXPECT_FLOAT_EQ(l.material().specular_anisotropy, 0.6f);
  EXPECT_FLOAT_EQ(l.material().specular_rotation, 1.25f);
  EXPECT_NE(l.material().anisotropy_texture, abi::kInvalidIndex);
}

TEST(GltfExtensions, DiffuseTransmissionBecomesThinSubsurface) {
  const Loaded l = load_with({{"extensions",
                               {{"KHR_materials_diffuse_transmission",
                                 {{"diffuseTransmissionFactor", 0.4},
                                  {"diffuseTransmissionColorFactor", {0.1, 0.8, 0.2}}}}}}});
  EXPECT_FLOAT_EQ(l.material().subsurface_weight, 0.4f);
  EXPECT_EQ(l.material().subsurface_color, glm::vec3(0.1f, 0.8f, 0.2f));
  EXPECT_TRUE(l.material().flags & abi::kMaterialThinWalled);
}

// glTF's Abbe number is 20 / dispersion; OpenPBR's is abbe_number / scale, abbe_number 20.
TEST(GltfExtensions, DispersionBecomesTheDispersionScale) {
  const Loaded l = load_with({{"extensions",
                               {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                {"KHR_materials_volume", {{"thicknessFactor", 0.5}}},
                                {"KHR_materials_dispersion", {{"dispersion", 0.4}}}}}});
  EXPECT_FLOAT_EQ(l.material().transmission_dispersion_scale, 0.4f);
  EXPECT_FLOAT_EQ(l.material().transmission_dispersion_abbe_number, 20.0f);
  const Loaded none = load_with(json::object());
  EXPECT_EQ(none.material().transmission_dispersion_scale, 0.0f);
}

TEST(GltfExtensions, ValuesOutOfRangeAreClamped) {
  const Loaded l = load_with({{"extensions",
                               {{"KHR_materials_transmission", {{"transmissionFactor", 3.0}}},
                                {"KHR_materials_ior", {{"ior", 0.5}}}}}});
  EXPECT_EQ(l.material().transmission_weight, 1.0f);
  EXPECT_EQ(l.material().specular_ior, 1.0f);
}

TEST(GltfAlphaModes, MaskBlendAndOpaque) {
  const json base = {{"baseColorFactor", {1, 1, 1, 0.4}}, {"baseColorTexture", texture(0)}};
  const Loaded mask =
      load_with({{"pbrMetallicRoughness", base}, {"alphaMode", "MASK"}, {"alphaCutoff", 0.3}});
  EXPECT_FLOAT_EQ(mask.material().geometry_opacity, 0.4f);
  EXPECT_FLOAT_EQ(mask.material().alpha_cutoff, 0.3f);
  EXPECT_FALSE(material_is_opaque(mask.material()));
  const Loaded blend = load_with({{"pbrMetallicRoughness", base}, {"alphaMode", "BLEND"}});
  EXPECT_FLOAT_EQ(blend.material().geometry_opacity, 0.4f);
  EXPECT_LT(blend.material().alpha_cutoff, 0.0f);
  EXPECT_FALSE(material_is_opaque(blend.material()));
  // OPAQUE ignores alpha, of the factor and of the texture: the geometry stays opaque.
  const Loaded opaque = load_with({{"pbrMetallicRoughness", base}});
  EXPECT_EQ(opaque.material().geometry_opacity, 1.0f);
  EXPECT_TRUE(opaque.material().flags & abi::kMaterialIgnoreTextureAlpha);
  EXPECT_TRUE(material_is_opaque(opaque.material()));
  // MASK's default cutoff is 0.5.
  EXPECT_FLOAT_EQ(load_with({{"alphaMode", "MASK"}}).material().alpha_cutoff, 0.5f);
}

TEST(GltfTextureTransform, OffsetRotationScaleAndTexCoordOverride) {
  const json transform = {
      {"offset", {0.25, -0.5}}, {"rotation", 0.5}, {"scale", {2.0, 3.0}}, {"texCoord", 1}};
  const Loaded l =
      load_with({{"pbrMetallicRoughness",
                  {{"baseColorTexture",
                    {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}},
                   {"metallicRoughnessTexture", texture(0)}}}},
                {"KHR_texture_transform"});
  const Texture& t = l.scene.textures[l.material().base_color_texture];
  // uv' = T(offset) R(rotation) S(scale) uv, the spec's order; u' = cos*u + sin*v before the
  // offset.
  const float c = std::cos(0.5f), s = std::sin(0.5f);
  const glm::vec2 uv(0.3f, 0.7f), scaled(0.6f, 2.1f);
  const glm::vec2 expected(c * scaled.x + s * scaled.y + 0.25f,
                           -s * scaled.x + c * scaled.y - 0.5f);
  EXPECT_NEAR(glm::dot(t.uv_transform_u, glm::vec3(uv, 1.0f)), expected.x, 1e-5f);
  EXPECT_NEAR(glm::dot(t.uv_transform_v, glm::vec3(uv, 1.0f)), expected.y, 1e-5f);
  EXPECT_TRUE(t.flags & abi::kTextureUv1) << "the transform's texCoord overrides the textureInfo's";
  // The same texture without a transform is another entry on the same texels.
  const Texture& plain = l.scene.textures[l.material().metallic_roughness_texture];
  EXPECT_NE(l.material().metallic_roughness_texture, l.material().base_color_texture);
  EXPECT_EQ(plain.image, t.image);
  EXPECT_EQ(plain.uv_transform_u, glm::vec3(1, 0, 0));
  EXPECT_FALSE(plain.flags & abi::kTextureUv1);
  EXPECT_EQ(l.scene.images.size(), 1u);
}

TEST(GltfTexCoords, SecondUvSetIsLoadedAndSelected) {
  Document doc = test::triangle_document();
  const int uv0 = doc.add_accessor(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2", 3);
  const int uv1 =
      doc.add_accessor(std::vector<float>{0.5f, 0.5f, 0.25f, 0.75f, 1, 1}, test::kFloat, "VEC2", 3);
  doc.primitive()["attributes"]["TEXCOORD_0"] = uv0;
  doc.primitive()["attributes"]["TEXCOORD_1"] = uv1;
  doc.gltf["images"] = json::array({{{"uri", "grey.png"}}});
  doc.gltf["textures"] = json::array({{{"source", 0}}});
  doc.gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0},
                                                                          {"texCoord", 1}};
  doc.gltf["materials"][0]["emissiveTexture"] = {{"index", 0}};
  const fs::path dir = test::temp_dir("gltf-texcoord1");
  write_image(dir / "grey.png", ImageRGB{1, 1, {0.5f, 0.5f, 0.5f}});
  test::write_document(dir / "scene.gltf", doc);
  const Scene scene = load_scene(dir / "scene.gltf");
  const MeshPrimitive& p = scene.meshes[0].primitives[0];
  EXPECT_EQ(p.uvs1, (std::vector<glm::vec2>{{0.5f, 0.5f}, {0.25f, 0.75f}, {1, 1}}));
  EXPECT_EQ(p.uvs[1], glm::vec2(1, 0));
  EXPECT_TRUE(scene.textures[scene.materials[0].params.base_color_texture].flags &
              abi::kTextureUv1);
  EXPECT_FALSE(scene.textures[scene.materials[0].params.emission_texture].flags & abi::kTextureUv1);
  // Without TEXCOORD_1 the second set is zeros, one per vertex.
  const Scene plain = load_scene(test::asset("cornell_box.gltf"));
  for (const Mesh& mesh : plain.meshes)
    for (const MeshPrimitive& q : mesh.primitives)
      EXPECT_EQ(q.uvs1, std::vector<glm::vec2>(q.positions.size(), glm::vec2(0)));
}

TEST(GltfExtensionSupport, UnknownOptionalExtensionWarnsOncePerExtension) {
  const Loaded l = load_with(
      json::object(), {"EXT_hipr_made_up", "KHR_materials_dispersion", "KHR_materials_variants",
                       "EXT_hipr_other", "KHR_materials_sheen"});
  const auto lines = test::lines_of(l.warnings);
  ASSERT_EQ(lines.size(), 2u) << l.warnings;  // dispersion, variants and sheen are read
  EXPECT_NE(lines[0].find("EXT_hipr_made_up is not supported"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("EXT_hipr_other is not supported"), std::string::npos) << lines[1];
  for (const std::string& line : lines)
    EXPECT_EQ(line.rfind("hipr: warning: scene.gltf: ", 0), 0u) << line;
}

// KHR_materials_unlit: the base colour (factor and texture) shown as emission, nothing reflected.
TEST(GltfExtensions, UnlitEmitsItsBaseColourAndReflectsNothing) {
  const Loaded l = load_with({{"pbrMetallicRoughness",
                               {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}},
                                {"baseColorTexture", texture(0)},
                                {"metallicFactor", 1.0},
                                {"metallicRoughnessTexture", texture(1)}}},
                              {"normalTexture", texture(1)},
                              {"extensions", {{"KHR_materials_unlit", json::object()}}}},
                             {"KHR_materials_unlit"});
  const MaterialParameters& p = l.scene.materials[0].params;
  EXPECT_EQ(p.emission_color, glm::vec3(0.2f, 0.4f, 0.6f));
  EXPECT_EQ(p.emission_luminance, 1.0f);
  EXPECT_NE(p.base_color_texture, kNoTexture);
  EXPECT_EQ(p.emission_texture, p.base_color_texture);
  EXPECT_EQ(p.base_weight, 0.0f);
  EXPECT_EQ(p.specular_weight, 0.0f);
  EXPECT_EQ(p.base_metalness, 0.0f);
  EXPECT_EQ(p.metallic_roughness_texture, kNoTexture);
  EXPECT_EQ(p.normal_texture, kNoTexture);
  EXPECT_TRUE(l.warnings.empty()) << l.warnings;
}

// KHR_materials_pbrSpecularGlossiness: a dielectric keeps its diffuse colour, a metal's specular
// colour becomes its base colour; glossiness turns into roughness.
TEST(GltfExtensions, SpecularGlossinessFactorsBecomeMetalRough) {
  const auto load = [](json ext) {
    return load_with({{"extensions", {{"KHR_materials_pbrSpecularGlossiness", ext}}}},
                     {"KHR_materials_pbrSpecularGlossiness"})
        .scene.materials[0]
        .params;
  };
  const MaterialParameters plastic = load({{"diffuseFactor", {0.5, 0.25, 0.125, 1.0}},
                                           {"specularFactor", {0.04, 0.04, 0.04}},
                                           {"glossinessFactor", 0.7}});
  EXPECT_EQ(plastic.base_metalness, 0.0f);
  EXPECT_NEAR(plastic.base_color.r, 0.5f, 1e-4f);
  EXPECT_NEAR(plastic.base_color.b, 0.125f, 1e-4f);
  EXPECT_NEAR(plastic.specular_roughness, 0.3f, 1e-6f);
  const MaterialParameters gold = load({{"diffuseFactor", {0.0, 0.0, 0.0, 1.0}},
                                        {"specularFactor", {1.0, 0.766, 0.336}},
                                        {"glossinessFactor", 0.9}});
  EXPECT_NEAR(gold.base_metalness, 1.0f, 1e-3f);
  EXPECT_NEAR(gold.base_color.g, 0.766f, 1e-3f);
  EXPECT_NEAR(gold.specular_roughness, 0.1f, 1e-6f);
}

// With textures the conversion is baked per texel: two new images, sampled as the diffuse one.
TEST(GltfExtensions, SpecularGlossinessTexturesAreBakedPerTexel) {
  const Loaded l = load_with({{"extensions",
                               {{"KHR_materials_pbrSpecularGlossiness",
                                 {{"diffuseTexture", texture(0)},
                                  {"specularGlossinessTexture", texture(1)},
                                  {"specularFactor", {0.0, 0.0, 0.0}},
                                  {"glossinessFactor", 0.5}}}}}},
                             {"KHR_materials_pbrSpecularGlossiness"});
  const Scene& scene = l.scene;
  const MaterialParameters& p = scene.materials[0].params;
  EXPECT_EQ(p.base_color, glm::vec3(1.0f));  // the baked image holds it all
  EXPECT_EQ(p.base_metalness, 1.0f);
  ASSERT_NE(p.base_color_texture, kNoTexture);
  ASSERT_NE(p.metallic_roughness_texture, kNoTexture);
  const Image& base = scene.images[scene.textures[p.base_color_texture].image];
  const Image& metal_rough = scene.images[scene.textures[p.metallic_roughness_texture].image];
  EXPECT_NE(base.name.find("spec-gloss"), std::string::npos);
  // grey.png is 0.5 linear: with a black specular the base colour is the diffuse over the 0.96
  // a dielectric's diffuse keeps (0.5208: sRGB 191), metalness 0, roughness 1 - 0.5 x 1 = 0.5.
  EXPECT_NEAR(base.rgba8[0], 191, 1);
  EXPECT_EQ(metal_rough.rgba8[2], 0);
  EXPECT_NEAR(metal_rough.rgba8[1], 128, 1);
  EXPECT_TRUE(scene.textures[p.base_color_texture].flags & kTextureSrgb);
  EXPECT_FALSE(scene.textures[p.metallic_roughness_texture].flags & kTextureSrgb);
}

// README's table of extensions is the loader's, row for row.
TEST(GltfExtensionSupport, ReadmeTableIsTheLoadersTable) {
  std::ifstream readme(fs::path(HIPR_ASSETS_DIR) / ".." / ".." / "README.md");
  ASSERT_TRUE(readme) << "README.md not found";
  std::vector<std::string> rows;
  for (std::string line; std::getline(readme, line);)
    if (line.rfind("  | `", 0) == 0) rows.push_back(line);
  std::vector<std::string> expected;
  for (const GltfExtension& e : gltf_extension_table())
    expected.push_back("  | `" + e.name + "` | " + e.meaning + " |");
  EXPECT_EQ(rows, expected);
  EXPECT_GE(expected.size(), 20u);
}

TEST(GltfExtensionSupport, EveryImplementedExtensionMayBeRequired) {
  for (const std::string& ext : supported_gltf_extensions()) {
    Document doc = test::triangle_document();
    doc.gltf["extensionsUsed"] = {ext};
    doc.gltf["extensionsRequired"] = {ext};
    const fs::path file = test::temp_dir("gltf-required") / "tri.gltf";
    test::write_document(file, doc);
    EXPECT_NO_THROW(load_scene(file)) << ext;
  }
}

TEST(GltfExtensionSupport, RequiredUnknownExtensionIsRefused) {
  Document doc = test::triangle_document();
  doc.gltf["extensionsUsed"] = {"KHR_materials_volume_scatter"};
  doc.gltf["extensionsRequired"] = {"KHR_materials_volume_scatter"};
  const fs::path file = test::temp_dir("gltf-required-unknown") / "tri.gltf";
  test::write_document(file, doc);
  try {
    load_scene(file);
    ADD_FAILURE() << "loaded a scene that requires an unsupported extension";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "tri.gltf: requires unsupported glTF extension KHR_materials_volume_scatter");
  }
}

}  // namespace
}  // namespace hipr
