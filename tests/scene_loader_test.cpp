// The glTF loader: what it makes of our own scenes, how it confines file access to the scene
// folder, how it reports broken input, and (when ../shared/scenes exists) real-world files.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "core/error.h"
#include "gltf_document.h"
#include "hipr/scene_loader.h"
#include "image/image_io.h"
#include "scene/base64.h"
#include "scene/default_camera.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

using test::Document;
using test::kFloat;
using test::kUnsignedShort;
using test::triangle_document;
using test::write_bytes;
using test::write_document;
constexpr int kTriangleStrip = 5;

// ---- Our shipped scenes -------------------------------------------------------------------

int node_named(const Scene& scene, const std::string& name) {
  for (size_t i = 0; i < scene.nodes.size(); ++i)
    if (scene.nodes[i].name == name) return int(i);
  return -1;
}

const Material* material_named(const Scene& scene, const std::string& name) {
  for (const Material& m : scene.materials)
    if (m.name == name) return &m;
  return nullptr;
}

glm::mat4 instance_world(const Scene& scene, const std::string& node) {
  const int index = node_named(scene, node);
  for (const Instance& instance : scene.instances())
    if (int(instance.node) == index) return instance.world;
  ADD_FAILURE() << "no instance for node " << node;
  return glm::mat4(1.0f);
}

void expect_near(const glm::vec3& actual, const glm::vec3& expected, float tolerance,
                 const std::string& what) {
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(actual[k], expected[k], tolerance) << what << " [" << k << "]";
}

TEST(ShippedScenes, CornellBoxStructure) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  std::vector<std::string> nodes;
  for (const Node& node : scene.nodes) nodes.push_back(node.name);
  EXPECT_EQ(nodes,
            (std::vector<std::string>{"floor", "ceiling", "back_wall", "left_wall", "right_wall",
                                      "short_block", "tall_block", "light", "camera"}));
  ASSERT_EQ(scene.meshes.size(), 8u);
  EXPECT_EQ(scene.meshes[5].name, "short_block");
  std::vector<std::string> materials;
  for (const Material& m : scene.materials) materials.push_back(m.name);
  // glTF's default material is appended for primitives that name none.
  EXPECT_EQ(materials, (std::vector<std::string>{"white", "red", "green", "light", "default"}));
  EXPECT_EQ(scene.instances().size(), 8u);
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_EQ(scene.content_hash.size(), 16u);

  size_t triangles = 0;
  for (const Mesh& mesh : scene.meshes)
    for (const MeshPrimitive& p : mesh.primitives) {
      triangles += p.indices.size() / 3;
      EXPECT_EQ(p.normals.size(), p.positions.size());
      EXPECT_EQ(p.tangents.size(), p.positions.size());
      EXPECT_EQ(p.uvs.size(), p.positions.size());
    }
  EXPECT_EQ(triangles, 36u);
}

TEST(ShippedScenes, CornellBoxMaterials) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  const Material* light = material_named(scene, "light");
  ASSERT_NE(light, nullptr);
  // emission = emissiveFactor (colour) x KHR_materials_emissive_strength (luminance)
  expect_near(light->params.emission_color, {1.0f, 0.7059f, 0.2353f}, 1e-6f, "emission_color");
  EXPECT_FLOAT_EQ(light->params.emission_luminance, 17.0f);

  const Material* red = material_named(scene, "red");
  ASSERT_NE(red, nullptr);
  expect_near(red->params.base_color, {0.63f, 0.065f, 0.05f}, 1e-6f, "red base_color");
  EXPECT_EQ(red->params.specular_weight, 0.0f);  // KHR_materials_specular specularFactor 0
  EXPECT_EQ(red->params.specular_roughness, 1.0f);
  EXPECT_EQ(red->params.base_metalness, 0.0f);
  EXPECT_EQ(red->params.emission_color, glm::vec3(0.0f));
}

