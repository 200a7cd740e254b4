// Scenes bigger than what the device addresses in one storage buffer (maxStorageBufferRange),
// reached with small scenes through ContextOptions::storage_range_limit: geometry that does not
// fit is one clear InputError, never a crash; textures that do not fit are shown at reduced
// resolution, the same picture.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "card_scene.h"
#include "core/error.h"
#include "hipr/renderer.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

vk::ContextOptions limited(uint64_t bytes) {
  vk::ContextOptions options;
  options.validation = true;
  options.storage_range_limit = bytes;
  return options;
}

// A 16x16 image of four 8x8 quadrants (red, green / blue, white) on an emissive card that fills
// the view, shown texel for texel (nearest).
Scene quadrant_card() {
  Scene scene = test::make_card_camera_scene(0.0f);
  Image image;
  image.name = "quadrants";
  image.width = image.height = 16;
  const std::array<std::array<uint8_t, 4>, 4> colours = {
      {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}}};
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      const auto& c = colours[(y / 8) * 2 + x / 8];
      image.rgba8.insert(image.rgba8.end(), c.begin(), c.end());
    }
  scene.images.push_back(image);
  scene.textures.push_back({"quadrants", 0, abi::kTextureNearest, {1, 0, 0}, {0, 1, 0}});
  test::add_card(scene, "card", glm::mat4(1.0f), test::emissive_texture_material(0));
  return scene;
}

ImageRGB render(const vk::Context& ctx, const Scene& scene) {
  RenderSettings s;
  s.width = s.height = 32;
  s.max_depth = 1;
  Renderer renderer(ctx, scene, s);
  renderer.add_samples_full_frame(1);
  return renderer.image();
}

TEST(DeviceLimits, GeometryBeyondOneStorageBufferIsOneClearError) {
  // A card's four vertex positions take more than 32 bytes.
  const vk::Context ctx(limited(32));
  try {
    render(ctx, quadrant_card());
    FAIL() << "a scene that does not fit the device rendered";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("vertex positions"), std::string::npos) << message;
    EXPECT_NE(message.find("maxStorageBufferRange"), std::string::npos) << message;
    EXPECT_NE(message.find("does not fit"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
  EXPECT_EQ(ctx.validation_errors(), 0u);
}

TEST(DeviceLimits, TexturesBeyondOneStorageBufferShowAtReducedResolution) {
  // 256 texels (1 KiB) into 128 bytes: the image halves twice, to 4x4, and every quadrant keeps
  // its colour. The geometry (4 vertices, 6 indices) fits.
  const vk::Context ctx(limited(128));
  const Scene scene = quadrant_card();
  const ImageRGB reduced = render(ctx, scene);
  const ImageRGB full = render(test::context(), scene);
  EXPECT_EQ(reduced.rgb, full.rgb);
  EXPECT_EQ(ctx.validation_errors(), 0u);
}

}  // namespace
}  // namespace hipr
