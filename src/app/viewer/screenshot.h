#pragma once
// Screenshots. A .png holds what the window shows (the displayed image with overlays, and the
// panels when they are on), read back from the frame image; an .exr holds the displayed
// radiance itself (linear, without overlays or UI), as `hipr render` writes it. Both appear
// whole or not at all.
#include <filesystem>

#include "image/image_io.h"
#include "vk/context.h"
#include "vk/image.h"

namespace hipr::viewer {

// Throws InputError for an extension other than .png/.exr or a folder that does not exist,
// so a bad --screenshot is refused before any window opens.
void check_screenshot_path(const std::filesystem::path& path);

// `frame`: RGBA8 in TRANSFER_SRC_OPTIMAL layout, no GPU work pending on it.
void save_screenshot(const std::filesystem::path& path, const vk::Context& ctx,
                     const vk::Image& frame, const ImageRGB& displayed);

}  // namespace hipr::viewer