TEST(ShippedScenes, CornellBoxCamera) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  ASSERT_EQ(scene.camera_node(), node_named(scene, "camera"));
  const Camera camera = resolve_camera(scene);
  EXPECT_NEAR(camera.yfov, 2.0 * std::atan(0.0125 / 0.035), 1e-6);  // 35 mm lens, 25 mm film
  expect_near(glm::vec3(camera.camera_to_world[3]), {0.278f, 0.273f, -0.8f}, 1e-6f,
              "camera position");
  // Cameras look down their local -Z; this one is turned to look into the box, down +Z.
  const glm::vec3 forward = glm::vec3(camera.camera_to_world * glm::vec4(0, 0, -1, 0));
  expect_near(forward, {0.0f, 0.0f, 1.0f}, 1e-6f, "camera forward");
  expect_near(glm::vec3(camera.camera_to_world[1]), {0.0f, 1.0f, 0.0f}, 1e-6f, "camera up");
}

TEST(ShippedScenes, MovedSceneShiftsTallBlockOnly) {
  const Scene before = load_scene(test::asset("cornell_box.gltf"));
  const Scene after = load_scene(test::asset("cornell_box_moved.gltf"));
  const glm::mat4 a = instance_world(before, "tall_block"), b = instance_world(after, "tall_block");
  expect_near(glm::vec3(b[3] - a[3]), {0.06f, 0.0f, -0.08f}, 1e-6f, "tall_block translation");
  for (int column = 0; column < 3; ++column)
    expect_near(glm::vec3(b[column]), glm::vec3(a[column]), 1e-7f, "tall_block rotation");
  for (const char* node : {"floor", "short_block", "light"})
    EXPECT_EQ(instance_world(before, node), instance_world(after, node)) << node;
  EXPECT_NE(before.content_hash, after.content_hash);
}

TEST(ShippedScenes, GlbWithPunctualLamp) {
  const Scene scene = load_scene(test::asset("cornell_sphere.glb"));
  EXPECT_EQ(scene.instances().size(), 8u);
  ASSERT_EQ(scene.lights.size(), 1u);
  const PunctualLight& lamp = scene.lights[0];
  EXPECT_EQ(lamp.name, "lamp");
  EXPECT_EQ(lamp.type, LightType::Point);
  EXPECT_FLOAT_EQ(lamp.intensity, 0.5f);
  EXPECT_EQ(lamp.color, glm::vec3(1.0f));
  const int node = node_named(scene, "lamp");
  ASSERT_GE(node, 0);
  EXPECT_EQ(scene.nodes[size_t(node)].light, 0);
  expect_near(glm::vec3(scene.world_transform(uint32_t(node))[3]), {0.278f, 0.45f, 0.28f}, 1e-6f,
              "lamp position");
  EXPECT_NE(node_named(scene, "sphere"), -1);
}

