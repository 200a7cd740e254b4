// Compressed and quantized glTF: EXT_meshopt_compression streams made here with
// libmeshoptimizer's encoders (every mode and mesh filter, and broken ones), and copies of the
// shipped scenes made by glTF-Transform (tools/node_modules; the tests using it skip without it
// unless HIPR_REQUIRE_GLTF_VALIDATOR=1 says the set-up installed it): Draco, meshopt,
// quantization and WebP load as the same geometry and texels as their originals.
#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <webp/decode.h>
#include <webp/encode.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "gltf_document.h"
#include "gltf_transform_support.h"
#include "hipr/scene_loader.h"
#include "image/image_io.h"
#include "scene/base64.h"
#include "scene/dds_header.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;

// ---- meshopt streams encoded here ----

// A fan of `n` triangles around the origin (positions far from 1 so the exponent filter works),
// with unit normals tilted per vertex.
struct Fan {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<uint32_t> indices;
};

Fan make_fan(int n) {
  Fan fan;
  fan.positions.push_back({0, 0, 0});
  fan.normals.push_back({0, 0, 1});
  for (int i = 0; i <= n; ++i) {
    const float a = 6.2831853f * float(i) / float(n);
    fan.positions.push_back({3.5f * std::cos(a), 3.5f * std::sin(a), 0.25f * float(i % 3)});
    fan.normals.push_back(glm::normalize(glm::vec3(0.2f * std::cos(a), 0.2f * std::sin(a), 1)));
  }
  for (int i = 0; i < n; ++i)
    fan.indices.insert(fan.indices.end(), {0u, uint32_t(i + 1), uint32_t(i + 2)});
  return fan;
}

// A document whose three bufferViews (float positions under the EXPONENTIAL filter, 8-bit
// normals under OCTAHEDRAL, 16-bit TRIANGLES indices) decode from buffer 0 into fallback buffer
// 1, which has a length and no data, as glTF-Transform writes them.
json meshopt_fan_document(const Fan& fan, std::vector<unsigned char>& compressed) {
  const size_t vertices = fan.positions.size();
  std::vector<float> position_floats;
  for (const glm::vec3& p : fan.positions)
    position_floats.insert(position_floats.end(), {p.x, p.y, p.z});
  std::vector<uint32_t> exp_positions(vertices * 3);
  meshopt_encodeFilterExp(exp_positions.data(), vertices, 12, 15, position_floats.data());
  std::vector<float> normal_floats;
  for (const glm::vec3& n : fan.normals)
    normal_floats.insert(normal_floats.end(), {n.x, n.y, n.z, 0});
  std::vector<int8_t> oct_normals(vertices * 4);
  meshopt_encodeFilterOct(oct_normals.data(), vertices, 4, 8, normal_floats.data());
  std::vector<uint16_t> indices16(fan.indices.begin(), fan.indices.end());

  json views = json::array();
  size_t fallback_size = 0;
  const auto add_view = [&](const std::vector<unsigned char>& stream, size_t stride, size_t count,
                            const char* mode, const char* filter) {
    const size_t offset = compressed.size();
    compressed.insert(compressed.end(), stream.begin(), stream.end());
    compressed.resize((compressed.size() + 3) / 4 * 4, 0);
    json ext = {{"buffer", 0},          {"byteOffset", offset}, {"byteLength", stream.size()},
                {"byteStride", stride}, {"count", count},       {"mode", mode}};
    if (std::string(filter) != "NONE") ext["filter"] = filter;
    json view = {{"buffer", 1},
                 {"byteOffset", fallback_size},
                 {"byteLength", stride * count},
                 {"extensions", {{"EXT_meshopt_compression", ext}}}};
    if (std::string(mode) == "ATTRIBUTES") view["byteStride"] = stride;
    views.push_back(view);
    fallback_size += (stride * count + 3) / 4 * 4;
  };
  const auto vertex_stream = [](const void* data, size_t count, size_t stride) {
    std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, count, stride));
    return out;
  };
  add_view(vertex_stream(exp_positions.data(), vertices, 12), 12, vertices, "ATTRIBUTES",
           "EXPONENTIAL");
  add_view(vertex_stream(oct_normals.data(), vertices, 4), 4, vertices, "ATTRIBUTES", "OCTAHEDRAL");
  std::vector<unsigned char> index_stream(
      meshopt_encodeIndexBufferBound(fan.indices.size(), vertices));
  index_stream.resize(meshopt_encodeIndexBuffer(index_stream.data(), index_stream.size(),
                                                fan.indices.data(), fan.indices.size()));
  add_view(index_stream, 2, fan.indices.size(), "TRIANGLES", "NONE");

  json doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"EXT_meshopt_compression"}},
      {"extensionsRequired", {"EXT_meshopt_compression"}},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", {0}}}})},
      {"nodes", json::array({{{"name", "fan"}, {"mesh", 0}}})},
      {"materials", json::array({{{"name", "mat"}}})},
      {"buffers",
       json::array({{{"byteLength", compressed.size()},
                     {"uri", "data:application/octet-stream;base64," + base64_encode(compressed)}},
                    {{"byteLength", fallback_size},
                     {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}})},
      {"bufferViews", views},
      {"accessors", json::array({{{"bufferView", 0},
                                  {"componentType", test::kFloat},
                                  {"type", "VEC3"},
                                  {"count", vertices}},
                                 {{"bufferView", 1},
                                  {"componentType", 5120},
                                  {"normalized", true},
                                  {"type", "VEC3"},
                                  {"count", vertices}},
                                 {{"bufferView", 2},
                                  {"componentType", test::kUnsignedShort},
                                  {"type", "SCALAR"},
                                  {"count", fan.indices.size()}}})},
      {"meshes",
       json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}},
                                                  {"indices", 2},
                                                  {"material", 0}}})}}})}};
  return doc;
}

