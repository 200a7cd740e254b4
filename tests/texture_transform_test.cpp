// Texture references on the GPU: each picks its UV set and applies its KHR_texture_transform
// (a 2x3 matrix) before the lookup. An emissive card shows a 2x2 checker texel for texel.
#include <gtest/gtest.h>

#include <array>

#include "card_scene.h"
#include "hipr/renderer.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

enum Texel { R, G, B, W };

// The colour each quadrant (top-left, top-right, bottom-left, bottom-right) of a 32x32 render
// shows, for a texture reference with the given flags and transform rows.
std::array<Texel, 4> quadrants(uint32_t flags, glm::vec3 row_u, glm::vec3 row_v) {
  Scene scene = test::make_card_camera_scene(0.0f);
  Image checker;
  checker.name = "checker";
  checker.width = checker.height = 2;
  checker.rgba8 = {255, 0, 0,   255, 0,   255, 0,   255,
                   0,   0, 255, 255, 255, 255, 255, 255};  // R G / B W
  scene.images.push_back(checker);
  scene.textures.push_back({"checker", 0, flags | abi::kTextureNearest, row_u, row_v});
  test::add_card(scene, "card", glm::mat4(1.0f), test::emissive_texture_material(0));

  RenderSettings s;
  s.width = s.height = 32;
  s.max_depth = 1;
  Renderer renderer(test::context(), scene, s);
  renderer.add_samples_full_frame(1);
  const ImageRGB image = renderer.image();
  std::array<Texel, 4> out{};
  const uint32_t centres[4][2] = {{8, 8}, {24, 8}, {8, 24}, {24, 24}};
  for (int q = 0; q < 4; ++q) {
    const float* c = &image.rgb[(size_t(centres[q][1]) * 32 + centres[q][0]) * 3];
    out[size_t(q)] = c[0] > 0.5f && c[1] > 0.5f ? W : c[0] > 0.5f ? R : c[1] > 0.5f ? G : B;
  }
  return out;
}

const glm::vec3 kU(1, 0, 0), kV(0, 1, 0);

TEST(TextureTransform, IdentityShowsTheTexture) {
  EXPECT_EQ(quadrants(0, kU, kV), (std::array<Texel, 4>{R, G, B, W}));
}

TEST(TextureTransform, OffsetShiftsByHalfATexture) {
  EXPECT_EQ(quadrants(0, {1, 0, 0.5f}, kV), (std::array<Texel, 4>{G, R, W, B}));
  EXPECT_EQ(quadrants(0, kU, {0, 1, 0.5f}), (std::array<Texel, 4>{B, W, R, G}));
}

TEST(TextureTransform, ScaleMagnifies) {
  EXPECT_EQ(quadrants(0, {0.5f, 0, 0}, {0, 0.5f, 0}), (std::array<Texel, 4>{R, R, R, R}));
}

TEST(TextureTransform, QuarterTurnRotates) {
  // rotation pi/2: u' = v, v' = -u (wrapping to 1 - u)
  EXPECT_EQ(quadrants(0, {0, 1, 0}, {-1, 0, 0}), (std::array<Texel, 4>{B, R, W, G}));
}

TEST(TextureTransform, SecondUvSetIsSelectedPerTexture) {
  // The card's TEXCOORD_1 mirrors u.
  EXPECT_EQ(quadrants(abi::kTextureUv1, kU, kV), (std::array<Texel, 4>{G, R, W, B}));
}

}  // namespace
}  // namespace hipr
