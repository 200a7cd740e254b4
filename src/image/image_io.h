#pragma once
// Image files through OpenImageIO. EXR keeps linear float radiance; PNG gets the tone-mapped
// sRGB image. Writes are atomic: a file appears whole or not at all.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "hipr/image.h"
#include "image/tonemap.h"

namespace hipr {

using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// PNG: `display` (exposure, tone mapper) then sRGB; EXR ignores it (linear radiance).
// Throws InputError for an unsupported extension (only .exr and .png) or a failed write.
void write_image(const std::filesystem::path& path, const ImageRGB& image,
                 const ImageMetadata& metadata = {}, const DisplayTransform& display = {});
// Writes 8-bit pixels as they are (already sRGB-encoded: no tone mapping) to a PNG, atomically.
// `channels`: 3 (RGB) or 4 (RGBA) bytes per pixel, rows top first.
void write_png8(const std::filesystem::path& path, uint32_t width, uint32_t height,
                uint32_t channels, const std::vector<uint8_t>& pixels);
// Reads an OpenEXR, PNG or Radiance .hdr image (told apart by content, never by name) as RGB: a
// grey image's one channel in all three. Any other file is an InputError.
ImageRGB read_image(const std::filesystem::path& path);
// Reads one metadata attribute as text ("" when absent).
std::string read_image_attribute(const std::filesystem::path& path, const std::string& name);

bool is_supported_output(const std::filesystem::path& path);

}  // namespace hipr
