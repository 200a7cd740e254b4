#pragma once
// glTF documents built in code (JSON + one binary buffer) for the loader tests.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace hipr::test {

constexpr int kFloat = 5126;
constexpr int kUnsignedShort = 5123;

void write_bytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes);

// A glTF document and its one binary buffer, built in code.
struct Document {
  nlohmann::json gltf;
  std::vector<unsigned char> bin;

  // Appends `values` as a new bufferView + accessor; returns the accessor index.
  template <typename T>
  int add_accessor(const std::vector<T>& values, int component_type, const char* type,
                   size_t count) {
    const size_t offset = bin.size();
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    bin.insert(bin.end(), bytes, bytes + values.size() * sizeof(T));
    bin.resize((bin.size() + 3) / 4 * 4, 0);  // keep every view 4-byte aligned
    gltf["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
    gltf["accessors"].push_back({{"bufferView", gltf["bufferViews"].size() - 1},
                                 {"componentType", component_type},
                                 {"type", type},
                                 {"count", count}});
    return int(gltf["accessors"].size() - 1);
  }

  nlohmann::json& primitive() { return gltf["meshes"][0]["primitives"][0]; }
};

// One triangle (node "tri", mesh "tri_mesh", material "mat") facing +Z. The buffer has no URI
// yet: write_document() adds one.
Document triangle_document();

// Writes `doc` as `file`; an empty `buffer_uri` embeds the buffer as a data: URI, any other is
// written as is (the test places the bytes where it wants them).
void write_document(const std::filesystem::path& file, Document doc,
                    const std::string& buffer_uri = "");

}  // namespace hipr::test
