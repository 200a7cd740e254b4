// Extreme OpenPBR inputs on the GPU path: a sphere at tiny and huge scales, far off the origin,
// with mirror-smooth and fully rough glass, index 3 and index 1.0001, a mirror metal, a coat of
// index 3 and an emitter of 1e6 nits under it. No sample may come out NaN or infinite (the CPU
// side of the same inputs is OpenPbrRobustness in openpbr_test.cpp).
#include <gtest/gtest.h>

#include <string>

#include "hipr/renderer.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

struct Extreme {
  const char* name;
  void (*set)(MaterialParameters&);
};

void PrintTo(const Extreme& e, std::ostream* os) { *os << e.name; }

const Extreme kExtremes[] = {
    {"SmoothGlassIor3",
     [](MaterialParameters& m) {
       m.specular_weight = 1.0f;
       m.transmission_weight = 1.0f;
       m.specular_roughness = 0.0f;
       m.specular_ior = 3.0f;
       m.transmission_depth = 1e-3f;
       m.transmission_color = glm::vec3(0.2f, 0.5f, 0.9f);
     }},
    {"RoughGlassIorNearOne",
     [](MaterialParameters& m) {
       m.specular_weight = 1.0f;
       m.transmission_weight = 1.0f;
       m.specular_roughness = 1.0f;
       m.specular_ior = 1.0001f;
     }},
    {"ThinWalledMirrorGlass",
     [](MaterialParameters& m) {
       m.specular_weight = 1.0f;
       m.transmission_weight = 1.0f;
       m.specular_roughness = 0.0f;
       m.specular_ior = 3.0f;
       m.flags |= abi::kMaterialThinWalled;
     }},
    {"MirrorAnisotropicMetal",
     [](MaterialParameters& m) {
       m.specular_weight = 1.0f;
       m.base_metalness = 1.0f;
       m.specular_roughness = 0.0f;
       m.specular_anisotropy = 1.0f;
     }},
    {"BrightEmitterUnderCoatAndFuzz",
     [](MaterialParameters& m) {
       m.coat_weight = 1.0f;
       m.coat_ior = 3.0f;
       m.coat_roughness = 0.0f;
       m.fuzz_weight = 1.0f;
       m.fuzz_roughness = 0.0f;
       m.emission_color = glm::vec3(1.0f);
       m.emission_luminance = 1e6f;
     }},
};

class MaterialStress : public ::testing::TestWithParam<std::tuple<Extreme, float>> {};

TEST_P(MaterialStress, NoNonFiniteSamples) {
  const auto& [extreme, scale] = GetParam();
  Scene scene =
      test::make_furnace_scene(scale, glm::vec3(3.0f * scale, -2.0f * scale, scale), 1.0f, 1.0f);
  for (Material& m : scene.materials) extreme.set(m.params);
  RenderSettings s;
  s.width = s.height = 24;
  s.max_depth = 24;
  s.seed = 5;
  test::render_finite(scene, s, 4);
}

INSTANTIATE_TEST_SUITE_P(Extremes, MaterialStress,
                         ::testing::Combine(::testing::ValuesIn(kExtremes),
                                            ::testing::Values(1e-4f, 1.0f, 1e5f)),
                         [](const auto& test_info) {
                           const float scale = std::get<1>(test_info.param);
                           return std::string(std::get<0>(test_info.param).name) +
                                  (scale < 1.0f   ? "_Tiny"
                                   : scale > 1.0f ? "_Huge"
                                                  : "_Unit");
                         });

}  // namespace
}  // namespace hipr
