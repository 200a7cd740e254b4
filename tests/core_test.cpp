// Small building blocks every other part relies on: hashing, atomic writes, URI confinement,
// mesh completion and the workgroup scatter stride.
#include <cmath>
#include <fstream>
#include <iterator>
#include <numeric>
#include <stdexcept>
#include <string_view>

#include "core/error.h"
#include "core/file_util.h"
#include "core/hash.h"
#include "core/log.h"
#include "core/process.h"
#include "hipr/renderer.h"
#include "render/trace_pass.h"
#include "scene/gltf_sandbox.h"
#include "scene/mesh_processing.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;
using namespace std::string_view_literals;

std::vector<fs::path> folder_entries(const fs::path& dir) {
  std::vector<fs::path> entries;
  for (const auto& entry : fs::directory_iterator(dir)) entries.push_back(entry.path().filename());
  return entries;
}

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// ---- Hasher -------------------------------------------------------------------------------

// Error and warning lines stay one clean line whatever bytes a broken file put in a name.
TEST(PrintableLine, KeepsUtf8AndEscapesEverythingElse) {
  EXPECT_EQ(log::printable_line("node 'caf\xc3\xa9' \xe6\x97\xa5"),
            "node 'caf\xc3\xa9' \xe6\x97\xa5");  // valid UTF-8 stays
  EXPECT_EQ(log::printable_line("a\xff"
                                "b"),
            "a\\xffb");                                               // not UTF-8
  EXPECT_EQ(log::printable_line("\xc0\xaf"), "\\xc0\\xaf");           // an overlong '/'
  EXPECT_EQ(log::printable_line("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a UTF-16 surrogate
  EXPECT_EQ(log::printable_line("\xe6\x97"), "\\xe6\\x97");           // cut short
  EXPECT_EQ(log::printable_line("one\ntwo\tthree\x1b[31m"), "one two three\\x1b[31m");
}

TEST(Hasher, MatchesPublishedFnv1aValues) {
  // Cache keys and scene hashes are stored on disk: the function must never change.
  EXPECT_EQ(Hasher().value(), 0xcbf29ce484222325ull);
  EXPECT_EQ(Hasher().add("a", 1).value(), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(Hasher().add("foobar", 6).value(), 0x85944171f73967e8ull);
  EXPECT_EQ(Hasher().hex(), "cbf29ce484222325");
  EXPECT_EQ(Hasher().add("a", 1).hex(), "af63dc4c8601ec8c");
}

TEST(Hasher, TextIsTerminatedBySeparator) {
  const uint8_t separator = 0xff;
  EXPECT_EQ(Hasher().add("abc"sv).value(), Hasher().add("abc", 3).add(&separator, 1).value());
  EXPECT_NE(Hasher().add("ab"sv).add("c"sv).value(), Hasher().add("a"sv).add("bc"sv).value());
  EXPECT_NE(Hasher().add(""sv).value(), Hasher().value());
  // Raw bytes have no separator: split points do not matter.
  EXPECT_EQ(Hasher().add("ab", 2).add("c", 1).value(), Hasher().add("a", 1).add("bc", 2).value());
}

// ---- write_atomically / read_file_bytes ---------------------------------------------------

TEST(WriteAtomically, RenamesTheTemporaryFileOntoThePath) {
  const fs::path dir = test::temp_dir("atomic-ok");
  const fs::path target = dir / "out.exr";
  fs::path written;
  write_atomically(target, [&](const fs::path& temp) {
    written = temp;
    EXPECT_EQ(temp.parent_path(), dir);   // same folder, so the rename cannot cross devices
    EXPECT_EQ(temp.extension(), ".exr");  // writers pick the format by extension
    EXPECT_NE(temp, target);
    write_text(temp, "payload");
  });
  EXPECT_EQ(file_text(target), "payload");
  EXPECT_FALSE(fs::exists(written));
  EXPECT_EQ(folder_entries(dir), std::vector<fs::path>{"out.exr"});
}

TEST(WriteAtomically, ThrowingWriterLeavesNothingBehind) {
  const fs::path dir = test::temp_dir("atomic-throw");
  const fs::path target = dir / "out.png";
  EXPECT_THROW(write_atomically(target,
                                [](const fs::path& temp) {
                                  write_text(temp, "half");
                                  throw std::runtime_error("writer failed");
                                }),
               std::runtime_error);
  EXPECT_TRUE(folder_entries(dir).empty());
}

TEST(WriteAtomically, ThrowingWriterKeepsThePreviousFile) {
  const fs::path dir = test::temp_dir("atomic-keep");
  const fs::path target = dir / "out.png";
  write_text(target, "old");
  EXPECT_THROW(write_atomically(target,
                                [](const fs::path& temp) {
                                  write_text(temp, "new");
                                  throw InputError("writer failed");
                                }),
               InputError);
  EXPECT_EQ(file_text(target), "old");
  EXPECT_EQ(folder_entries(dir), std::vector<fs::path>{"out.png"});
}

TEST(WriteAtomically, WriterThatWritesNothingIsAnError) {
  const fs::path dir = test::temp_dir("atomic-empty");
  EXPECT_THROW(write_atomically(dir / "out.json", [](const fs::path&) {}), InputError);
  EXPECT_TRUE(folder_entries(dir).empty());
}

TEST(WriteAtomically, MissingFolderIsAnInputError) {
  const fs::path dir = test::temp_dir("atomic-missing");
  bool called = false;
  EXPECT_THROW(
      write_atomically(dir / "no" / "such" / "out.exr", [&](const fs::path&) { called = true; }),
      InputError);
  EXPECT_FALSE(called);
}

TEST(ReadFileBytes, ReadsEveryByte) {
  const fs::path dir = test::temp_dir("read-bytes");
  const std::string bytes(
      "\x00\x01\xff\n\r\x7f"
      "end",
      9);
  write_text(dir / "data.bin", bytes);
  const std::vector<unsigned char> read = read_file_bytes(dir / "data.bin");
  EXPECT_EQ(std::string(read.begin(), read.end()), bytes);

  write_text(dir / "empty.bin", "");
  EXPECT_TRUE(read_file_bytes(dir / "empty.bin").empty());
  EXPECT_THROW(read_file_bytes(dir / "missing.bin"), InputError);
}

TEST(ReadFileBytes, FolderIsAnInputError) {
  // A user may name a folder where a file is expected; that is their error, not ours.
  EXPECT_THROW(read_file_bytes(test::temp_dir("read-folder")), InputError);
}

// ---- glTF URI confinement -----------------------------------------------------------------

TEST(CheckUri, AcceptsPathsInsideTheFolder) {
  for (const char* uri : {"a.bin", "sub/x.png", "./x.bin", "sub/../x.bin", "a%20b.bin",
                          "data:application/octet-stream;base64,AAAA", "data:image/png;base64,"})
    EXPECT_NO_THROW(gltf::check_uri(uri, "buffer 0")) << uri;
}

TEST(CheckUri, RefusesPathsOutsideTheFolder) {
  for (const char* uri : {"../x.bin", "a/../../x", "/etc/passwd", "C:/x", "C:\\x", "\\\\server\\x",
                          "file:///etc/passwd", "http://example.com/x.bin", "%2e%2e/x.bin",
                          "%2F%65tc/passwd", "sub/..%2f..%2fx.bin", ""}) {
    try {
      gltf::check_uri(uri, "buffer 3");
      ADD_FAILURE() << "accepted '" << uri << "'";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("buffer 3"), std::string::npos) << message;
      EXPECT_NE(message.find("scene folder"), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

TEST(DecodeUri, DecodesPercentEscapesOnly) {
  EXPECT_EQ(gltf::decode_uri("a%20b.bin"), "a b.bin");
  EXPECT_EQ(gltf::decode_uri("%2e%2E/x"), "../x");
  EXPECT_EQ(gltf::decode_uri("plain/path.png"), "plain/path.png");
  // Malformed escapes are kept as written, never read past the end.
  EXPECT_EQ(gltf::decode_uri("100%"), "100%");
  EXPECT_EQ(gltf::decode_uri("x%4"), "x%4");
  EXPECT_EQ(gltf::decode_uri("%zz"), "%zz");
  EXPECT_EQ(gltf::decode_uri(""), "");
}

// ---- Mesh processing ----------------------------------------------------------------------

glm::vec3 face_normal(const std::vector<glm::vec3>& positions, const uint32_t* triangle) {
  const glm::vec3 a = positions[triangle[0]], b = positions[triangle[1]],
                  c = positions[triangle[2]];
  return glm::cross(b - a, c - a);
}

// Every triangle of `indices` faces +Z (counter-clockwise seen from +Z, as glTF requires).
void expect_all_face_plus_z(const std::vector<glm::vec3>& positions,
                            const std::vector<uint32_t>& indices) {
  ASSERT_EQ(indices.size() % 3, 0u);
  for (size_t t = 0; t < indices.size(); t += 3)
    EXPECT_GT(face_normal(positions, &indices[t]).z, 0.0f) << "triangle " << t / 3 << " is flipped";
}

TEST(Triangulate, StripKeepsTheFrontFace) {
  // A zig-zag strip up the Y axis: even vertices at x = 0, odd at x = 1.
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
  for (uint32_t i = 0; i < 7; ++i) {
    positions.emplace_back(float(i % 2), float(i / 2), 0.0f);
    indices.push_back(i);
  }
  const std::vector<uint32_t> triangles = triangulate(indices, 5);
  EXPECT_EQ(triangles.size(), 3u * 5u);
  EXPECT_EQ(std::vector<uint32_t>(triangles.begin(), triangles.begin() + 6),
            (std::vector<uint32_t>{0, 1, 2, 2, 1, 3}));
  expect_all_face_plus_z(positions, triangles);
}

TEST(Triangulate, FanKeepsTheFrontFace) {
  std::vector<glm::vec3> positions = {glm::vec3(0.0f)};
  std::vector<uint32_t> indices = {0};
  for (uint32_t i = 0; i < 6; ++i) {
    const float angle = 0.4f * float(i);
    positions.emplace_back(std::cos(angle), std::sin(angle), 0.0f);
    indices.push_back(i + 1);
  }
  const std::vector<uint32_t> triangles = triangulate(indices, 6);
  EXPECT_EQ(triangles.size(), 3u * 5u);
  for (size_t t = 0; t < triangles.size(); t += 3) EXPECT_EQ(triangles[t], 0u);
  expect_all_face_plus_z(positions, triangles);
}

TEST(Triangulate, TooFewIndicesGiveNoTriangles) {
  EXPECT_TRUE(triangulate({}, 5).empty());
  EXPECT_TRUE(triangulate({0, 1}, 5).empty());
  EXPECT_TRUE(triangulate({0, 1}, 6).empty());
}

// Two triangles sharing an edge, folded along it so their face normals differ.
MeshPrimitive folded_quad() {
  MeshPrimitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1}};
  p.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  p.indices = {0, 1, 2, 0, 2, 3};
  return p;
}

void expect_unit(const glm::vec3& v, const std::string& what) {
  EXPECT_NEAR(glm::length(v), 1.0f, 1e-5f) << what;
}

void expect_valid_tangent_frames(const MeshPrimitive& p) {
  ASSERT_EQ(p.tangents.size(), p.positions.size());
  ASSERT_EQ(p.normals.size(), p.positions.size());
  for (size_t i = 0; i < p.positions.size(); ++i) {
    const glm::vec3 t(p.tangents[i]);
    expect_unit(p.normals[i], "normal " + std::to_string(i));
    expect_unit(t, "tangent " + std::to_string(i));
    EXPECT_NEAR(glm::dot(t, p.normals[i]), 0.0f, 1e-5f)
        << "tangent " << i << " is not perpendicular";
    EXPECT_EQ(std::abs(p.tangents[i].w), 1.0f) << "tangent " << i;
  }
}

TEST(CompletePrimitive, MissingNormalsGiveUnweldedFlatNormals) {
  const MeshPrimitive source = folded_quad();
  MeshPrimitive p = source;
  complete_primitive(p, "mesh 0 primitive 0");

  ASSERT_EQ(p.positions.size(), 6u);
  ASSERT_EQ(p.indices.size(), 6u);
  ASSERT_EQ(p.uvs.size(), 6u);
  for (size_t corner = 0; corner < 6; ++corner) {
    EXPECT_EQ(p.indices[corner], corner);
    EXPECT_EQ(p.positions[corner], source.positions[source.indices[corner]]);
    EXPECT_EQ(p.uvs[corner], source.uvs[source.indices[corner]]);
    const glm::vec3 face =
        glm::normalize(face_normal(source.positions, &source.indices[corner / 3 * 3]));
    EXPECT_NEAR(glm::distance(p.normals[corner], face), 0.0f, 1e-6f) << "corner " << corner;
  }
  // The shared corners now carry different normals: the mesh really was unwelded.
  EXPECT_GT(glm::distance(p.normals[0], p.normals[3]), 0.1f);
  expect_valid_tangent_frames(p);
}

TEST(CompletePrimitive, OutOfRangeIndexIsAnInputError) {
  MeshPrimitive p = folded_quad();
  p.indices[4] = 4;
  try {
    complete_primitive(p, "mesh 7 primitive 1");
    FAIL() << "index 4 of 4 vertices was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mesh 7 primitive 1"), std::string::npos) << e.what();
  }
}

TEST(CompletePrimitive, AttributeCountMismatchIsAnInputError) {
  MeshPrimitive p = folded_quad();
  p.uvs.pop_back();
  EXPECT_THROW(complete_primitive(p, "uvs"), InputError);
  p = folded_quad();
  p.normals.assign(3, glm::vec3(0, 0, 1));
  EXPECT_THROW(complete_primitive(p, "normals"), InputError);
}

TEST(CompletePrimitive, DropsAnIncompleteTrailingTriangle) {
  MeshPrimitive p = folded_quad();
  p.normals.assign(4, glm::vec3(0, 0, 1));
  p.indices.push_back(1);
  complete_primitive(p, "mesh");
  EXPECT_EQ(p.indices.size(), 6u);
}

TEST(CompletePrimitive, RepairsUnusableNormals) {
  MeshPrimitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  p.indices = {0, 1, 2};
  p.normals = {{std::nanf(""), 0, 1}, {0, 0, 0}, {0, 0, 3}};
  complete_primitive(p, "mesh");
  for (const glm::vec3& n : p.normals) {
    ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    EXPECT_NEAR(glm::distance(n, glm::vec3(0, 0, 1)), 0.0f,
                1e-6f);  // the face normal, or normalized
  }
  expect_valid_tangent_frames(p);
}

TEST(CompletePrimitive, GeneratedTangentsFollowTheUvs) {
  MeshPrimitive p = folded_quad();
  p.normals.assign(4, glm::normalize(glm::vec3(0.2f, -0.3f, 1.0f)));  // not the face normal
  complete_primitive(p, "mesh");
  expect_valid_tangent_frames(p);
  // u grows along +X on this mesh.
  EXPECT_GT(p.tangents[1].x, 0.5f);
}

TEST(CompletePrimitive, GivenTangentsAreNormalized) {
  MeshPrimitive p = folded_quad();
  p.normals.assign(4, glm::vec3(0, 0, 1));
  p.tangents.assign(4, glm::vec4(2, 0, 0, -5));
  complete_primitive(p, "mesh");
  expect_valid_tangent_frames(p);
  EXPECT_EQ(p.tangents[0], glm::vec4(1, 0, 0, -1));
}

TEST(CompletePrimitive, WithoutUvsTangentsAreStillAFrame) {
  MeshPrimitive p = folded_quad();
  p.uvs.clear();
  complete_primitive(p, "mesh");
  EXPECT_EQ(p.uvs.size(), p.positions.size());
  expect_valid_tangent_frames(p);
}

// ---- Workgroup scatter --------------------------------------------------------------------

TEST(ScatterStride, IsCoprimeToTheCount) {
  for (uint32_t n = 1; n <= 5000; ++n) {
    const uint32_t stride = scatter_stride(n);
    ASSERT_EQ(std::gcd(stride, n), 1u) << "n = " << n << ", stride = " << stride;
    // Below n, so (i * stride) % n visits every tile once and really scatters them.
    if (n > 1) {
      ASSERT_LT(stride, n) << "n = " << n;
    }
  }
  EXPECT_NEAR(double(scatter_stride(1000)) / 1000.0, 0.618, 0.01);
}

// ---- run_process --------------------------------------------------------------------------

TEST(RunProcess, FeedsStdinAndCollectsOutputAndExitCode) {
  // More input than a pipe buffer holds: feeding and draining must interleave.
  const std::string input(200000, 'x');
  const ProcessResult result = run_process({"sh", "-c", "wc -c; echo done >&2; exit 3"}, input);
  EXPECT_EQ(result.exit_code, 3);
  EXPECT_NE(result.output.find("200000"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("done"), std::string::npos) << result.output;
}

TEST(RunProcess, ArgumentsAreNotInterpretedByAShell) {
  const ProcessResult result = run_process({"echo", "$HOME; rm -rf /"}, "");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.output, "$HOME; rm -rf /\n");
}

TEST(RunProcess, AMissingProgramExits127) {
  EXPECT_EQ(run_process({"hipr-no-such-program"}, "ignored").exit_code, 127);
}

TEST(RunProcess, AChildThatIgnoresItsInputDoesNotBlockOrKillUs) {
  const ProcessResult result = run_process({"true"}, std::string(1 << 20, 'y'));
  EXPECT_EQ(result.exit_code, 0);
}

// HiPR ranks view-dependent surfaces first after a camera move: smooth metal, dielectric and
// coat lobes and refraction count; rough lobes and a matte base do not.
TEST(Materials, ViewDependenceFollowsTheSmoothLobesAndRefraction) {
  const MaterialParameters plastic = default_material_params();  // specular roughness 0.3
  EXPECT_FALSE(material_is_view_dependent(plastic));
  MaterialParameters m = plastic;
  m.specular_roughness = 0.1f;
  EXPECT_TRUE(material_is_view_dependent(m)) << "glossy dielectric";
  m = plastic;
  m.base_metalness = 1.0f;
  EXPECT_TRUE(material_is_view_dependent(m)) << "metal at roughness 0.3";
  m.specular_roughness = 0.6f;
  EXPECT_FALSE(material_is_view_dependent(m)) << "rough metal";
  m.specular_weight = 0.0f;
  m.specular_roughness = 0.0f;
  EXPECT_FALSE(material_is_view_dependent(m)) << "no specular lobe";
  m = plastic;
  m.transmission_weight = 1.0f;
  m.specular_roughness = 0.5f;
  EXPECT_TRUE(material_is_view_dependent(m)) << "refraction";
  m = plastic;
  m.coat_weight = 1.0f;
  m.coat_roughness = 0.0f;
  EXPECT_TRUE(material_is_view_dependent(m)) << "clear coat";
}

}  // namespace
}  // namespace hipr
