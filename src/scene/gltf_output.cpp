#include "scene/gltf_output.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "core/file_util.h"
#include "core/log.h"
#include "scene/base64.h"

namespace hipr::gltf {
namespace fs = std::filesystem;

namespace {

void write_file(const fs::path& path, const std::vector<unsigned char>& bytes) {
  write_atomically(path, [&](const fs::path& temp) {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out)
      throw InputError("cannot write " + path.string() + ": cannot create a file in its folder");
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    out.close();
    if (!out) throw InputError("cannot write " + path.string() + " (disk full?)");
    // Replacing a file (saving in place): keep its permissions.
    std::error_code ec;
    const fs::file_status existing = fs::status(path, ec);
    if (!ec && fs::is_regular_file(existing)) fs::permissions(temp, existing.permissions(), ec);
  });
}

fs::path resolved(const fs::path& path) {
  std::error_code ec;
  const fs::path r = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal() : r;
}

void append_u32(std::vector<unsigned char>& out, uint32_t v) {
  const auto* b =
      reinterpret_cast<const unsigned char*>(&v);  // glTF is little-endian, as our platforms
  out.insert(out.end(), b, b + 4);
}

// The image's media type: declared, from its data: URI, or from its first bytes.
std::string image_mime(const Json& image, const std::string& uri,
                       const std::vector<unsigned char>& b) {
  if (image.contains("mimeType") && image["mimeType"].is_string()) return image["mimeType"];
  if (is_data_uri(uri)) {
    const std::string type = uri.substr(5, uri.find_first_of(";,") - 5);
    if (type.rfind("image/", 0) == 0) return type;
  }
  const auto starts = [&](std::initializer_list<unsigned char> magic, size_t at = 0) {
    return b.size() >= at + magic.size() &&
           std::equal(magic.begin(), magic.end(), b.begin() + std::ptrdiff_t(at));
  };
  if (starts({0x89, 'P', 'N', 'G'})) return "image/png";
  if (starts({0xFF, 0xD8, 0xFF})) return "image/jpeg";
  if (starts({'R', 'I', 'F', 'F'}) && starts({'W', 'E', 'B', 'P'}, 8)) return "image/webp";
  if (starts({0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB})) return "image/ktx2";
  return "";
}

std::string data_uri(const std::string& mime, const std::vector<unsigned char>& bytes) {
  return "data:" + mime + ";base64," + base64_encode(bytes);
}

// A file name as a URI reference: unreserved characters as they are, the rest percent-encoded.
std::string uri_of(const std::string& name) {
  static const char* kHex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : name) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~')
      out += char(c);
    else
      out += {'%', kHex[c >> 4], kHex[c & 15]};
  }
  return out;
}

bool has_array(const Json& doc, const char* key) {
  return doc.contains(key) && doc[key].is_array();
}

// Fails with a clear line if `path` is one of the source's side files.
void refuse_source_file(const SourceDocument& source, const fs::path& path,
                        bool allow_source_itself) {
  const fs::path target = resolved(path);
  const fs::path self = resolved(source.path);
  for (const fs::path& file : source_files(source)) {
    if (file != target || (allow_source_itself && file == self)) continue;
    throw InputError("refusing to overwrite " + path.string() +
                     ": it is a file of the scene being saved (" + source.name + ")");
  }
}

}  // namespace

std::vector<fs::path> source_files(const SourceDocument& source) {
  std::vector<fs::path> out = {resolved(source.path)};
  for (const SideFile& side : side_files(source.json)) {
    try {
      out.push_back(resolved(source.folder / uri_path(side.uri, source.name + ": " + side.what)));
    } catch (const InputError&) {
      // A URI the loader's sandbox refuses names no file of the scene.
    }
  }
  return out;
}

