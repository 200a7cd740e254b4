#include "scene/gltf_sandbox.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "core/error.h"
#include "core/file_util.h"

namespace hipr::gltf {
namespace fs = std::filesystem;

std::string decode_uri(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(uint8_t(uri[i + 1])) &&
        std::isxdigit(uint8_t(uri[i + 2]))) {
      out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

void check_uri(const std::string& uri, const std::string& what) {
  if (uri.rfind("data:", 0) == 0) return;
  const std::string path = decode_uri(uri);
  const auto refuse = [&](const std::string& why) {
    throw InputError(what + " URI '" + uri + "' " + why +
                     " (only files inside the scene folder are read)");
  };
  if (path.empty()) refuse("is empty");
  if (path.find('\0') != std::string::npos) refuse("contains a NUL byte");
  if (path[0] == '/' || path[0] == '\\' || (path.size() > 1 && path[1] == ':'))
    refuse("is an absolute path");
  const size_t colon = path.find(':');
  if (colon != std::string::npos && path.find('/') > colon) refuse("has a URI scheme");
  int depth = 0;
  for (const auto& part : fs::path(path)) {
    if (part == "..")
      --depth;
    else if (part != "." && !part.empty())
      ++depth;
    if (depth < 0) refuse("leaves the scene folder");
  }
}

Sandbox::Sandbox(const fs::path& root) {
  std::error_code ec;
  m_root = fs::weakly_canonical(root, ec);
  if (ec) m_root = root;
}

bool Sandbox::inside(const fs::path& path) const {
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(path, ec);  // follows symlinks
  if (ec) return false;
  const auto [root_end, ignored] =
      std::mismatch(m_root.begin(), m_root.end(), resolved.begin(), resolved.end());
  return root_end == m_root.end();
}

// Existence is answered truthfully even outside the folder, so that read() is reached and
// refuses with a message that says why, instead of a misleading "file not found".
bool Sandbox::exists(const std::string& path) const {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

bool Sandbox::read(std::vector<unsigned char>* out, std::string* err, const std::string& path) {
  if (!inside(path)) {
    if (err) *err += "refused to read '" + path + "': outside the scene folder\n";
    return false;
  }
  try {
    *out = read_file_bytes(path);
  } catch (const std::exception& e) {
    if (err) *err += std::string(e.what()) + "\n";
    return false;
  }
  m_hasher.add(out->data(), out->size());
  return true;
}

}  // namespace hipr::gltf