fs::path write_json(const fs::path& dir, const std::string& name, const json& doc) {
  const fs::path path = dir / name;
  std::ofstream(path) << doc.dump();
  return path;
}

TEST(Meshopt, EveryModeAndMeshFilterDecodesToTheEncodedMesh) {
  const fs::path dir = test::temp_dir("meshopt");
  const Fan fan = make_fan(24);
  std::vector<unsigned char> compressed;
  const Scene scene =
      load_scene(write_json(dir, "fan.gltf", meshopt_fan_document(fan, compressed)));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const MeshPrimitive& p = scene.meshes[0].primitives.at(0);
  ASSERT_EQ(p.positions.size(), fan.positions.size());
  EXPECT_EQ(p.indices, fan.indices);
  for (size_t i = 0; i < fan.positions.size(); ++i) {
    // 15 bits of mantissa shared per vector: within 2^-14 of the largest component.
    EXPECT_NEAR(glm::length(p.positions[i] - fan.positions[i]), 0.0f, 3.5f / 8192.0f) << i;
    // 8-bit octahedral normals: a degree or two.
    EXPECT_GT(glm::dot(p.normals[i], fan.normals[i]), 0.999f) << i;
  }
}

// Each broken stream is one line naming the bufferView, never a crash or a silent mesh.
TEST(Meshopt, MalformedStreamsAreOneLineErrors) {
  const fs::path dir = test::temp_dir("meshopt_bad");
  const Fan fan = make_fan(24);
  std::vector<unsigned char> compressed;
  const json good = meshopt_fan_document(fan, compressed);
  struct Case {
    const char* name;
    std::function<void(json&)> spoil;
    const char* message;
  };
  const auto ext = [](json& doc, int view) -> json& {
    return doc["bufferViews"][view]["extensions"]["EXT_meshopt_compression"];
  };
  const std::vector<Case> cases = {
      {"unknown filter", [&](json& d) { ext(d, 0)["filter"] = "SPHERICAL"; }, "filter"},
      {"quaternion filter on 12-byte elements",
       [&](json& d) { ext(d, 0)["filter"] = "QUATERNION"; }, "QUATERNION"},
      {"octahedral filter on 12-byte elements",
       [&](json& d) { ext(d, 0)["filter"] = "OCTAHEDRAL"; }, "OCTAHEDRAL"},
      {"filter on indices", [&](json& d) { ext(d, 2)["filter"] = "EXPONENTIAL"; }, "filter"},
      {"unknown mode", [&](json& d) { ext(d, 1)["mode"] = "POINTS"; }, "mode"},
      {"truncated stream", [&](json& d) { ext(d, 0)["byteLength"] = 9; }, "does not decode"},
      {"stream past its buffer", [&](json& d) { ext(d, 1)["byteOffset"] = 1u << 20; }, "past"},
      {"stride not a multiple of 4", [&](json& d) { ext(d, 0)["byteStride"] = 6; }, "stride"},
      {"index stride 3", [&](json& d) { ext(d, 2)["byteStride"] = 3; }, "stride"},
      {"triangle count not a multiple of 3", [&](json& d) { ext(d, 2)["count"] = 7; },
       "multiple of 3"},
      {"more elements than the view holds", [&](json& d) { ext(d, 0)["count"] = 1000; },
       "more than"},
      {"missing buffer", [&](json& d) { ext(d, 0)["buffer"] = 7; }, "missing buffer"},
      {"negative count", [&](json& d) { ext(d, 0)["count"] = -1; }, "count"},
      {"fallback of a terabyte", [&](json& d) { d["buffers"][1]["byteLength"] = size_t(1) << 40; },
       "limit"},
  };
  for (const Case& c : cases) {
    json doc = good;
    c.spoil(doc);
    const fs::path path = write_json(dir, "bad.gltf", doc);
    try {
      load_scene(path);
      ADD_FAILURE() << c.name << ": loaded";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(c.message), std::string::npos) << c.name << ": " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << c.name << ": " << message;
    }
  }
}

