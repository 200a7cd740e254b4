#pragma once
// File helpers shared by every writer: outputs appear whole or not at all.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace hipr {

// Calls write(temp_path) for a temporary file beside `path`, then renames it onto `path`.
// If write throws, the temporary file is removed and `path` is left untouched.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path&)>& write);
// write_atomically for a text file; a failed write or flush (disk full) is an InputError.
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

std::vector<unsigned char> read_file_bytes(const std::filesystem::path& path);

}  // namespace hipr
