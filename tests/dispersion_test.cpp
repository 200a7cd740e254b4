// Dispersion (shaders/common/dispersion.glsl): the index at each channel's wavelength, run as
// the kernels run it, and a render through a dispersive glass sphere whose every colour channel
// is, in expectation, the render of a plain glass of that channel's index.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "card_scene.h"
#include "hipr/renderer.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace test::shader {
using namespace glm;
using namespace hipr::abi;
#include "shaders/common/dispersion.glsl"
}  // namespace test::shader

namespace {

namespace sh = test::shader;

TEST(Dispersion, TheIndexFollowsTheAbbeNumber) {
  const float ior = 1.5f, abbe = 20.0f;
  // At the d line the index is the material's; between the F and C lines it falls by
  // (n_d - 1) / V, the definition of the Abbe number.
  EXPECT_NEAR(sh::dispersed_ior(ior, 1.0f / abbe, 587.56f), ior, 1e-5f);
  const float f = sh::dispersed_ior(ior, 1.0f / abbe, 486.13f);
  const float c = sh::dispersed_ior(ior, 1.0f / abbe, 656.27f);
  EXPECT_NEAR(f - c, (ior - 1.0f) / abbe, 1e-4f);
  // Blue bends more than green, green more than red; no dispersion is the index itself.
  const float r = sh::dispersed_ior(ior, 1.0f / abbe, sh::dispersion_wavelength(0));
  const float g = sh::dispersed_ior(ior, 1.0f / abbe, sh::dispersion_wavelength(1));
  const float b = sh::dispersed_ior(ior, 1.0f / abbe, sh::dispersion_wavelength(2));
  EXPECT_LT(r, g);
  EXPECT_LT(g, b);
  for (uint32_t channel = 0; channel < 3; ++channel)
    EXPECT_EQ(sh::dispersed_ior(ior, 0.0f, sh::dispersion_wavelength(channel)), ior);
  // An index never falls below 1, whatever the dispersion.
  EXPECT_EQ(sh::dispersed_ior(1.01f, 100.0f, 700.0f), 1.0f);
}

TEST(Dispersion, EachChannelIsTakenAThirdOfTheTimeAndWeighedThreefold) {
  int counts[3] = {0, 0, 0};
  glm::vec3 sum(0.0f);
  for (int i = 0; i < 3000; ++i) {
    const uint32_t channel = sh::dispersion_channel((float(i) + 0.5f) / 3000.0f);
    ASSERT_LT(channel, 3u);
    ++counts[channel];
    sum += sh::dispersion_channel_weight(channel);
  }
  EXPECT_EQ(counts[0], 1000);
  EXPECT_EQ(counts[1], 1000);
  EXPECT_EQ(counts[2], 1000);
  EXPECT_EQ(sum / 3000.0f, glm::vec3(1.0f));  // unbiased: the mean weight is one per channel
  EXPECT_EQ(sh::dispersion_channel(0.99999994f), 2u);
}

// A smooth glass sphere (radius 0.55, at z = 1.2) between the card camera and an emissive card
// of vertical stripes: the sphere images the stripes, where each index puts them.
Scene sphere_before_stripes(float ior, float dispersion_scale) {
  Scene scene = test::make_card_camera_scene(0.0f);
  Image stripes;
  stripes.name = "stripes";
  stripes.width = 16;
  stripes.height = 1;
  for (uint32_t x = 0; x < 16; ++x) {
    const uint8_t v = (x % 2) ? 255 : 0;
    stripes.rgba8.insert(stripes.rgba8.end(), {v, v, v, 255});
  }
  scene.images.push_back(stripes);
  scene.textures.push_back({"stripes", 0, abi::kTextureNearest, {1, 0, 0}, {0, 1, 0}});
  test::add_card(scene, "stripes", glm::mat4(1.0f), test::emissive_texture_material(0));

  MeshPrimitive sphere;
  const int rings = 24, segments = 48;
  const float radius = 0.55f;
  const glm::vec3 centre(0.0f, 0.0f, 1.2f);
  for (int r = 0; r <= rings; ++r) {
    const float theta = float(M_PI) * float(r) / float(rings);
    for (int s = 0; s <= segments; ++s) {
      const float phi = 2.0f * float(M_PI) * float(s) / float(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
      sphere.positions.push_back(centre + radius * n);
      sphere.normals.push_back(n);
      sphere.tangents.push_back(glm::vec4(1, 0, 0, 1));
      sphere.uvs.push_back(glm::vec2(0.0f));
      sphere.uvs1.push_back(glm::vec2(0.0f));
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const uint32_t a = uint32_t(r * (segments + 1) + s), b = a + uint32_t(segments + 1);
      sphere.indices.insert(sphere.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  MaterialParameters glass = default_material_params();
  glass.specular_roughness = 0.0f;
  glass.specular_ior = ior;
  glass.transmission_weight = 1.0f;
  glass.transmission_dispersion_scale = dispersion_scale;
  sphere.material = uint32_t(scene.materials.size());
  scene.materials.push_back({"glass", glass});
  scene.meshes.push_back({"sphere", {sphere}});
  Node node;
  node.name = "sphere";
  node.mesh = int(scene.meshes.size() - 1);
  scene.nodes.push_back(node);
  scene.children.push_back({});
  scene.root_nodes.push_back(uint32_t(scene.nodes.size() - 1));
  return scene;
}

constexpr uint32_t kSize = 64, kBlock = 4;

// Means over kBlock x kBlock blocks of one channel: what the comparisons below compare, so
// that the dispersive render's colour noise averages out.
std::vector<double> block_means(const ImageRGB& image, int channel) {
  std::vector<double> means;
  for (uint32_t by = 0; by < kSize; by += kBlock)
    for (uint32_t bx = 0; bx < kSize; bx += kBlock) {
      double sum = 0.0;
      for (uint32_t y = by; y < by + kBlock; ++y)
        for (uint32_t x = bx; x < bx + kBlock; ++x)
          sum += image.rgb[(size_t(y) * kSize + x) * 3 + size_t(channel)];
      means.push_back(sum / (kBlock * kBlock));
    }
  return means;
}

double mean_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sum += std::abs(a[i] - b[i]);
  return sum / double(a.size());
}

ImageRGB render(const Scene& scene, uint32_t spp) {
  RenderSettings s;
  s.width = s.height = kSize;
  s.max_depth = 8;
  Renderer renderer(test::context(), scene, s);
  renderer.add_samples_full_frame(spp);
  return renderer.image();
}

TEST(Dispersion, EachChannelRefractsAtItsOwnWavelength) {
  // Abbe number 2 (scale 10 of 20): red sees 1.47, green 1.56, blue 1.73. Measured: each
  // channel 0.004 from its own index's render (block means, at 192 spp) and 0.21 to 0.32 from the
  // others'.
  const float ior = 1.5f, scale = 10.0f;
  const ImageRGB dispersive = render(sphere_before_stripes(ior, scale), 64);
  ImageRGB plain[3];
  for (uint32_t c = 0; c < 3; ++c)
    plain[c] =
        render(sphere_before_stripes(
                   sh::dispersed_ior(ior, scale / 20.0f, sh::dispersion_wavelength(c)), 0.0f),
               64);
  for (int c = 0; c < 3; ++c) {
    const std::vector<double> got = block_means(dispersive, c);
    const double own = mean_abs_difference(got, block_means(plain[c], c));
    for (int other = 0; other < 3; ++other) {
      if (other == c) continue;
      const double apart = mean_abs_difference(got, block_means(plain[other], c));
      EXPECT_LT(own, 0.25 * apart) << "channel " << c << " against the index of channel " << other;
    }
  }
  // A glass without dispersion is the same image whatever the channel: the channels agree.
  const ImageRGB still = render(sphere_before_stripes(ior, 0.0f), 16);
  EXPECT_EQ(block_means(still, 0), block_means(still, 2));
}

}  // namespace
}  // namespace hipr
