#include "app/viewer/screenshot.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "image/image_io.h"

namespace hipr::viewer {
namespace fs = std::filesystem;
namespace {

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

void check_screenshot_path(const fs::path& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".png" && ext != ".exr")
    throw InputError("screenshot must be .png or .exr: " + path.string());
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(dir)) throw InputError("screenshot folder does not exist: " + dir.string());
}

void save_screenshot(const fs::path& path, const vk::Context& ctx, const vk::Image& frame,
                     const ImageRGB& displayed) {
  check_screenshot_path(path);
  if (lower_extension(path) == ".exr") {
    write_image(path, displayed);
    return;
  }
  const std::vector<uint8_t> rgba = vk::read_image_rgba8(ctx, frame);
  std::vector<uint8_t> rgb(rgba.size() / 4 * 3);
  for (size_t i = 0, o = 0; i < rgba.size(); i += 4, o += 3)
    std::copy_n(rgba.begin() + std::ptrdiff_t(i), 3, rgb.begin() + std::ptrdiff_t(o));
  write_png8(path, frame.extent().width, frame.extent().height, 3, rgb);
}

}  // namespace hipr::viewer