TEST(ShippedScenes, FurnaceSphereFromDataUri) {
  const Scene scene = load_scene(test::asset("furnace_sphere.gltf"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.meshes[0].primitives.size(), 1u);
  const MeshPrimitive& sphere = scene.meshes[0].primitives[0];
  EXPECT_EQ(sphere.indices.size() / 3, 3968u);
  for (size_t i = 0; i < sphere.positions.size(); ++i) {
    ASSERT_NEAR(glm::length(sphere.positions[i]), 1.0f, 1e-4f) << "vertex " << i;
    ASSERT_GT(glm::dot(sphere.normals[i], sphere.positions[i]), 0.99f) << "normal " << i;
  }
  EXPECT_EQ(scene.materials[0].params.specular_weight, 0.0f);
  EXPECT_EQ(scene.materials[0].params.base_color, glm::vec3(1.0f));
}

TEST(ShippedScenes, ContentHashIsStable) {
  EXPECT_EQ(load_scene(test::asset("cornell_sphere.glb")).content_hash,
            load_scene(test::asset("cornell_sphere.glb")).content_hash);
}

// ---- Scenes written by the tests ----------------------------------------------------------

// Adds an image with `uri`, a texture on it and uses it as the material's base colour.
void add_base_color_image(Document& doc, const std::string& uri) {
  doc.gltf["images"] = json::array({{{"uri", uri}}});
  doc.gltf["textures"] = json::array({{{"source", 0}}});
  doc.gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
}

// Writes `doc` with an embedded buffer and expects load_scene to refuse it with one line that
// names the file and contains `mentions`.
void expect_refused(const Document& doc, const std::string& mentions) {
  const fs::path file = test::temp_dir("refused") / "broken.gltf";
  write_document(file, doc);
  try {
    load_scene(file);
    ADD_FAILURE() << "loaded; expected an InputError mentioning '" << mentions << "'";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(mentions), std::string::npos) << message;
    EXPECT_NE(message.find("broken.gltf"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(WrittenScenes, EmbeddedTriangleLoads) {
  const fs::path file = test::temp_dir("triangle") / "tri.gltf";
  write_document(file, triangle_document());
  const Scene scene = load_scene(file);
  ASSERT_EQ(scene.instances().size(), 1u);
  const MeshPrimitive& p = scene.meshes[0].primitives[0];
  EXPECT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(p.positions[1], glm::vec3(1, 0, 0));
  EXPECT_EQ(p.normals[2], glm::vec3(0, 0, 1));
  EXPECT_EQ(scene.materials[p.material].name, "mat");
}

TEST(WrittenScenes, MissingNormalsGiveFlatNormals) {
  Document doc = triangle_document();
  doc.primitive()["attributes"].erase("NORMAL");
  const fs::path file = test::temp_dir("flat") / "flat.gltf";
  write_document(file, doc);
  const Scene scene = load_scene(file);
  const MeshPrimitive& p = scene.meshes[0].primitives[0];
  ASSERT_EQ(p.normals.size(), 3u);
  for (const glm::vec3& n : p.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(WrittenScenes, TriangleStripLoads) {
  Document doc = triangle_document();
  // A unit quad as a strip: (0,1,2) and (2,1,3), both facing +Z.
  const int position =
      doc.add_accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, kFloat, "VEC3", 4);
  doc.primitive() = {{"attributes", {{"POSITION", position}}}, {"mode", kTriangleStrip}};
  const fs::path file = test::temp_dir("strip") / "strip.gltf";
  write_document(file, doc);
  const Scene scene = load_scene(file);
  const MeshPrimitive& p = scene.meshes[0].primitives[0];
  ASSERT_EQ(p.indices.size(), 6u);
  for (const glm::vec3& n : p.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

TEST(WrittenScenes, PrimitiveWithoutMaterialGetsTheDefault) {
  Document doc = triangle_document();
  doc.primitive().erase("material");
  const fs::path file = test::temp_dir("default-material") / "tri.gltf";
  write_document(file, doc);
  const Scene scene = load_scene(file);
  EXPECT_EQ(scene.materials[scene.meshes[0].primitives[0].material].name, "default");
}

TEST(WrittenScenes, ExternalBufferBytesFeedTheContentHash) {
  const fs::path dir = test::temp_dir("hash");
  Document doc = triangle_document();
  write_document(dir / "tri.gltf", doc, "tri.bin");
  write_bytes(dir / "tri.bin", doc.bin);
  const std::string first = load_scene(dir / "tri.gltf").content_hash;
  doc.bin[4] ^= 1;  // the first vertex's y: a change only the buffer shows
  write_bytes(dir / "tri.bin", doc.bin);
  EXPECT_NE(load_scene(dir / "tri.gltf").content_hash, first);
}

TEST(WrittenScenes, UnsupportedRequiredExtensionIsRefused) {
  Document doc = triangle_document();
  doc.gltf["extensionsUsed"] = {"EXT_hipr_made_up"};
  doc.gltf["extensionsRequired"] = {"EXT_hipr_made_up"};
  expect_refused(doc, "requires unsupported glTF extension EXT_hipr_made_up");
}

TEST(WrittenScenes, SupportedRequiredExtensionLoads) {
  Document doc = triangle_document();
  doc.gltf["extensionsUsed"] = {"KHR_materials_specular"};
  doc.gltf["extensionsRequired"] = {"KHR_materials_specular"};
  const fs::path file = test::temp_dir("required-ok") / "tri.gltf";
  write_document(file, doc);
  EXPECT_NO_THROW(load_scene(file));
}

TEST(WrittenScenes, NodeCycleIsRefused) {
  Document doc = triangle_document();
  doc.gltf["nodes"] = json::array(
      {{{"name", "a"}, {"mesh", 0}, {"children", {1}}}, {{"name", "b"}, {"children", {0}}}});
  expect_refused(doc, "cycle");
}

TEST(WrittenScenes, NodeWithTwoParentsIsRefused) {
  Document doc = triangle_document();
  doc.gltf["nodes"] = json::array({{{"mesh", 0}}, {{"children", {0}}}, {{"children", {0}}}});
  doc.gltf["scenes"][0]["nodes"] = {1, 2};
  expect_refused(doc, "more than one parent");
}

TEST(WrittenScenes, DuplicateSceneRootIsRefused) {
  // Listed twice, the node would be drawn twice in the same place (glTF requires unique roots).
  Document doc = triangle_document();
  doc.gltf["scenes"][0]["nodes"] = {0, 0};
  expect_refused(doc, "node 0");
}

TEST(WrittenScenes, NonFiniteMatrixIsRefused) {
  // 1e39 is a finite double but overflows float.
  Document doc = triangle_document();
  doc.gltf["nodes"][0]["matrix"] = {1e39, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  expect_refused(doc, "non-finite transform");
  doc = triangle_document();
  doc.gltf["nodes"][0]["translation"] = {0, -1e39, 0};
  expect_refused(doc, "non-finite transform");
}

TEST(WrittenScenes, NonFiniteVertexIsRefused) {
  Document doc = triangle_document();
  const float inf = std::numeric_limits<float>::infinity();
  std::memcpy(doc.bin.data() + 4, &inf, sizeof inf);
  expect_refused(doc, "non-finite value");
}

TEST(WrittenScenes, AccessorOutOfBoundsIsRefused) {
  Document doc = triangle_document();
  doc.gltf["accessors"][0]["count"] = 100;
  expect_refused(doc, "runs past the end");
  doc = triangle_document();
  doc.gltf["accessors"][0]["byteOffset"] = 4;
  expect_refused(doc, "runs past the end");
}

TEST(WrittenScenes, HugeAccessorOffsetIsRefused) {
  // 2^64 - 12: offset + stride * (count - 1) + element size wraps around to 24 bytes.
  Document doc = triangle_document();
  doc.gltf["accessors"][0]["byteOffset"] = std::numeric_limits<uint64_t>::max() - 11;
  expect_refused(doc, "runs past the end");
}

TEST(WrittenScenes, UnusedBrokenAccessorIsRefused) {
  // Broken data is refused even where no mesh reads it: the file is invalid either way.
  Document doc = triangle_document();
  doc.gltf["accessors"].push_back(
      {{"bufferView", 0}, {"componentType", kFloat}, {"type", "VEC3"}, {"count", 50}});
  expect_refused(doc, "runs past the end");
  doc = triangle_document();
  doc.gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 40}, {"byteLength", 400}});
  expect_refused(doc, "runs past the end of its buffer");
}

TEST(WrittenScenes, AnImageViewPastItsBufferIsRefusedBeforeItIsDecoded) {
  // tinygltf hands an image's bufferView to the decoder as long as the view claims: the view must
  // be checked against its buffer first (a fuzzed GLB had OpenImageIO's DDS path read past it).
  for (const char* magic : {"\x89PNG\r\n\x1a\n", "DDS "}) {
    Document doc = triangle_document();
    const size_t offset = doc.bin.size();
    doc.bin.insert(doc.bin.end(), magic, magic + std::strlen(magic));
    doc.bin.resize((doc.bin.size() + 3) / 4 * 4, 0);
    doc.gltf["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", doc.bin.size() - offset + 400}});
    const size_t view = doc.gltf["bufferViews"].size() - 1;
    doc.gltf["images"] = json::array({{{"bufferView", view}, {"mimeType", "image/png"}}});
    expect_refused(
        doc, "image 0's bufferView " + std::to_string(view) + " runs past the end of its buffer");
    doc.gltf["images"][0]["bufferView"] = view + 1;
    expect_refused(doc, "image 0 names a bufferView that does not exist");
    doc.gltf["images"][0]["bufferView"] = view;
    doc.gltf["bufferViews"][view]["byteOffset"] = -4;
    expect_refused(doc, "has no valid byteOffset or byteLength");
  }
  // A meshopt fallback buffer: tinygltf reads a 4-byte placeholder in its place.
  Document doc = triangle_document();
  doc.gltf["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", 512}});
  doc.gltf["images"] = json::array({{{"bufferView", doc.gltf["bufferViews"].size() - 1}}});
  doc.gltf["extensionsUsed"] = {"EXT_meshopt_compression"};
  doc.gltf["buffers"] =
      json::array({{{"byteLength", doc.bin.size()},
                    {"uri", "data:application/octet-stream;base64," + base64_encode(doc.bin)}},
                   {{"byteLength", 1024},
                    {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}});
  const fs::path file = test::temp_dir("refused") / "fallback_image.gltf";
  std::ofstream(file) << doc.gltf.dump();
  try {
    load_scene(file);
    ADD_FAILURE() << "an image in a meshopt fallback buffer was handed to its decoder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lies in a meshopt fallback buffer"), std::string::npos)
        << e.what();
  }
}

