#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>

namespace hipr {

// The size an OpenEXR file's header claims for its first part.
struct ExrDataWindow {
  int64_t width = 0;
  int64_t height = 0;
};

// Walks an OpenEXR file's header before OpenEXR sees it. OpenEXR allocates each attribute at the
// size its header claims (up to 2 GiB) before it finds the file too short, which costs seconds
// and gigabytes for a few hostile bytes; this walk refuses any attribute that does not fit in the
// file, names that are too long, and a header without a valid dataWindow, each as an InputError.
// Returns the largest part's window (a multi-part file's every part is walked), or nothing for a
// file that is not OpenEXR (no magic number) or cannot be found.
std::optional<ExrDataWindow> scan_exr_header(const std::filesystem::path& path);

// Whether an image of width x height texels can be held by a file of `file_bytes` bytes: no real
// file holds more than about a thousand texels per byte (the best compression of a constant
// image), so a header claiming more is refused before anything is allocated. Overflow-safe for
// any sizes a header can state.
bool plausible_image_size(int64_t width, int64_t height, uintmax_t file_bytes);

}  // namespace hipr
