#pragma once
// Shared helpers for the test suites: paths to test data, a validated Vulkan context, running
// the hipr binary, and image statistics.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "hipr/edits.h"
#include "hipr/renderer.h"
#include "hipr/scene.h"
#include "image/image_io.h"
#include "vk/context.h"

namespace hipr::test {

std::filesystem::path asset(const std::string& name);         // assets/scenes/NAME
std::filesystem::path shared_scene(const std::string& name);  // ../shared/scenes/NAME
bool shared_scenes_available();
// Whether the glTF validator must be there: tools/test.sh, whose set-up installs it, says so
// (HIPR_REQUIRE_GLTF_VALIDATOR=1); a validator test then fails without it instead of skipping.
bool gltf_validator_required();
std::filesystem::path temp_dir(const std::string& name);  // fresh, empty
// The shipped Cornell box without its camera, written into `dir` (as most real assets come: the
// view is the default camera that frames the scene as loaded).
std::filesystem::path camera_less_cornell_box(const std::filesystem::path& dir);

// One Vulkan context per test binary, with validation layers on. A test environment fails
// the run at exit if the layer reported any error.
const vk::Context& context();
// Small render settings for GPU tests, everything else at its default.
RenderSettings render_settings(uint32_t width, uint32_t height, uint32_t tile_size,
                               uint32_t max_depth, uint32_t seed);
// HiPR's stage 2 over every active tile in one dispatch, after ordering the schedule.
void discover_all(Renderer& renderer, uint32_t samples_per_pixel);
// Applies the edit to `scene` and returns what it changed (diff_scenes of before and after).
ChangeSet edit_scene(Scene& scene, const Edit& edit);
// Applies `edit`, updates the renderer and restarts it with `spp` samples per pixel: it must
// render what a renderer made for the edited scene (same settings) renders, bit for bit, the
// edit must change something, and that must differ from the scene before (non-fatal checks).
void expect_update_matches_fresh(Renderer& renderer, Scene& scene, const Edit& edit,
                                 uint32_t spp = 2);

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout + stderr
};
// Runs build/hipr with the given arguments (already shell-quoted where needed).
CommandResult run_hipr(const std::string& arguments);
// Runs a shell command line (stdout + stderr captured), e.g. hipr under xvfb-run.
CommandResult run_command(const std::string& command_line);
std::filesystem::path hipr_binary();  // build/hipr

std::string quoted(const std::filesystem::path& path);  // for run_hipr arguments
std::vector<std::string> lines_of(const std::string& text);

double mean(const ImageRGB& image, int channel = -1);  // channel -1: mean over RGB
bool all_finite(const ImageRGB& image);

// Renders `spp` samples per pixel over the whole frame and checks (non-fatally) that no sample
// came out NaN or infinite and that the image is finite.
ImageRGB render_finite(const Scene& scene, const RenderSettings& settings, uint32_t spp);

// A full-frame render of `spp` samples per pixel as a display shows it (the same GPU division of
// the same sums): what every schedule must end on, bit for bit.
ImageRGB full_frame_display(const Scene& scene, const RenderSettings& settings, uint32_t spp);

}  // namespace hipr::test

namespace hipr::test {

// A scene built in code: one UV sphere (white Lambert, base_color `albedo`) of `radius` at
// `center`, a camera on +Z framing it, and a uniform environment of radiance `env`.
Scene make_furnace_scene(float radius, glm::vec3 center, float albedo, float env);

// A small equirectangular environment of one radiance everywhere.
Environment uniform_environment(float radiance);

// The triangles of an n x n grid of quads over (n + 1)^2 vertices numbered row by row, two a
// quad, listed row by row, or shuffled by `shuffle_seed` (0: not): three indices a triangle.
std::vector<uint32_t> grid_triangles(uint32_t n, uint32_t shuffle_seed);

}  // namespace hipr::test

namespace hipr::test {

// Means over b x b pixel blocks (RGB averaged): comparisons then test the picture, not the
// particular noise of a render.
std::vector<double> block_means(const ImageRGB& image, uint32_t b);

// Compares the average of two independent renders `a`, `b` (different seeds) with `reference`
// over 4x4 blocks. Returns RMS(difference to reference) / RMS(our noise), where our noise is
// estimated from the half-difference of a and b (the standard error of their average).
// About 1 when the only difference is noise; clearly above 1 for a real change.
double error_to_noise_ratio(const ImageRGB& a, const ImageRGB& b, const ImageRGB& reference);
// The same for k >= 2 independent renders, the noise of their mean from their spread (k - 1
// degrees of freedom per block: steadier than one pair when a few blocks dominate the error,
// as with low-discrepancy samples).
double error_to_noise_ratio(const std::vector<ImageRGB>& renders, const ImageRGB& reference);

ImageRGB average(const ImageRGB& a, const ImageRGB& b);

}  // namespace hipr::test
