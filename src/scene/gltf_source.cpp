#include "scene/gltf_source.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "core/file_util.h"
#include "scene/base64.h"
#include "scene/glb_container.h"
#include "scene/gltf_sandbox.h"

namespace hipr::gltf {
namespace fs = std::filesystem;

namespace {

uint32_t u32(const std::vector<unsigned char>& bytes, size_t offset) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + offset, 4);
  return v;
}

}  // namespace

SourceDocument read_source(const fs::path& path) {
  SourceDocument source;
  source.path = path;
  source.name = path.filename().string();
  if (path.empty()) throw InputError("the scene has no source file to save from");
  std::error_code ec;
  source.folder = fs::absolute(path, ec).parent_path();
  const std::vector<unsigned char> bytes = read_file_bytes(path);
  source.glb = looks_like_glb(bytes);
  std::string text;
  if (source.glb) {
    check_glb_container(bytes, source.name);
    // Chunk 0 is JSON, chunk 1 (if any) BIN: check_glb_container guarantees both fit.
    const uint32_t json_length = u32(bytes, 12);
    text.assign(bytes.begin() + 20, bytes.begin() + 20 + std::ptrdiff_t(json_length));
    const size_t bin_at = 20 + size_t(json_length);
    if (bin_at + 8 <= bytes.size()) {
      const uint32_t bin_length = u32(bytes, bin_at);
      source.bin.assign(bytes.begin() + std::ptrdiff_t(bin_at + 8),
                        bytes.begin() + std::ptrdiff_t(bin_at + 8 + bin_length));
    }
  } else {
    text.assign(bytes.begin(), bytes.end());
  }
  try {
    source.json = Json::parse(text);
  } catch (const Json::exception&) {
    throw InputError(source.name + ": cannot save from it: its JSON no longer parses");
  }
  if (!source.json.is_object())
    throw InputError(source.name + ": cannot save from it: not a glTF document");
  return source;
}

bool is_data_uri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

fs::path uri_path(const std::string& uri, const std::string& what) {
  check_uri(uri, what);
  return fs::path(decode_uri(uri)).lexically_normal();
}

std::vector<unsigned char> read_uri(const SourceDocument& source, const std::string& uri,
                                    const std::string& what) {
  if (is_data_uri(uri)) {
    const size_t comma = uri.find(',');
    const std::string header = uri.substr(0, comma);
    if (comma == std::string::npos || header.size() < 7 ||
        header.compare(header.size() - 7, 7, ";base64") != 0)
      throw InputError(source.name + ": " + what + " has a data: URI that is not base64");
    const auto bytes = base64_decode(uri.substr(comma + 1));
    if (!bytes) throw InputError(source.name + ": " + what + " has invalid base64 data");
    return *bytes;
  }
  Sandbox sandbox(source.folder);
  std::vector<unsigned char> bytes;
  std::string err;
  if (!sandbox.read(&bytes, &err,
                    (source.folder / uri_path(uri, source.name + ": " + what)).string())) {
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throw InputError(source.name + ": " + what + ": " + err);
  }
  return bytes;
}

std::vector<SideFile> side_files(const Json& doc) {
  std::vector<SideFile> out;
  for (const char* kind : {"buffers", "images"}) {
    if (!doc.contains(kind) || !doc[kind].is_array()) continue;
    for (size_t i = 0; i < doc[kind].size(); ++i) {
      const Json& item = doc[kind][i];
      if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
      const std::string uri = item["uri"];
      if (!is_data_uri(uri))
        out.push_back(
            {uri, std::string(kind).substr(0, std::strlen(kind) - 1) + " " + std::to_string(i)});
    }
  }
  return out;
}

}  // namespace hipr::gltf