TEST(WrittenScenes, NodeThatIsItsOwnChildIsRefused) {
  Document doc = triangle_document();
  doc.gltf["nodes"][0]["children"] = {0};
  expect_refused(doc, "cycle");
}

TEST(WrittenScenes, IndexOutOfRangeIsRefused) {
  Document doc = triangle_document();
  doc.primitive()["indices"] =
      doc.add_accessor(std::vector<uint16_t>{0, 1, 7}, kUnsignedShort, "SCALAR", 3);
  expect_refused(doc, "index 7");
}

TEST(WrittenScenes, MaterialIndexOutOfRangeIsRefused) {
  Document doc = triangle_document();
  doc.primitive()["material"] = 3;
  expect_refused(doc, "missing material 3");
}

TEST(WrittenScenes, TextureIndexOutOfRangeIsRefused) {
  Document doc = triangle_document();
  doc.gltf["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 4}};
  expect_refused(doc, "missing texture 4");
}

// ---- Textures and file confinement --------------------------------------------------------

// A 2x2 green PNG, a real image for the loader to decode.
void write_png(const fs::path& path) {
  fs::create_directories(path.parent_path());
  ImageRGB image{2, 2, std::vector<float>(12, 0.0f)};
  for (size_t i = 1; i < image.rgb.size(); i += 3) image.rgb[i] = 1.0f;
  write_image(path, image);
}

std::array<uint8_t, 4> texel(const Image& t, uint32_t x, uint32_t y) {
  const size_t at = (size_t(y) * t.width + x) * 4;
  return {t.rgba8[at], t.rgba8[at + 1], t.rgba8[at + 2], t.rgba8[at + 3]};
}

// The loader's stand-in for an image it cannot read: 8x8, magenta and black 2x2 checks.
bool is_fallback_checker(const Image& t) {
  if (t.width != 8 || t.height != 8 || t.rgba8.size() != 8 * 8 * 4) return false;
  const std::array<uint8_t, 4> magenta = {255, 0, 255, 255}, black = {0, 0, 0, 255};
  return texel(t, 0, 0) == magenta && texel(t, 1, 1) == magenta && texel(t, 2, 0) == black &&
         texel(t, 0, 2) == black && texel(t, 2, 2) == magenta;
}

struct LoadedTexture {
  Texture texture;
  Image image;
  std::string warnings;  // what the loader printed on stderr
};

// Loads a scene whose material's base colour texture reads `uri`.
LoadedTexture load_texture(const fs::path& file, const std::string& uri) {
  Document doc = triangle_document();
  add_base_color_image(doc, uri);
  write_document(file, doc);
  testing::internal::CaptureStderr();
  Scene scene;
  try {
    scene = load_scene(file);
  } catch (...) {
    testing::internal::GetCapturedStderr();  // stop capturing before the error reaches gtest
    throw;
  }
  LoadedTexture loaded;
  loaded.warnings = testing::internal::GetCapturedStderr();
  EXPECT_EQ(scene.materials[0].params.base_color_texture, 0u);
  if (scene.textures.size() != 1 || scene.images.size() != 1)
    throw std::runtime_error("expected exactly one texture");
  loaded.texture = scene.textures[0];
  loaded.image = scene.images[loaded.texture.image];
  return loaded;
}

TEST(Textures, ImageInsideTheFolderIsDecoded) {
  const fs::path dir = test::temp_dir("texture-ok");
  write_png(dir / "maps" / "green.png");
  const LoadedTexture loaded = load_texture(dir / "scene.gltf", "maps/green.png");
  ASSERT_EQ(loaded.image.width, 2u);
  ASSERT_EQ(loaded.image.height, 2u);
  EXPECT_EQ(texel(loaded.image, 1, 1), (std::array<uint8_t, 4>{0, 255, 0, 255}));
  EXPECT_TRUE(loaded.texture.flags & abi::kTextureSrgb);  // base colour is sRGB-encoded
  EXPECT_EQ(loaded.warnings, "");
}

TEST(Textures, MissingImageFallsBackToAMagentaChecker) {
  const LoadedTexture loaded =
      load_texture(test::temp_dir("texture-missing") / "scene.gltf", "missing.png");
  EXPECT_TRUE(is_fallback_checker(loaded.image));
  EXPECT_NE(loaded.warnings.find("hipr: warning:"), std::string::npos) << loaded.warnings;
  EXPECT_NE(loaded.warnings.find("missing.png"), std::string::npos) << loaded.warnings;
}

TEST(Textures, UndecodableImageFallsBackToAMagentaChecker) {
  const fs::path dir = test::temp_dir("texture-garbage");
  write_bytes(dir / "garbage.png", {'n', 'o', 't', ' ', 'a', ' ', 'p', 'n', 'g'});
  const LoadedTexture loaded = load_texture(dir / "scene.gltf", "garbage.png");
  EXPECT_TRUE(is_fallback_checker(loaded.image));
  EXPECT_NE(loaded.warnings.find("hipr: warning:"), std::string::npos) << loaded.warnings;
}

TEST(Textures, SymlinkedImageOutsideTheFolderIsNeverRead) {
  const fs::path root = test::temp_dir("texture-symlink");
  write_png(root / "outside.png");
  fs::create_directories(root / "scene");
  fs::create_symlink(root / "outside.png", root / "scene" / "link.png");
  try {
    EXPECT_TRUE(is_fallback_checker(load_texture(root / "scene" / "scene.gltf", "link.png").image))
        << "the image outside the scene folder was decoded";
  } catch (const InputError&) {
    // Refusing the scene outright is fine too.
  }
}

// URIs that point outside the scene folder; "@" stands for the test's folder, for absolute
// URIs to a file that really exists.
const char* const kOutsideUris[] = {
    "../outside.bin", "sub/../../outside.bin", "%2e%2e/outside.bin", "/etc/passwd",
    "@/outside.bin",  "file:///etc/passwd",    "file:@/outside.bin"};

enum class UriUse { Buffer, Image };

// Writes a scene per outside URI, used for its buffer or for an image, and expects each to be
// refused. The outside file holds a valid buffer, so a loader that read it would load the scene.
void expect_outside_uris_refused(UriUse use) {
  const fs::path root = test::temp_dir("confine");
  const fs::path scene = root / "scene" / "scene.gltf";
  write_bytes(root / "outside.bin", triangle_document().bin);
  for (std::string uri : kOutsideUris) {
    if (const size_t at = uri.find('@'); at != std::string::npos) uri.replace(at, 1, root.string());
    SCOPED_TRACE("URI '" + uri + "'");
    Document doc = triangle_document();
    if (use == UriUse::Image) add_base_color_image(doc, uri);
    write_document(scene, doc, use == UriUse::Buffer ? uri : "");
    try {
      load_scene(scene);
      ADD_FAILURE() << "loaded the scene";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("only files inside the scene folder are read"), std::string::npos)
          << message;
      EXPECT_NE(message.find("scene.gltf"), std::string::npos) << message;
    }
  }
}