void write_glb(const SourceDocument& source, Json doc, const fs::path& path) {
  refuse_source_file(source, path, true);
  std::vector<unsigned char> bin;
  bool has_bin = false, grown = false;
  if (has_array(doc, "buffers") && !doc["buffers"].empty()) {
    Json& first = doc["buffers"][0];
    if (first.contains("uri") && first["uri"].is_string()) {
      bin = read_uri(source, first["uri"], "buffer 0");
      first.erase("uri");
    } else {
      bin = source.bin;
    }
    // The chunk holds the buffer's bytes (plus at most 3 of padding, which is added again below).
    if (first.contains("byteLength") && first["byteLength"].is_number_unsigned() &&
        first["byteLength"].get<size_t>() <= bin.size())
      bin.resize(first["byteLength"].get<size_t>());
    has_bin = true;
    // Further buffers join the chunk (in a GLB they would need URIs, and a data: URI there is
    // what validators warn about): their views move to buffer 0, at the offset each lands at
    // (4-aligned: no component is larger, so every accessor stays aligned). A meshopt fallback
    // buffer has no bytes to join (EXT_meshopt_compression decodes into it): it stays a buffer.
    std::vector<size_t> base(doc["buffers"].size(), 0);
    std::vector<size_t> index(doc["buffers"].size(), 0);
    Json kept = Json::array({first});
    for (size_t i = 1; i < doc["buffers"].size(); ++i) {
      const Json& buffer = doc["buffers"][i];
      if (is_meshopt_fallback(buffer) && !buffer.contains("uri")) {
        index[i] = kept.size();
        kept.push_back(buffer);
        continue;
      }
      if (!buffer.contains("uri") || !buffer["uri"].is_string())
        throw InputError(source.name + ": buffer " + std::to_string(i) + " has no uri");
      std::vector<unsigned char> bytes =
          read_uri(source, buffer["uri"], "buffer " + std::to_string(i));
      if (buffer.contains("byteLength") && buffer["byteLength"].is_number_unsigned() &&
          buffer["byteLength"].get<size_t>() <= bytes.size())
        bytes.resize(buffer["byteLength"].get<size_t>());
      bin.resize((bin.size() + 3) / 4 * 4, 0);
      base[i] = bin.size();
      bin.insert(bin.end(), bytes.begin(), bytes.end());
      grown = true;
    }
    const auto move_reference = [&](Json& object, const char* offset_key) {
      if (!object.is_object() || !object.contains("buffer") ||
          !object["buffer"].is_number_unsigned())
        return;
      const size_t buffer = object["buffer"].get<size_t>();
      if (buffer == 0 || buffer >= base.size()) return;
      object["buffer"] = index[buffer];
      if (index[buffer] == 0)
        object[offset_key] = base[buffer] + object.value(offset_key, size_t(0));
    };
    if (doc["buffers"].size() > 1 && has_array(doc, "bufferViews"))
      for (Json& view : doc["bufferViews"]) {
        move_reference(view, "byteOffset");
        // The compressed bytes a meshopt bufferView decodes from live in a buffer too.
        if (view.is_object() && view.contains("extensions") && view["extensions"].is_object() &&
            view["extensions"].contains("EXT_meshopt_compression"))
          move_reference(view["extensions"]["EXT_meshopt_compression"], "byteOffset");
      }
    doc["buffers"] = std::move(kept);
  }
  if (has_array(doc, "images")) {
    for (size_t i = 0; i < doc["images"].size(); ++i) {
      Json& image = doc["images"][i];
      if (!image.is_object() || !image.contains("uri") || !image["uri"].is_string()) continue;
      const std::string uri = image["uri"];
      const std::string what = "image " + std::to_string(i);
      std::vector<unsigned char> bytes;
      try {
        bytes = read_uri(source, uri, what);
      } catch (const InputError& e) {
        // The loader rendered a checkerboard for it; the saved file keeps the reference.
        log::warn(std::string(e.what()) + "; its URI is kept as it was");
        continue;
      }
      const std::string mime = image_mime(image, uri, bytes);
      if (mime.empty()) {
        log::warn(source.name + ": " + what + " is of an unknown format; embedded as a data: URI");
        image["uri"] = data_uri("application/octet-stream", bytes);
        continue;
      }
      if (!has_bin) {
        doc["buffers"] = Json::array({Json{{"byteLength", 0}}});
        has_bin = true;
      }
      bin.resize((bin.size() + 3) / 4 * 4, 0);
      const size_t offset = bin.size();
      bin.insert(bin.end(), bytes.begin(), bytes.end());
      doc["bufferViews"].push_back(
          {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes.size()}});
      image.erase("uri");
      image["bufferView"] = doc["bufferViews"].size() - 1;
      image["mimeType"] = mime;
      grown = true;
    }
  }
  if (grown) doc["buffers"][0]["byteLength"] = bin.size();

  std::string json = doc.dump();
  json.resize((json.size() + 3) / 4 * 4, ' ');
  bin.resize((bin.size() + 3) / 4 * 4, 0);
  std::vector<unsigned char> out;
  const size_t total = 12 + 8 + json.size() + (has_bin ? 8 + bin.size() : 0);
  if (total > 0xFFFFFFFFull)
    throw InputError(path.string() + ": the scene is too large for a .glb (over 4 GiB)");
  out.reserve(total);
  append_u32(out, 0x46546C67);  // "glTF"
  append_u32(out, 2);
  append_u32(out, uint32_t(total));
  append_u32(out, uint32_t(json.size()));
  append_u32(out, 0x4E4F534A);  // "JSON"
  out.insert(out.end(), json.begin(), json.end());
  if (has_bin) {
    append_u32(out, uint32_t(bin.size()));
    append_u32(out, 0x004E4942);  // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
  }
  write_file(path, out);
}

