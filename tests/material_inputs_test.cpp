// shaders/common/material_inputs.glsl: what the BSDF receives for the glTF extension lobes, each
// factor times its texture channel (glTF packing), read through material_probe.comp.
#include <gtest/gtest.h>

#include <cmath>

#include "card_scene.h"
#include "render/material_probe.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

// One texel of every texture: RGBA = (0.2, 0.4, 0.6, 0.8), so each channel is recognisable.
constexpr float kTexel[4] = {51 / 255.0f, 102 / 255.0f, 153 / 255.0f, 204 / 255.0f};

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

struct Probe {
  Scene scene = test::make_card_camera_scene(0.0f);
  MaterialParameters m = test::black_material();
  uint32_t linear = 0, srgb = 1;  // texture entries on the one image

  Probe() {
    scene.images.push_back({"texel", 1, 1, {51, 102, 153, 204}});
    scene.textures.push_back({"linear", 0, abi::kTextureNearest});
    scene.textures.push_back({"srgb", 0, abi::kTextureNearest | abi::kTextureSrgb});
  }

  abi::MaterialInputsProbe run() {
    test::add_card(scene, "card", glm::mat4(1.0f), m);
    return MaterialProbe(test::context(), scene).at(0, 0, glm::vec2(0.25f, 0.25f));
  }
};

void expect_near(glm::vec3 actual, glm::vec3 expected, const char* what) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(actual[k], expected[k], 1e-5f) << what << "[" << k << "]";
}

TEST(MaterialInputs, FactorsAloneWithoutTextures) {
  Probe probe;
  probe.m.transmission_weight = 0.3f;
  probe.m.coat_weight = 0.5f;
  probe.m.coat_roughness = 0.25f;
  probe.m.fuzz_color = {0.1f, 0.2f, 0.3f};
  probe.m.fuzz_roughness = 0.7f;
  probe.m.specular_weight = 0.9f;
  probe.m.specular_color = {0.4f, 0.5f, 0.6f};
  probe.m.thin_film_weight = 0.8f;
  probe.m.thin_film_thickness = 420.0f;
  probe.m.specular_anisotropy = 0.6f;
  probe.m.specular_rotation = float(M_PI / 2);
  const abi::MaterialInputsProbe p = probe.run();
  EXPECT_FLOAT_EQ(p.transmissionWeight, 0.3f);
  EXPECT_FLOAT_EQ(p.coatWeight, 0.5f);
  EXPECT_FLOAT_EQ(p.coatRoughness, 0.25f);
  expect_near(p.coatNormal, {0, 0, 1}, "coat normal follows the geometry");
  expect_near(p.fuzzColor, {0.1f, 0.2f, 0.3f}, "fuzz colour");
  EXPECT_FLOAT_EQ(p.fuzzRoughness, 0.7f);
  EXPECT_FLOAT_EQ(p.specularWeight, 0.9f);
  expect_near(p.specularColor, {0.4f, 0.5f, 0.6f}, "specular colour");
  EXPECT_FLOAT_EQ(p.thinFilmWeight, 0.8f);
  EXPECT_FLOAT_EQ(p.thinFilmThickness, 420.0f);
  EXPECT_FLOAT_EQ(p.anisotropyStrength, 0.6f);
  // The card's tangent is +X and its bitangent +Y: a quarter turn points the direction along +Y.
  expect_near(p.anisotropyDirection, {0, 1, 0}, "anisotropy direction");
}

TEST(MaterialInputs, TexturesScaleTheFactorsByTheirGltfChannels) {
  Probe probe;
  probe.m.transmission_weight = probe.m.coat_weight = probe.m.coat_roughness = 0.5f;
  probe.m.fuzz_color = glm::vec3(0.5f);
  probe.m.fuzz_roughness = probe.m.specular_weight = probe.m.thin_film_weight = 0.5f;
  probe.m.specular_color = glm::vec3(0.5f);
  probe.m.thin_film_thickness_min = 100.0f;
  probe.m.thin_film_thickness = 600.0f;
  probe.m.specular_anisotropy = 0.5f;
  probe.m.specular_rotation = 0.0f;
  probe.m.coat_normal_scale = 1.0f;
  for (uint32_t* slot :
       {&probe.m.transmission_texture, &probe.m.clearcoat_texture,
        &probe.m.clearcoat_roughness_texture, &probe.m.clearcoat_normal_texture,
        &probe.m.sheen_roughness_texture, &probe.m.specular_texture, &probe.m.iridescence_texture,
        &probe.m.iridescence_thickness_texture, &probe.m.anisotropy_texture})
    *slot = probe.linear;
  probe.m.sheen_color_texture = probe.m.specular_color_texture = probe.srgb;
  const abi::MaterialInputsProbe p = probe.run();
  const auto [r, g, b, a] = kTexel;
  EXPECT_NEAR(p.transmissionWeight, 0.5f * r, 1e-5f) << "transmissionTexture.r";
  EXPECT_NEAR(p.coatWeight, 0.5f * r, 1e-5f) << "clearcoatTexture.r";
  EXPECT_NEAR(p.coatRoughness, 0.5f * g, 1e-5f) << "clearcoatRoughnessTexture.g";
  EXPECT_NEAR(p.fuzzRoughness, 0.5f * a, 1e-5f) << "sheenRoughnessTexture.a";
  EXPECT_NEAR(p.specularWeight, 0.5f * a, 1e-5f) << "specularTexture.a";
  EXPECT_NEAR(p.thinFilmWeight, 0.5f * r, 1e-5f) << "iridescenceTexture.r";
  EXPECT_NEAR(p.thinFilmThickness, 100.0f + 500.0f * g, 1e-3f) << "iridescenceThicknessTexture.g";
  EXPECT_NEAR(p.anisotropyStrength, 0.5f * b, 1e-5f) << "anisotropyTexture.b";
  const glm::vec3 colour =
      0.5f * glm::vec3(srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b));
  expect_near(p.fuzzColor, colour, "sheenColorTexture.rgb (sRGB)");
  expect_near(p.specularColor, colour, "specularColorTexture.rgb (sRGB)");
  // anisotropyTexture.rg and clearcoatNormalTexture.rgb in the card's frame (+X, +Y, +Z).
  expect_near(p.anisotropyDirection, glm::normalize(glm::vec3(2 * r - 1, 2 * g - 1, 0)),
              "anisotropy direction");
  expect_near(p.coatNormal, glm::normalize(glm::vec3(2 * r - 1, 2 * g - 1, 2 * b - 1)),
              "coat normal");
}

}  // namespace
}  // namespace hipr