// ---- texture sources of other formats (built here: no tool needed) ----

// An uncompressed 32-bit BGRA DDS file of `w` x `h` texels, texel (x, y) = (x * 60, y * 60, 200).
std::vector<unsigned char> dds_image(uint32_t w, uint32_t h) {
  std::vector<uint32_t> header(32, 0);  // "DDS " then the 124-byte DDS_HEADER
  std::memcpy(header.data(), "DDS ", 4);
  header[1] = 124;                       // dwSize
  header[2] = 0x1 | 0x2 | 0x4 | 0x1000;  // CAPS, HEIGHT, WIDTH, PIXELFORMAT
  header[3] = h;
  header[4] = w;
  header[5] = w * 4;        // pitch
  header[19] = 32;          // DDS_PIXELFORMAT.dwSize
  header[20] = 0x40 | 0x1;  // RGB, ALPHAPIXELS
  header[22] = 32;          // bits per texel
  header[23] = 0x00ff0000;  // R mask
  header[24] = 0x0000ff00;  // G
  header[25] = 0x000000ff;  // B
  header[26] = 0xff000000;  // A
  header[27] = 0x1000;      // DDSCAPS_TEXTURE
  std::vector<unsigned char> bytes(128);
  std::memcpy(bytes.data(), header.data(), 128);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      bytes.insert(bytes.end(), {200, uint8_t(y * 60), uint8_t(x * 60), 255});  // B G R A
  return bytes;
}