TEST(Confinement, OutsideBufferUriIsRefused) { expect_outside_uris_refused(UriUse::Buffer); }
TEST(Confinement, OutsideImageUriIsRefused) { expect_outside_uris_refused(UriUse::Image); }

TEST(ConfinementSymlinks, FileLinkOutsideIsNeverRead) {
  const fs::path root = test::temp_dir("confine-link");
  const Document doc = triangle_document();
  write_bytes(root / "outside.bin", doc.bin);
  write_document(root / "scene" / "scene.gltf", doc, "link.bin");
  fs::create_symlink(root / "outside.bin", root / "scene" / "link.bin");
  EXPECT_THROW(load_scene(root / "scene" / "scene.gltf"), InputError);
}

TEST(ConfinementSymlinks, FolderLinkOutsideIsNeverRead) {
  const fs::path root = test::temp_dir("confine-dirlink");
  const Document doc = triangle_document();
  write_bytes(root / "elsewhere" / "data.bin", doc.bin);
  write_document(root / "scene" / "scene.gltf", doc, "linked/data.bin");
  fs::create_directory_symlink(root / "elsewhere", root / "scene" / "linked");
  EXPECT_THROW(load_scene(root / "scene" / "scene.gltf"), InputError);
}

TEST(ConfinementSymlinks, LinkInsideTheFolderIsFollowed) {
  const fs::path dir = test::temp_dir("confine-inner-link");
  const Document doc = triangle_document();
  write_bytes(dir / "real.bin", doc.bin);
  write_document(dir / "scene.gltf", doc, "link.bin");
  fs::create_symlink("real.bin", dir / "link.bin");
  EXPECT_EQ(load_scene(dir / "scene.gltf").meshes[0].primitives[0].positions[1],
            glm::vec3(1, 0, 0));
}

