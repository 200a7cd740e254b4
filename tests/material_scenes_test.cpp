// The real-world material test scenes of ../shared/scenes (skipped when absent), each rendered
// small under a studio environment: every sample finite, and a picture, not a black frame; the
// kernel specialized for the scene and the shortcut for background tiles change no pixel.
// The full-size renders these stand for are looked at by hand (see the README's commands).
#include <gtest/gtest.h>

#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "test_support.h"

namespace hipr {
namespace {

struct MaterialScene {
  const char* name;  // folder in ../shared/scenes
  const char* file;
};

void PrintTo(const MaterialScene& s, std::ostream* os) { *os << s.name; }

class MaterialScenes : public ::testing::TestWithParam<MaterialScene> {};

Scene load(const MaterialScene& param) {
  SceneLoadOptions options;
  options.environment = test::shared_scene("EnvMaps/studio_small_03_1k.hdr");
  return load_scene(test::shared_scene(std::string(param.name) + "/" + param.file), options);
}

RenderSettings settings() { return test::render_settings(48, 48, 16, 8, 9); }

TEST_P(MaterialScenes, RenderWithoutNonFiniteSamples) {
  if (!test::shared_scenes_available()) GTEST_SKIP() << "../shared/scenes is not available";
  EXPECT_GT(test::mean(test::render_finite(load(GetParam()), settings(), 4)), 0.01)
      << "a black frame";
}

ImageRGB render(const Scene& scene, const RenderSettings& s) {
  Renderer renderer(test::context(), scene, s);
  renderer.add_samples_full_frame(2);
  return renderer.image();
}

TEST_P(MaterialScenes, SkippingWhatTheSceneDoesNotNeedChangesNoPixel) {
  if (!test::shared_scenes_available()) GTEST_SKIP() << "../shared/scenes is not available";
  const Scene scene = load(GetParam());
  const ImageRGB image = render(scene, settings());
  RenderSettings uber = settings();
  uber.specialize_kernel = false;
  EXPECT_EQ(image.rgb, render(scene, uber).rgb) << "specialized kernel against the uber kernel";
  RenderSettings trace = settings();
  trace.skip_background_tiles = false;
  EXPECT_EQ(image.rgb, render(scene, trace).rgb) << "background tiles with and without ray queries";
}

INSTANTIATE_TEST_SUITE_P(
    Shared, MaterialScenes,
    ::testing::Values(MaterialScene{"MetalRoughSpheresNoTextures",
                                    "MetalRoughSpheresNoTextures.glb"},
                      MaterialScene{"TransmissionTest", "TransmissionTest.glb"},
                      MaterialScene{"TransmissionRoughnessTest", "TransmissionRoughnessTest.glb"},
                      MaterialScene{"AttenuationTest", "AttenuationTest.glb"},
                      MaterialScene{"ClearCoatTest", "ClearCoatTest.glb"},
                      MaterialScene{"SpecularTest", "SpecularTest.glb"},
                      MaterialScene{"SheenChair", "SheenChair.gltf"},
                      MaterialScene{"EmissiveStrengthTest", "EmissiveStrengthTest.glb"},
                      MaterialScene{"LightsPunctualLamp", "LightsPunctualLamp.gltf"},
                      MaterialScene{"GlassVaseFlowers", "GlassVaseFlowers.glb"},
                      MaterialScene{"DamagedHelmet", "DamagedHelmet.glb"}),
    [](const auto& test_info) { return std::string(test_info.param.name); });

}  // namespace
}  // namespace hipr