// A triangle whose texture has a PNG `source` (grey) and the extension's other source.
test::Document textured_triangle(const fs::path& dir, const json& texture) {
  write_image(dir / "grey.png", ImageRGB{1, 1, {0.5f, 0.5f, 0.5f}});
  test::Document doc = test::triangle_document();
  const int uv = doc.add_accessor(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2", 3);
  doc.primitive()["attributes"]["TEXCOORD_0"] = uv;
  doc.gltf["images"] = json::array({{{"uri", "grey.png"}}, {{"uri", "texels.dds"}}});
  doc.gltf["textures"] = json::array({texture});
  doc.gltf["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  return doc;
}

TEST(TextureSources, DdsIsPreferredToTheFallback) {
  const fs::path dir = test::temp_dir("dds");
  test::write_bytes(dir / "texels.dds", dds_image(4, 3));
  test::Document doc = textured_triangle(
      dir, {{"source", 0}, {"extensions", {{"MSFT_texture_dds", {{"source", 1}}}}}});
  doc.gltf["extensionsUsed"] = {"MSFT_texture_dds"};
  test::write_document(dir / "dds.gltf", doc);
  const Scene scene = load_scene(dir / "dds.gltf");
  ASSERT_EQ(scene.images.size(), 1u);
  const Image& image = scene.images[0];
  ASSERT_EQ(image.width, 4u);
  ASSERT_EQ(image.height, 3u);
  const uint8_t* texel = &image.rgba8[(2 * 4 + 3) * 4];  // (3, 2)
  EXPECT_EQ(texel[0], 180);
  EXPECT_EQ(texel[1], 120);
  EXPECT_EQ(texel[2], 200);
}

// glTF colours are not premultiplied by alpha. OpenImageIO's WebP reader, which hipr used before
// libwebp, handed texels premultiplied (a half-transparent texel at half its colour).
TEST(TextureSources, AWebpKeepsTheColourOfItsTranslucentTexels) {
  const fs::path dir = test::temp_dir("webp_alpha");
  std::vector<uint8_t> rgba;
  // (Alpha from 15 up: the encoder may drop the colour of a wholly transparent texel.)
  for (int i = 0; i < 16; ++i)
    rgba.insert(rgba.end(), {200, uint8_t(16 * i), 40, uint8_t(15 + 15 * i)});
  uint8_t* encoded = nullptr;
  const size_t size = WebPEncodeLosslessRGBA(rgba.data(), 4, 4, 16, &encoded);
  ASSERT_GT(size, 0u);
  test::write_bytes(dir / "texels.webp", std::vector<unsigned char>(encoded, encoded + size));
  WebPFree(encoded);
  test::Document doc = test::triangle_document();
  const int uv = doc.add_accessor(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2", 3);
  doc.primitive()["attributes"]["TEXCOORD_0"] = uv;
  doc.gltf["images"] = json::array({{{"uri", "texels.webp"}}});
  doc.gltf["textures"] = json::array({{{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}}});
  doc.gltf["extensionsUsed"] = {"EXT_texture_webp"};
  doc.gltf["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  test::write_document(dir / "webp.gltf", doc);
  const Scene scene = load_scene(dir / "webp.gltf");
  ASSERT_EQ(scene.images.size(), 1u);
  ASSERT_EQ(scene.images[0].width, 4u);
  EXPECT_EQ(scene.images[0].rgba8, rgba) << "lossless: every texel as written, colour unscaled";
}

TEST(TextureSources, ADdsTheReaderWouldTripOnIsRefusedAndItsFallbackShown) {
  // DXT2 (premultiplied BC2): OpenImageIO 2.4's DDS reader divided by zero on it (found by
  // fuzzing). hipr refuses it from its header and shows the texture's PNG fallback.
  const fs::path dir = test::temp_dir("dds_dxt2");
  std::vector<unsigned char> dds = dds_image(4, 4);
  const uint32_t four_cc = 0x4, dxt2 = 0x32545844;  // DDPF_FOURCC, "DXT2"
  std::memcpy(dds.data() + 80, &four_cc, 4);
  std::memcpy(dds.data() + 84, &dxt2, 4);
  test::write_bytes(dir / "texels.dds", dds);
  test::Document doc = textured_triangle(
      dir, {{"source", 0}, {"extensions", {{"MSFT_texture_dds", {{"source", 1}}}}}});
  doc.gltf["extensionsUsed"] = {"MSFT_texture_dds"};
  test::write_document(dir / "dxt2.gltf", doc);
  const Scene scene = load_scene(dir / "dxt2.gltf");
  ASSERT_EQ(scene.images.size(), 1u);
  ASSERT_EQ(scene.images[0].width, 1u);           // the grey PNG, not the magenta checker
  EXPECT_NEAR(scene.images[0].rgba8[0], 188, 1);  // 0.5 linear, sRGB-encoded
  // Without a fallback: the checker, and a warning, never a crash.
  doc.gltf["textures"][0].erase("source");
  test::write_document(dir / "dxt2_alone.gltf", doc);
  const Scene alone = load_scene(dir / "dxt2_alone.gltf");
  ASSERT_EQ(alone.images.size(), 1u);
  EXPECT_GT(alone.images[0].width, 1u);
}

TEST(DdsHeader, OnlyTheKindsTheReaderDecodesPass) {
  const auto problem = [](std::vector<unsigned char> dds) {
    gltf::DdsLayout layout;
    return gltf::read_dds_header(dds.data(), dds.size(), &layout);
  };
  const auto with = [](std::vector<unsigned char> dds, size_t at, uint32_t value) {
    std::memcpy(dds.data() + at, &value, 4);
    return dds;
  };
  const std::vector<unsigned char> good = dds_image(4, 3);
  EXPECT_EQ(problem(good), "");
  EXPECT_NE(problem(with(good, 88, 0)).find("0 bits"), std::string::npos);  // hung the reader
  EXPECT_NE(problem(with(good, 88, 12)).find("12 bits"), std::string::npos);
  EXPECT_NE(problem(with(with(good, 88, 16), 92, 0x00ff0000)).find("masks"), std::string::npos);
  EXPECT_NE(problem(with(good, 112, 0x200)).find("cube map"), std::string::npos);
  EXPECT_NE(problem(with(good, 12, 0)).find("without texels"), std::string::npos);
  EXPECT_NE(problem(with(good, 4, 100)).find("malformed"), std::string::npos);
  EXPECT_NE(problem(std::vector<unsigned char>(good.begin(), good.end() - 1)).find("run past"),
            std::string::npos);
  EXPECT_NE(problem(std::vector<unsigned char>(good.begin(), good.begin() + 64)).find("too short"),
            std::string::npos);
  // Mip levels beyond a 4 x 3 image's three.
  const std::vector<unsigned char> mipped = with(good, 8, 0x1 | 0x2 | 0x4 | 0x1000 | 0x20000);
  EXPECT_EQ(problem(with(mipped, 28, 3)), "");
  EXPECT_NE(problem(with(mipped, 28, 4)).find("mip levels"), std::string::npos);
  // Block formats: DXT1 passes with its blocks' bytes, DXT4 is refused by name.
  std::vector<unsigned char> dxt1 = with(with(good, 80, 0x4), 84, 0x31545844);
  dxt1.resize(128 + 8);  // 4 x 3 texels: one 4 x 4 block of 8 bytes
  EXPECT_EQ(problem(dxt1), "");
  EXPECT_NE(problem(with(dxt1, 84, 0x34545844)).find("DXT4"), std::string::npos);
  EXPECT_NE(problem(with(dxt1, 16, 12)).find("run past"), std::string::npos);  // 12 wide: 3 blocks
}

TEST(TextureSources, BasisuUsesItsFallbackOrIsOneClearError) {
  const fs::path dir = test::temp_dir("basisu");
  test::write_bytes(dir / "texels.dds", dds_image(1, 1));  // stands for a .ktx2: never decoded
  test::Document doc = textured_triangle(
      dir, {{"source", 0}, {"extensions", {{"KHR_texture_basisu", {{"source", 1}}}}}});
  doc.gltf["extensionsUsed"] = {"KHR_texture_basisu"};
  test::write_document(dir / "fallback.gltf", doc);
  const Scene scene = load_scene(dir / "fallback.gltf");
  ASSERT_EQ(scene.images.size(), 1u);
  EXPECT_EQ(scene.images[0].width, 1u);
  EXPECT_EQ(scene.images[0].rgba8[0], 188);  // the grey PNG, 0.5 linear

  doc.gltf["textures"][0].erase("source");
  doc.gltf["extensionsRequired"] = {"KHR_texture_basisu"};
  test::write_document(dir / "only_ktx2.gltf", doc);
  try {
    load_scene(dir / "only_ktx2.gltf");
    ADD_FAILURE() << "a KTX2-only texture loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("KHR_texture_basisu"), std::string::npos) << e.what();
  }
}

// ---- copies made by glTF-Transform ----

struct Triangle {
  glm::vec3 a, b, c;
};

// Every visible triangle in world space, with its instance's world transform applied.
std::vector<Triangle> world_triangles(const Scene& scene) {
  std::vector<Triangle> out;
  for (const Instance& instance : scene.instances()) {
    for (const MeshPrimitive& p : scene.meshes[instance.mesh].primitives)
      for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        const auto at = [&](size_t k) {
          return glm::vec3(instance.world * glm::vec4(p.positions[p.indices[t + k]], 1));
        };
        out.push_back({at(0), at(1), at(2)});
      }
  }
  return out;
}

// Same surface: as many triangles, the same total area and bounds (within `tolerance` of the
// scene's size: quantization moves vertices by a fraction of it).
void expect_same_geometry(const Scene& copy, const Scene& original, float tolerance,
                          const std::string& what) {
  const std::vector<Triangle> a = world_triangles(copy), b = world_triangles(original);
  ASSERT_EQ(a.size(), b.size()) << what;
  const auto area = [](const std::vector<Triangle>& ts) {
    double sum = 0;
    for (const Triangle& t : ts) sum += 0.5 * glm::length(glm::cross(t.b - t.a, t.c - t.a));
    return sum;
  };
  EXPECT_NEAR(area(a) / area(b), 1.0, 0.01) << what;
  const auto [lo_a, hi_a] = copy.bounds();
  const auto [lo_b, hi_b] = original.bounds();
  const float size = glm::length(hi_b - lo_b);
  EXPECT_LT(glm::length(lo_a - lo_b), tolerance * size) << what;
  EXPECT_LT(glm::length(hi_a - hi_b), tolerance * size) << what;
  EXPECT_EQ(copy.materials.size(), original.materials.size()) << what;
}

TEST(GltfTransformCopies, DracoMeshoptAndQuantizedLoadAsTheOriginalGeometry) {
  HIPR_REQUIRE_GLTF_TRANSFORM();
  const fs::path dir = test::temp_dir("gltf_transform_geometry");
  for (const char* name : {"cornell_box.gltf", "cornell_sphere.glb"}) {
    const fs::path source = test::asset(name);
    const Scene original = load_scene(source);
    const std::string stem = fs::path(name).stem().string();
    for (const auto& [command, extension] :
         std::vector<std::pair<std::string, std::string>>{{"draco", ".glb"},
                                                          {"draco", ".gltf"},
                                                          {"meshopt", ".glb"},
                                                          {"meshopt", ".gltf"},
                                                          {"quantize", ".glb"}}) {
      const fs::path copy =
          test::gltf_transform(command, source, dir / (stem + "_" + command + extension));
      const std::string what = std::string(name) + " via " + command + extension;
      expect_same_geometry(load_scene(copy), original, 2e-3f, what);
    }
  }
}

// A quad showing a 64x64 PNG, built here, and its WebP and AVIF copies: the texels agree within
// the formats' loss (exactly for lossless WebP).
TEST(GltfTransformCopies, WebpAndAvifTexturesDecodeAsTheirPngs) {
  HIPR_REQUIRE_GLTF_TRANSFORM();
  const fs::path dir = test::temp_dir("gltf_transform_webp");
  ImageRGB texture{64, 64, std::vector<float>(64 * 64 * 3)};
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      float* rgb = &texture.rgb[(y * 64 + x) * 3];
      rgb[0] = float(x) / 63.0f;
      rgb[1] = float(y) / 63.0f;
      rgb[2] = ((x / 8 + y / 8) % 2) ? 0.8f : 0.1f;
    }
  write_image(dir / "texture.png", texture);
  test::Document doc = test::triangle_document();
  const int uv = doc.add_accessor(std::vector<float>{0, 0, 1, 0, 0, 1}, test::kFloat, "VEC2", 3);
  doc.primitive()["attributes"]["TEXCOORD_0"] = uv;
  doc.gltf["images"] = json::array({{{"uri", "texture.png"}}});
  doc.gltf["textures"] = json::array({{{"source", 0}}});
  doc.gltf["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  test::write_document(dir / "quad.gltf", doc);

  const Scene original = load_scene(dir / "quad.gltf");
  ASSERT_EQ(original.images.size(), 1u);
  // Lossless WebP: every texel as the PNG has it. Lossy (the tool's default, quality 80, with
  // 4:2:0 chroma): near it, and nowhere flipped or shifted (which would cost far more).
  struct Copy {
    const char* command;
    std::string arguments;
    double mean_limit;
  };
  for (const Copy& copy :
       {Copy{"webp", "--lossless true", 0.0}, Copy{"webp", "", 25.0}, Copy{"avif", "", 25.0}}) {
    const std::string arguments = std::string(copy.command) + " " + copy.arguments;
    const double mean_limit = copy.mean_limit;
    const Scene webp = load_scene(test::gltf_transform(copy.command, dir / "quad.gltf",
                                                       dir / (std::string(copy.command) + ".glb"),
                                                       copy.arguments));
    ASSERT_EQ(webp.images.size(), 1u);
    const Image& a = webp.images[0];
    const Image& b = original.images[0];
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.rgba8.size(), b.rgba8.size());
    double difference = 0;
    for (size_t i = 0; i < a.rgba8.size(); ++i)
      difference += std::abs(int(a.rgba8[i]) - int(b.rgba8[i]));
    EXPECT_LE(difference / double(a.rgba8.size()), mean_limit)
        << arguments << ": mean texel difference out of 255";
  }
}

TEST(GltfTransformCopies, BrokenDracoStreamsAreOneLineErrors) {
  HIPR_REQUIRE_GLTF_TRANSFORM();
  const fs::path dir = test::temp_dir("gltf_transform_bad_draco");
  const fs::path copy =
      test::gltf_transform("draco", test::asset("cornell_box.gltf"), dir / "draco.gltf");
  json doc;
  std::ifstream(copy) >> doc;
  // The Draco stream of the first primitive, cut short; then its bytes overwritten.
  const int view =
      doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"];
  json truncated = doc;
  truncated["bufferViews"][view]["byteLength"] =
      doc["bufferViews"][view]["byteLength"].get<int>() / 2;
  std::vector<std::pair<std::string, json>> cases = {{"truncated", truncated}};
  json missing_attribute = doc;
  missing_attribute["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]
                   ["attributes"]["POSITION"] = 99;
  cases.push_back({"missing attribute", missing_attribute});
  json bad_view = doc;
  bad_view["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] =
      999;
  cases.push_back({"missing bufferView", bad_view});
  for (const auto& [name, spoiled] : cases) {
    const fs::path path = write_json(dir, "bad.gltf", spoiled);
    try {
      load_scene(path);
      ADD_FAILURE() << name << ": loaded";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("mesh 0 primitive 0"), std::string::npos) << name << ": " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << name << ": " << message;
    }
  }
  // Garbage in the stream itself: an error or some mesh, never a crash (the sanitizers run this).
  std::vector<unsigned char> bin;
  {
    std::ifstream in(dir / doc["buffers"][0]["uri"].get<std::string>(), std::ios::binary);
    bin.assign(std::istreambuf_iterator<char>(in), {});
  }
  const size_t start = doc["bufferViews"][view].value("byteOffset", size_t(0));
  const size_t length = doc["bufferViews"][view]["byteLength"];
  for (size_t i = start + length / 3; i < start + length; i += 7) bin[i] ^= 0x5a;
  test::write_bytes(dir / doc["buffers"][0]["uri"].get<std::string>(), bin);
  try {
    load_scene(copy);
  } catch (const InputError&) {
  }
}

}  // namespace
}  // namespace hipr
