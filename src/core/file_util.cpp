#include "core/file_util.h"

#include <fstream>
#include <system_error>

#include <unistd.h>

#include "core/error.h"

namespace hipr {
namespace fs = std::filesystem;

void write_atomically(const fs::path& path, const std::function<void(const fs::path&)>& write) {
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(dir)) throw InputError("output folder does not exist: " + dir.string());
  // Keep the extension last so format-by-extension writers still see it.
  const fs::path temp = dir / ("." + path.stem().string() + ".tmp" + std::to_string(getpid()) +
                               path.extension().string());
  try {
    write(temp);
    std::error_code ec;
    fs::rename(temp, path, ec);
    if (ec) throw InputError("cannot write " + path.string() + ": " + ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw;
  }
}

void write_text_atomically(const fs::path& path, const std::string& text) {
  write_atomically(path, [&](const fs::path& temp) {
    std::ofstream out(temp);
    out << text;
    out.close();  // the flush can fail too: checked before the rename makes the file visible
    if (!out) throw InputError("cannot write " + path.string());
  });
}

std::vector<unsigned char> read_file_bytes(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError("not a readable file: " + path.string());
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open " + path.string());
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError("cannot read " + path.string());
  std::vector<unsigned char> bytes(static_cast<size_t>(size));
  in.seekg(0);
  if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), size))
    throw InputError("cannot read " + path.string());
  return bytes;
}

}  // namespace hipr