void write_gltf(const SourceDocument& source, Json doc, const fs::path& path) {
  refuse_source_file(source, path, true);
  const fs::path folder = fs::absolute(path).parent_path();
  const bool same_folder = resolved(folder) == resolved(source.folder);

  struct Pending {
    fs::path path;
    std::vector<unsigned char> bytes;
    bool replaces_freely;  // ours to overwrite (named after the output)
  };
  std::vector<Pending> files;
  if (!same_folder) {
    for (const SideFile& side : side_files(doc)) {
      const fs::path relative = uri_path(side.uri, source.name + ": " + side.what);
      const fs::path target = folder / relative;
      if (std::any_of(files.begin(), files.end(),
                      [&](const Pending& p) { return p.path == target; }))
        continue;
      try {
        files.push_back({target, read_uri(source, side.uri, side.what), false});
      } catch (const InputError& e) {
        if (side.what.rfind("image", 0) != 0) throw;
        log::warn(std::string(e.what()) + "; not copied, its URI is kept as it was");
      }
    }
  }
  if (source.glb && has_array(doc, "buffers") && !doc["buffers"].empty() &&
      !doc["buffers"][0].contains("uri")) {
    const std::string name = path.stem().string() + ".bin";
    std::vector<unsigned char> bytes = source.bin;
    const Json& length = doc["buffers"][0]["byteLength"];
    if (length.is_number_unsigned() && length.get<size_t>() <= bytes.size())
      bytes.resize(length.get<size_t>());
    doc["buffers"][0]["uri"] = uri_of(name);
    files.push_back({folder / name, std::move(bytes), true});
  }

  // Check everything before writing anything, so a refusal leaves no file behind.
  std::vector<const Pending*> to_write;
  for (const Pending& file : files) {
    refuse_source_file(source, file.path, false);
    if (resolved(file.path) == resolved(path))
      throw InputError(path.string() + " is also the name of one of its side files");
    std::error_code ec;
    if (!file.replaces_freely && fs::exists(file.path, ec)) {
      if (read_file_bytes(file.path) == file.bytes) continue;  // already there (an earlier save)
      throw InputError("cannot save " + path.filename().string() + ": " + file.path.string() +
                       " already exists with other content (another scene's file?); save into "
                       "another folder or as .glb");
    }
    to_write.push_back(&file);
  }
  for (const Pending* file : to_write) {
    std::error_code ec;
    fs::create_directories(file->path.parent_path(), ec);
    if (ec) throw InputError("cannot write " + file->path.string() + ": " + ec.message());
    write_file(file->path, file->bytes);
  }
  const std::string json = doc.dump(2) + "\n";
  write_file(path, std::vector<unsigned char>(json.begin(), json.end()));
}

}  // namespace hipr::gltf
