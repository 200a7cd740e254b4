// glTF documents built in code for the loader tests.
#include "gltf_document.h"

#include <fstream>

namespace hipr::test {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* const kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t chunk = uint32_t(bytes[i]) << 16 |
                           (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0u) |
                           (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0u);
    out += kAlphabet[chunk >> 18 & 63];
    out += kAlphabet[chunk >> 12 & 63];
    out += i + 1 < bytes.size() ? kAlphabet[chunk >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=';
  }
  return out;
}

}  // namespace

void write_bytes(const fs::path& path, const std::vector<unsigned char>& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

Document triangle_document() {
  Document doc;
  doc.gltf = {{"asset", {{"version", "2.0"}}},
              {"scene", 0},
              {"scenes", json::array({{{"nodes", {0}}}})},
              {"nodes", json::array({{{"name", "tri"}, {"mesh", 0}}})},
              {"materials", json::array({{{"name", "mat"}}})},
              {"bufferViews", json::array()},
              {"accessors", json::array()}};
  const int position =
      doc.add_accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, kFloat, "VEC3", 3);
  const int normal =
      doc.add_accessor(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3", 3);
  const int indices = doc.add_accessor(std::vector<uint16_t>{0, 1, 2}, kUnsignedShort, "SCALAR", 3);
  doc.gltf["meshes"] = json::array(
      {{{"name", "tri_mesh"},
        {"primitives", json::array({{{"attributes", {{"POSITION", position}, {"NORMAL", normal}}},
                                     {"indices", indices},
                                     {"material", 0}}})}}});
  return doc;
}

void write_document(const fs::path& file, Document doc, const std::string& buffer_uri) {
  const std::string uri =
      buffer_uri.empty() ? "data:application/octet-stream;base64," + base64(doc.bin) : buffer_uri;
  doc.gltf["buffers"] = json::array({{{"byteLength", doc.bin.size()}, {"uri", uri}}});
  fs::create_directories(file.parent_path());
  std::ofstream(file) << doc.gltf.dump(1);
}

}  // namespace hipr::test
