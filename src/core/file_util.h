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

std::vector<unsigned char> read_file_bytes(const std::filesystem::path& path);

}  // namespace hipr