TEST(ConfinementSymlinks, SubfolderBufferLoads) {
  const fs::path dir = test::temp_dir("confine-sub");
  const Document doc = triangle_document();
  write_bytes(dir / "sub" / "data.bin", doc.bin);
  write_document(dir / "scene.gltf", doc, "sub/data.bin");
  EXPECT_EQ(load_scene(dir / "scene.gltf").meshes[0].primitives[0].positions[1],
            glm::vec3(1, 0, 0));
}

// ---- Real-world scenes (../shared/scenes, when present) -----------------------------------

// Every .gltf/.glb under ../shared/scenes except the deliberately broken ones; a single empty
// entry when the folder is absent, so the suite reports one skip instead of nothing.
std::vector<std::string> shared_scene_files() {
  std::vector<std::string> files;
  if (test::shared_scenes_available()) {
    const fs::path root = test::shared_scene("");
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      const std::string relative = fs::relative(entry.path(), root).generic_string();
      const std::string extension = entry.path().extension().string();
      if (relative.rfind("InvalidInputs/", 0) != 0 && (extension == ".gltf" || extension == ".glb"))
        files.push_back(relative);
    }
    std::sort(files.begin(), files.end());
  }
  if (files.empty()) files.push_back("");
  return files;
}

std::string test_name_for(const std::string& file) {
  if (file.empty()) return "shared_scenes_absent";
  std::string name = fs::path(file).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

class SharedScene : public testing::TestWithParam<std::string> {};

TEST_P(SharedScene, Loads) {
  if (GetParam().empty()) GTEST_SKIP() << "../shared/scenes is not available";
  const fs::path file = test::shared_scene(GetParam());
  const Scene scene = load_scene(file);
  EXPECT_FALSE(scene.instances().empty());
  EXPECT_EQ(scene.content_hash.size(), 16u);
  for (const Image& t : scene.images)
    EXPECT_EQ(t.rgba8.size(), size_t(t.width) * t.height * 4) << t.name;
  for (const Texture& t : scene.textures) EXPECT_LT(t.image, scene.images.size()) << t.name;
}

std::string shared_scene_name(const testing::TestParamInfo<std::string>& param_info) {
  return test_name_for(param_info.param);
}

INSTANTIATE_TEST_SUITE_P(Files, SharedScene, testing::ValuesIn(shared_scene_files()),
                         shared_scene_name);

}  // namespace
}  // namespace hipr
