// `hipr view` as CI runs it: in a virtual X server (xvfb-run), scripted, ending in a
// screenshot. Checks that an edit from a script is visible, that overlays render what they
// stand for, that the panels draw, and that bad input is refused before any window opens.
// The window tests skip when xvfb-run is missing; the headless viewer's (--headless) run
// anywhere.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "core/error.h"
#include "hipr/edits.h"
#include "hipr/hipr_stages.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "image/debug_images.h"
#include "image/image_io.h"
#include "image/tonemap.h"
#include "render/render_readback.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;
using test::quoted;

constexpr uint32_t kSize = 128;

bool have_xvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// Deterministic runs: one full-frame step per frame (--tiles-per-step 64 = every tile), so a
// frame count fixes the picture. Unedited, 2 spp are reached at frame 2; a script edit comes
// at frame 4; by frame 8 the edit has converged again.
// Without panels (--no-ui) the window is exactly the render.
// The display is pinned to the plain one (no metering, clamp, not denoised): the screenshots are
// compared with images tone-mapped by tonemap_srgb8's default and with each other across edits.
std::string view_arguments(const std::string& extra, bool panels = false, bool denoised = false) {
  return "view " + quoted(test::asset("cornell_box.gltf")) +
         " --size 128x128 --tile 16 --spp 2 --max-depth 4 --tiles-per-step 64 --steps-per-frame 1 "
         "--script-every 4 --exposure 0 --tonemap clamp -q " +
         (panels ? "" : "--no-ui ") + (denoised ? "" : "--no-denoise ") + extra;
}

test::CommandResult run_in_xvfb(const std::string& arguments) {
  return test::run_command("xvfb-run -a -s '-screen 0 800x700x24' " + quoted(test::hipr_binary()) +
                           " " + arguments);
}

fs::path write_script(const fs::path& dir, const std::string& name, const std::string& json) {
  const fs::path path = dir / name;
  std::ofstream(path) << json;
  return path;
}

const char* kRecolour =
    R"({"edits": [{"op": "material", "material": "red", "set": {"base_color": [0.05, 0.1, 0.65]}}]})";
const char* kMove =
    R"({"edits": [{"op": "transform", "node": "tall_block", "translate": [0.12, 0.0, -0.05]}]})";

// Screenshots of one kind of run, made once per test binary: runs cost a second or two each.
class ViewerWindow : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { s_dir = test::temp_dir("viewer-window"); }

  void SetUp() override {
    if (!have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (package xvfb)";
  }

  // Runs the viewer once per distinct argument list and returns its screenshot.
  static const ImageRGB& screenshot(const std::string& name, const std::string& arguments,
                                    bool panels = false) {
    static std::map<std::string, ImageRGB> shots;
    if (auto it = shots.find(name); it != shots.end()) return it->second;
    const fs::path png = s_dir / (name + ".png");
    const test::CommandResult result =
        run_in_xvfb(view_arguments(arguments + " --screenshot " + quoted(png), panels));
    EXPECT_EQ(result.exit_code, kExitOk) << result.output;
    shots[name] = fs::exists(png) ? read_image(png) : ImageRGB{};
    return shots[name];
  }

  static fs::path script(const std::string& name, const char* json) {
    return write_script(s_dir, name, json);
  }

  // Runs the viewer for `frames` frames with `edits` as its script (saved as `name`) and --save
  // to `saved`; returns the box with the edits applied, which the saved file must load as.
  static Scene save_from_viewer(const char* edits, const std::string& name, const fs::path& saved,
                                int frames) {
    const test::CommandResult result =
        run_in_xvfb(view_arguments("--exit-after-frames " + std::to_string(frames) + " --save " +
                                   quoted(saved) + " --script " + quoted(script(name, edits))));
    EXPECT_EQ(result.exit_code, kExitOk) << result.output;
    Scene expected = load_scene(test::asset("cornell_box.gltf"));
    for (const Edit& edit : parse_edit_script(edits, name)) apply_edit(expected, edit);
    return expected;
  }

  static fs::path s_dir;
};

fs::path ViewerWindow::s_dir;

// The instance per pixel of `scene` at the test size, from the renderer's own G-buffer.
std::vector<uint32_t> instance_ids(const Scene& scene) {
  RenderSettings s;
  s.width = s.height = kSize;
  s.tile_size = 16;
  Renderer renderer(test::context(), scene, s);
  hipr_stages(renderer).stage1_visibility({});
  return renderer.gbuffer_instances();
}

uint32_t instance_of(const Scene& scene, const std::string& node) {
  const auto instances = scene.instances();
  for (uint32_t i = 0; i < instances.size(); ++i)
    if (scene.nodes[instances[i].node].name == node) return i;
  return UINT32_MAX;
}

// Mean of one channel over the pixels where `mask` holds `value`.
double masked_mean(const ImageRGB& image, const std::vector<uint32_t>& mask, uint32_t value,
                   int channel) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < mask.size(); ++i)
    if (mask[i] == value) {
      sum += image.rgb[3 * i + size_t(channel)];
      ++n;
    }
  return n ? sum / double(n) : -1.0;
}

// Whether 16x16 tile t holds the same pixels in both images.
bool same_tile(const ImageRGB& a, const ImageRGB& b, uint32_t t) {
  const uint32_t tx = t % (kSize / 16), ty = t / (kSize / 16);
  for (uint32_t y = ty * 16; y < ty * 16 + 16; ++y)
    for (uint32_t x = tx * 16; x < tx * 16 + 16; ++x)
      for (size_t c = 0; c < 3; ++c)
        if (a.rgb[(size_t(y) * kSize + x) * 3 + c] != b.rgb[(size_t(y) * kSize + x) * 3 + c])
          return false;
  return true;
}

TEST_F(ViewerWindow, AScriptedRecolourIsVisible) {
  const ImageRGB& before = screenshot("plain", "--exit-after-frames 8");
  const ImageRGB& after = screenshot(
      "recolour", "--exit-after-frames 8 --script " + quoted(script("recolour.json", kRecolour)));
  ASSERT_EQ(before.width, kSize);
  ASSERT_EQ(after.width, kSize);
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  const std::vector<uint32_t> ids = instance_ids(scene);
  const uint32_t wall = instance_of(scene, "left_wall");
  // The red wall turned blue (under the warm light: darker, and the bright speckles of 2 spp
  // keep some red in it)...
  EXPECT_GT(masked_mean(before, ids, wall, 0), masked_mean(before, ids, wall, 2) + 0.2);
  EXPECT_LT(masked_mean(after, ids, wall, 0), masked_mean(before, ids, wall, 0) - 0.15);
  EXPECT_GT(masked_mean(after, ids, wall, 2), masked_mean(before, ids, wall, 2) + 0.05);
  // ...and the right wall stayed green.
  const uint32_t right = instance_of(scene, "right_wall");
  EXPECT_NEAR(masked_mean(after, ids, right, 1), masked_mean(before, ids, right, 1), 0.05);
}

// The object-id view of a moved block is exactly the G-buffer of the moved scene: the edit
// reached the renderer and the overlay shows its ids, one flat colour per object.
// The display pass reads the renderer's display where the resolve wrote it, and the overlays
// are made on the GPU from the renderer's buffers: while the viewer
// re-renders an edit, no image crosses between host and device, only a few hundred bytes per
// frame (the sample counters the convergence test reads, frame parameters, the edit's material
// block), less than one row of the accumulation (128 x 28 bytes; the image is 128 x 128 x 12).
TEST_F(ViewerWindow, NoImageCrossesTheHostWhileReRendering) {
  for (const std::string overlay : {"none", "weights", "owed", "ids"}) {
    const fs::path stats = s_dir / ("transfer_stats_" + overlay + ".json");
    const test::CommandResult result = run_in_xvfb(
        view_arguments("--exit-after-frames 8 --overlay " + overlay + " --stats-json " +
                       quoted(stats) + " --script " + quoted(script("recolour.json", kRecolour))));
    ASSERT_EQ(result.exit_code, kExitOk) << result.output;
    std::ifstream in(stats);
    const nlohmann::json json = nlohmann::json::parse(in);
    ASSERT_TRUE(json.contains("host_transfer_bytes_per_frame")) << json.dump();
    EXPECT_LT(json["host_transfer_bytes_per_frame"].get<double>(), 2048.0)
        << overlay << ": " << json.dump();
    EXPECT_GT(json["steps"].get<double>(), 0.0);
    ASSERT_EQ(json["edits"].size(), 1u);
    EXPECT_GE(json["edits"][0]["latency_seconds"].get<double>(), 0.0) << "the recolour was shown";
  }
}

// --frames-dir writes what every frame showed, and which script edits it shows; --script-start
// holds the script back (here to frame 6 instead of 4): the frames before show the scene as
// loaded, the frames from then on the recolour.
TEST_F(ViewerWindow, FramesDirHoldsEveryFrameAndTheEditsItShows) {
  const fs::path frames = s_dir / "frames";
  fs::create_directories(frames);
  const test::CommandResult result = run_in_xvfb(
      view_arguments("--exit-after-frames 9 --script-start 6 --frames-dir " + quoted(frames) +
                     " --script " + quoted(script("recolour_late.json", kRecolour))));
  ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  std::ifstream in(frames / "frames.json");
  const nlohmann::json log = nlohmann::json::parse(in);
  ASSERT_EQ(log.size(), 9u);
  for (size_t i = 0; i < log.size(); ++i) {
    EXPECT_EQ(log[i]["frame"].get<uint32_t>(), i + 1);
    EXPECT_EQ(log[i]["script_edits"].get<uint32_t>(), i + 1 >= 7 ? 1u : 0u) << "frame " << i + 1;
    ASSERT_TRUE(fs::exists(frames / log[i]["file"].get<std::string>())) << log[i].dump();
  }
  // The red wall (left edge, mid height) before and after the recolour to blue.
  const ImageRGB before = read_image(frames / log[5]["file"].get<std::string>());
  const ImageRGB after = read_image(frames / log[8]["file"].get<std::string>());
  const size_t wall = (size_t(64) * before.width + 6) * 3;
  EXPECT_GT(before.rgb[wall], before.rgb[wall + 2]) << "red before";
  EXPECT_GT(after.rgb[wall + 2], after.rgb[wall]) << "blue after";
}

TEST_F(ViewerWindow, ObjectIdOverlayShowsTheEditedScene) {
  const ImageRGB& shot = screenshot("ids-moved", "--exit-after-frames 6 --overlay ids --script " +
                                                     quoted(script("move.json", kMove)));
  ASSERT_EQ(shot.width, kSize);
  Scene moved = load_scene(test::asset("cornell_box.gltf"));
  apply_edit(moved, parse_edit_script(kMove, "move").front());
  const std::vector<uint8_t> expected =
      tonemap_srgb8(object_id_image(instance_ids(moved), kSize, kSize).rgb, 0.0f);
  const std::vector<uint8_t> original = tonemap_srgb8(
      object_id_image(instance_ids(load_scene(test::asset("cornell_box.gltf"))), kSize, kSize).rgb,
      0.0f);
  size_t mismatches = 0, moved_pixels = 0;
  for (size_t i = 0; i < expected.size(); ++i) {
    mismatches += std::lround(shot.rgb[i] * 255.0f) != expected[i];
    moved_pixels += expected[i] != original[i];
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(moved_pixels, 100u) << "the move changes the id image";
}

// A scene without a camera (most real assets): a scripted move that grows the scene's bounds
// (the tall block in front of the box) changes the object ids only where the block was or is.
TEST_F(ViewerWindow, AMoveInASceneWithoutACameraKeepsTheView) {
  const fs::path scene = test::camera_less_cornell_box(s_dir);
  const char* move =
      R"({"edits": [{"op": "transform", "node": "tall_block", "translate": [0, 0, 0.6]}]})";
  const fs::path png = s_dir / "camera_less_ids.png";
  const test::CommandResult result =
      run_in_xvfb("view " + quoted(scene) +
                  " --size 128x128 --tile 16 --spp 2 --max-depth 4 --tiles-per-step 64 "
                  "--steps-per-frame 1 --script-every 4 "
                  "--env studio --no-ui -q --exit-after-frames 6 --overlay ids --script " +
                  quoted(script("camera_less_move.json", move)) + " --screenshot " + quoted(png));
  ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  const ImageRGB shot = read_image(png);
  ASSERT_EQ(shot.width, kSize);
  const Scene loaded = load_scene(scene);
  Scene moved = loaded;
  apply_edit(moved, parse_edit_script(move, "move").front());
  const std::vector<uint32_t> before = instance_ids(loaded), after = instance_ids(moved);
  const std::vector<uint8_t> expected =
      tonemap_srgb8(object_id_image(after, kSize, kSize).rgb, 0.0f);
  size_t mismatches = 0;
  for (size_t i = 0; i < expected.size(); ++i)
    mismatches += std::lround(shot.rgb[i] * 255.0f) != expected[i];
  EXPECT_EQ(mismatches, 0u) << "the screen shows the moved scene's ids";
  const uint32_t block = instance_of(loaded, "tall_block");
  size_t block_pixels = 0, other_changes = 0;
  for (size_t i = 0; i < before.size(); ++i) {
    if (before[i] == block || after[i] == block)
      ++block_pixels;
    else
      other_changes += before[i] != after[i];
  }
  EXPECT_GT(block_pixels, 100u);
  EXPECT_EQ(other_changes, 0u) << "outside the block's pixels the view shows what it showed";
}

// Right after an edit (one step: HiPR's stage 2 rendered the active tiles), the owed overlay
// tints exactly the tiles still showing old radiance: the wall's tiles are re-rendered and
// clean, the rest tinted.
TEST_F(ViewerWindow, OwedOverlayTintsTheTilesStillOwed) {
  const std::string edit =
      " --exit-after-frames 5 --script " + quoted(script("recolour.json", kRecolour));
  const ImageRGB& plain = screenshot("step1", edit);
  const ImageRGB& owed = screenshot("step1-owed", edit + " --overlay owed");
  const ImageRGB& weights = screenshot("step1-weights", edit + " --overlay weights");
  ASSERT_EQ(plain.width, kSize);
  ASSERT_EQ(owed.width, kSize);
  ASSERT_EQ(weights.width, kSize);
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  const std::vector<uint32_t> ids = instance_ids(scene);
  const uint32_t wall = instance_of(scene, "left_wall");
  uint32_t clean = 0, tinted = 0;
  for (uint32_t t = 0; t < (kSize / 16) * (kSize / 16); ++t) {
    bool shows_wall = false;
    for (uint32_t y = (t / 8) * 16; y < (t / 8) * 16 + 16; ++y)
      for (uint32_t x = (t % 8) * 16; x < (t % 8) * 16 + 16; ++x)
        shows_wall |= ids[y * kSize + x] == wall;
    const bool same = same_tile(plain, owed, t);
    if (shows_wall) {
      EXPECT_TRUE(same) << "tile " << t << " holds the wall: re-rendered by stage 2, not owed";
    }
    clean += same;
    tinted += !same;
  }
  EXPECT_GT(tinted, clean) << "most tiles still owe their restart after one step";
  // The weight heat map marks the active tiles (the wall) blue.
  EXPECT_GT(masked_mean(weights, ids, wall, 2), masked_mean(weights, ids, wall, 0) + 0.2);
  EXPECT_NE(weights.rgb, plain.rgb);
}

// With panels on, the window is wider than the render and the render sits unchanged in the
// view area (the panel takes the right side).
TEST_F(ViewerWindow, PanelsDrawBesideTheRender) {
  const ImageRGB& plain = screenshot("plain", "--exit-after-frames 8");
  // With the validation layer on: the swapchain, UI pass and display pass must be clean (exit
  // code 1 otherwise).
  const ImageRGB& ui = screenshot("ui", "--exit-after-frames 8 --validate", true);
  ASSERT_EQ(plain.width, kSize);
  ASSERT_GT(ui.width, kSize + 200);
  ASSERT_GE(ui.height, kSize);
  // The render, centred vertically at 1:1 in a view as wide as itself.
  const uint32_t top = (ui.height - kSize) / 2;
  size_t different = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x)
      for (size_t c = 0; c < 3; ++c)
        different += plain.rgb[(size_t(y) * kSize + x) * 3 + c] !=
                     ui.rgb[(size_t(y + top) * ui.width + x) * 3 + c];
  EXPECT_EQ(different, 0u);
  // The panel: text on a dark background, not a flat fill.
  std::map<uint32_t, size_t> colours;
  for (uint32_t y = 0; y < ui.height; ++y)
    for (uint32_t x = kSize + 10; x < ui.width; ++x) {
      const size_t i = (size_t(y) * ui.width + x) * 3;
      colours[uint32_t(std::lround(ui.rgb[i] * 255)) << 16 |
              uint32_t(std::lround(ui.rgb[i + 1] * 255)) << 8 |
              uint32_t(std::lround(ui.rgb[i + 2] * 255))]++;
    }
  EXPECT_GT(colours.size(), 20u);
}

// Errors and warnings the Khronos glTF-Validator reports for `files` (tools/validate_gltf.js,
// one JSON line per file), or nothing when node or the validator package is absent.
struct ValidatorReport {
  int errors = 0;
  std::map<std::string, int> codes;
};

std::optional<std::vector<ValidatorReport>> validate_gltf(const std::vector<fs::path>& files) {
  const fs::path tools = HIPR_TOOLS_DIR;
  if (std::system("command -v node >/dev/null 2>&1") != 0 ||
      !fs::exists(tools / "node_modules" / "gltf-validator" / "package.json"))
    return std::nullopt;
  std::string command = "node " + quoted(tools / "validate_gltf.js");
  for (const fs::path& file : files) command += " " + quoted(file);
  const test::CommandResult result = test::run_command(command);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  std::vector<ValidatorReport> reports;
  for (const std::string& line : test::lines_of(result.output)) {
    const nlohmann::json summary = nlohmann::json::parse(line);
    ValidatorReport report;
    report.errors = summary["errors"];
    for (const auto& [code, count] : summary["error_codes"].items()) report.codes[code] = count;
    reports.push_back(report);
  }
  return reports;
}

// Edits typed into the viewer (here: a script), saved at exit: the file reloads to the edited
// scene, and the glTF validator finds no error the original did not have.
TEST_F(ViewerWindow, SavedSceneReloadsToTheEditedScene) {
  const char* edits = R"({"edits": [
    {"op": "transform", "node": "tall_block", "translate": [0.12, 0.0, -0.05]},
    {"op": "material", "material": "red", "set": {"base_color": [0.05, 0.1, 0.65], "specular_roughness": 0.2}},
    {"op": "visibility", "node": "short_block", "visible": false},
    {"op": "camera", "translate": [0.0, 0.02, -0.1]}]})";
  const fs::path saved = s_dir / "edited.gltf";
  const Scene expected = save_from_viewer(edits, "save.json", saved, 17);
  ASSERT_TRUE(fs::exists(saved));
  const Scene reloaded = load_scene(saved);
  EXPECT_TRUE(diff_scenes(expected, reloaded).empty())
      << "the saved file loads as the edited scene";
  ASSERT_EQ(reloaded.nodes.size(), expected.nodes.size());
  for (size_t n = 0; n < expected.nodes.size(); ++n) {
    EXPECT_EQ(reloaded.nodes[n].visible, expected.nodes[n].visible) << n;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        EXPECT_NEAR(reloaded.nodes[n].local[c][r], expected.nodes[n].local[c][r], 1e-6f) << n;
  }
  EXPECT_FLOAT_EQ(reloaded.materials[1].params.specular_roughness, 0.2f);
  const auto reports = validate_gltf({test::asset("cornell_box.gltf"), saved});
  if (!reports && test::gltf_validator_required())
    FAIL() << "the set-up installs the glTF validator, yet it is absent";
  if (!reports)
    GTEST_SKIP()
        << "node or the gltf-validator package is absent (tools/setup-deps.sh installs it)";
  ASSERT_EQ(reports->size(), 2u);
  EXPECT_LE((*reports)[1].errors, (*reports)[0].errors);
  const auto& original = (*reports)[0].codes;
  for (const auto& [code, count] : (*reports)[1].codes)
    EXPECT_LE(count, original.count(code) ? original.at(code) : 0)
        << "new validator error " << code;
}

// Geometry edits as the viewer's script applies them (as if typed: Ctrl+D, Delete...): the
// saved file holds the copy and the deformed mesh, not the deleted block.
TEST_F(ViewerWindow, GeometryEditsAreSavedAsMade) {
  const char* edits = R"({"edits": [
    {"op": "duplicate", "node": "short_block", "as": "short_block_2", "translate": [-0.25, 0.0, 0.2]},
    {"op": "deform", "node": "tall_block", "matrix": [1,0,0,0, 0,1.3,0,0, 0,0,1,0, 0,0,0,1]},
    {"op": "delete", "node": "short_block"}]})";
  const fs::path saved = s_dir / "geometry.glb";
  const Scene expected = save_from_viewer(edits, "geometry.json", saved, 13);
  ASSERT_TRUE(fs::exists(saved));
  const Scene reloaded = load_scene(saved);
  EXPECT_TRUE(diff_scenes(expected, reloaded).empty())
      << "the saved file loads as the edited scene";
  EXPECT_THROW(find_node(reloaded, "short_block"), InputError);
  EXPECT_NO_THROW(find_node(reloaded, "short_block_2"));
}

// A light edit re-renders first where the light reaches (docs/method.md#light-reach): the
// lamp's range cut to 0.2 m at frame 24, the lamp moved 5 cm at frame 48 (24 steps of 4 of the 64
// tiles after the first edit: every tile has been re-rendered, none carries that edit's rank),
// then one step. Every tile that step cleaned (the owed overlay no longer tints it) is one stage 1
// found the moved lamp reaching, before or after the move.
TEST_F(ViewerWindow, AMovedLampRerendersWhereItReachesFirst) {
  const fs::path scene_file = test::asset("cornell_sphere.glb");
  const fs::path edits = script("reach.json", R"({"edits": [
    {"op": "light", "node": "lamp", "set": {"range": 0.2}},
    {"op": "transform", "node": "lamp", "translate": [-0.05, 0.0, 0.0]}]})");
  std::map<std::string, ImageRGB> shots;
  for (const char* overlay : {"none", "owed"}) {
    const fs::path png = s_dir / (std::string("reach-") + overlay + ".png");
    const test::CommandResult result =
        run_in_xvfb("view " + quoted(scene_file) +
                    " --size 128x128 --tile 16 --spp 2 --max-depth 4 --tiles-per-step 4 "
                    "--steps-per-frame 1 --no-ui -q"
                    " --script-every 24 --exit-after-frames 49 --script " +
                    quoted(edits) + " --overlay " + overlay + " --screenshot " + quoted(png));
    ASSERT_EQ(result.exit_code, kExitOk) << result.output;
    shots[overlay] = read_image(png);
  }
  // Stage 1 of the move, on a renderer of the same size and tiles.
  Scene before = load_scene(scene_file);
  apply_edit(before, LightEdit{.node = "lamp", .range = 0.2f});
  Scene after = before;
  apply_edit(after, TransformEdit{"lamp", glm::vec3(-0.05f, 0.0f, 0.0f), std::nullopt});
  RenderSettings s;
  s.width = s.height = kSize;
  s.tile_size = 16;
  Renderer renderer(test::context(), before, s);
  renderer.add_samples_full_frame(1);
  renderer.resolve_display_all(DisplayRule::Immediate);
  hipr_stages(renderer).stage1_visibility({});
  const ChangeSet changes = diff_scenes(before, after);
  renderer.update_scene(after, changes);
  const uint32_t reached = hipr_stages(renderer).stage1_visibility(changes);
  const std::vector<uint32_t> flags = read_tile_flags(renderer);
  EXPECT_GT(reached, 4u);
  EXPECT_LT(reached, 32u) << "a lamp of 0.2 m range lights a part of the box";
  uint32_t clean = 0;
  for (uint32_t t = 0; t < 64; ++t) {
    if (!same_tile(shots["none"], shots["owed"], t)) continue;
    ++clean;
    EXPECT_NE(flags[t] & abi::kTileActive, 0u)
        << "tile " << t << " was re-rendered first but the lamp does not reach it";
  }
  EXPECT_EQ(clean, 4u) << "one step of 4 tiles";
}

// Bad input is refused before a window opens: no display is needed to see the error.
// The selected object is the focus (docs/method.md#focus): from a cold start hipr renders where
// it is seen first, while --no-focus starts at the top row. Two steps of 4 of the 64 tiles.
TEST_F(ViewerWindow, TheSelectedObjectIsRenderedFirst) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  const std::vector<uint32_t> ids = instance_ids(scene);
  const uint32_t block = instance_of(scene, "short_block"), ceiling = instance_of(scene, "ceiling");
  std::map<std::string, ImageRGB> shots;
  for (const char* focus : {"", "--no-focus"}) {
    const fs::path exr = s_dir / (std::string("focus") + focus + ".exr");
    const test::CommandResult result =
        run_in_xvfb("view " + quoted(test::asset("cornell_box.gltf")) +
                    " --size 128x128 --tile 16 --spp 2 --max-depth 4 --tiles-per-step 4 "
                    "--steps-per-frame 1 --no-ui -q"
                    " --select short_block --exit-after-frames 2 --screenshot " +
                    quoted(exr) + " " + focus);
    ASSERT_EQ(result.exit_code, kExitOk) << result.output;
    shots[focus] = read_image(exr);
  }
  const double block_focused =
      masked_mean(shots[""], ids, block, 0) + masked_mean(shots[""], ids, block, 1);
  EXPECT_GT(block_focused, 0.01) << "the block's tiles were rendered first";
  EXPECT_EQ(masked_mean(shots["--no-focus"], ids, block, 0), 0.0)
      << "scanline order has not reached the block";
  EXPECT_GT(masked_mean(shots["--no-focus"], ids, ceiling, 0), 0.0) << "it starts at the top";
}

// The viewer shows the display denoised by default: its EXR screenshot (what the window shows,
// in linear radiance) is `hipr render --denoise` of the same samples, bit for bit, and differs
// from the plain display. The render's --stats-json states what the filter costs.
TEST(ViewerCli, TheDenoisedWindowIsTheDenoisedRender) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run is not installed (package xvfb)";
  const fs::path dir = test::temp_dir("viewer-denoised");
  const fs::path shown = dir / "shown.exr", plain = dir / "plain.exr", render = dir / "render.exr";
  const fs::path stats = dir / "stats.json";
  for (const auto& [shot, denoised] : {std::pair{shown, true}, std::pair{plain, false}}) {
    const test::CommandResult result = run_in_xvfb(
        view_arguments("--exit-after-frames 3 --screenshot " + quoted(shot), false, denoised));
    ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  }
  const test::CommandResult rendered =
      test::run_hipr("render " + quoted(test::asset("cornell_box.gltf")) +
                     " --width 128 --height 128 --tile 16 --spp 2 --max-depth 4 --denoise -q -o " +
                     quoted(render) + " --stats-json " + quoted(stats));
  ASSERT_EQ(rendered.exit_code, kExitOk) << rendered.output;
  EXPECT_EQ(read_image(shown).rgb, read_image(render).rgb);
  EXPECT_NE(read_image(shown).rgb, read_image(plain).rgb);
  std::ifstream in(stats);
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_GT(json.at("denoise_filter_seconds").get<double>(), 0.0);
  EXPECT_GT(json.at("denoise_seconds").get<double>(), 0.0);
}

TEST(ViewerCli, BadInputExitsTwoWithoutADisplay) {
  const fs::path dir = test::temp_dir("viewer-bad");
  const fs::path bad_script =
      write_script(dir, "bad.json",
                   R"({"edits": [{"op": "transform", "node": "teapot", "translate": [0,0,0]}]})");
  const fs::path shot = dir / "shot.png";
  const std::string base =
      quoted(test::asset("cornell_box.gltf")) + " --screenshot " + quoted(shot);
  for (const std::string& arguments :
       {base + " --size 12", base + " --size 0x64", base + " --overlay normals",
        base + " --policy best", base + " --script " + quoted(bad_script),
        base + " --script " + quoted(dir / "missing.json"),
        quoted(test::asset("cornell_box.gltf")) + " --screenshot " + quoted(dir / "shot.jpg"),
        quoted(test::asset("cornell_box.gltf")) + " --screenshot " +
            quoted(dir / "no/such/folder/shot.png"),
        quoted(dir / "missing.gltf"), base + " --visit-spp 0", base + " --policy oracle",
        base + " --display fast", base + " --save " + quoted(dir / "scene.obj"),
        base + " --save " + quoted(dir / "no/such/folder/a.gltf"), base + " --select teapot",
        base + " --frames-dir " + quoted(dir / "no/such/folder"), base + " --headless",
        base + " --converge-relmse 2", base + " --converge-seconds -1"}) {
    const test::CommandResult result = test::run_command(
        "env -u DISPLAY -u WAYLAND_DISPLAY " + quoted(test::hipr_binary()) + " view " + arguments);
    EXPECT_EQ(result.exit_code, kExitBadInput) << arguments << "\n" << result.output;
    const auto lines = test::lines_of(result.output);
    ASSERT_EQ(lines.size(), 1u) << result.output;
    EXPECT_EQ(lines[0].rfind("hipr: error: ", 0), 0u) << lines[0];
  }
  EXPECT_FALSE(fs::exists(shot));
}

// Headless, the viewer draws the same frames off screen: its screenshot is the window's, pixel for
// pixel (one step a frame fixes what each frame shows).
TEST_F(ViewerWindow, HeadlessFramesAreTheWindowsPixels) {
  const ImageRGB& window = screenshot(
      "recolour", "--exit-after-frames 8 --script " + quoted(script("recolour.json", kRecolour)));
  const fs::path png = s_dir / "headless_recolour.png";
  const test::CommandResult result = test::run_command(
      "env -u DISPLAY -u WAYLAND_DISPLAY " + quoted(test::hipr_binary()) + " " +
      view_arguments("--headless --exit-after-frames 8 --screenshot " + quoted(png) + " --script " +
                     quoted(script("recolour.json", kRecolour))));
  ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  const ImageRGB headless = read_image(png);
  ASSERT_EQ(window.width, kSize);
  EXPECT_EQ(headless.width, window.width);
  EXPECT_EQ(headless.height, window.height);
  EXPECT_EQ(headless.rgb, window.rgb);
}

// With no display at all: the panels draw, the script's edit reaches the screen, and the stats
// say how the frames were shown.
TEST(ViewerHeadless, RunsWithoutADisplay) {
  const fs::path dir = test::temp_dir("viewer-headless");
  const fs::path png = dir / "panels.png", stats = dir / "stats.json";
  const test::CommandResult result = test::run_command(
      "env -u DISPLAY -u WAYLAND_DISPLAY " + quoted(test::hipr_binary()) + " " +
      view_arguments("--headless --exit-after-frames 8 --screenshot " + quoted(png) +
                         " --stats-json " + quoted(stats) + " --script " +
                         quoted(write_script(dir, "recolour.json", kRecolour)),
                     /*panels=*/true));
  ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  std::ifstream in(stats);
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_EQ(json["presentation"], "off-screen (headless)");
  EXPECT_EQ(json["frames"].get<int>(), 8);
  EXPECT_GT(json["fps"].get<double>(), 0.0);
  // One step a frame until 2 spp: frames 1-2 and, after the edit at frame 4, two more.
  EXPECT_EQ(json["rendering"]["frames"].get<int>(), 4) << json.dump();
  EXPECT_GT(json["rendering"]["fps"].get<double>(), 0.0);
  EXPECT_LE(json["rendering"]["frame_ms_median"].get<double>(),
            json["rendering"]["frame_ms_max"].get<double>());
  // The status line's mean samples per pixel is summed on the GPU: no image crosses with panels
  // either.
  EXPECT_LT(json["host_transfer_bytes_per_frame"].get<double>(), 2048.0) << json.dump();
  ASSERT_EQ(json["edits"].size(), 1u);
  EXPECT_GE(json["edits"][0]["latency_seconds"].get<double>(), 0.0) << "the recolour was shown";
  // The side panel beside the render: wider than the render, and not one flat colour.
  const ImageRGB shot = read_image(png);
  ASSERT_GT(shot.width, kSize);
  const size_t x = shot.width - 100, row = size_t(shot.width) * 3;
  std::set<float> panel_values;
  for (size_t y = 0; y < shot.height; ++y) panel_values.insert(shot.rgb[y * row + x * 3]);
  EXPECT_GT(panel_values.size(), 3u) << "the panel's text and widgets";
}

// On a discrete GPU's path (HIPR_DEVICE_MEMORY=staged: device memory reached through copies), a
// frame that re-renders allocates no device memory and waits for one submission per step (the
// step's trace and resolve), the edit's own stages aside: the counters each step reads are
// mapped, staged copies reuse one staging buffer. 80 frames (16 spp, so all of them render):
// the one edit's stages (about 20 submissions, a few more when a loaded machine splits them
// over more frames) stay a small share of the average (40 frames failed at 1.525 in a full CI
// run).
TEST(ViewerHeadless, ReRenderingAllocatesNothingOnADiscreteGpusPath) {
  const fs::path dir = test::temp_dir("viewer-headless-staged");
  const fs::path stats = dir / "stats.json";
  const test::CommandResult result = test::run_command(
      "env -u DISPLAY -u WAYLAND_DISPLAY HIPR_DEVICE_MEMORY=staged " + quoted(test::hipr_binary()) +
      " view " + quoted(test::asset("cornell_box.gltf")) +
      " --size 128x128 --tile 16 --spp 16 --max-depth 4 --tiles-per-step 16 --steps-per-frame 1 "
      "--script-every 20"
      " --headless --exit-after-frames 80 -q --stats-json " +
      quoted(stats) + " --script " + quoted(write_script(dir, "recolour.json", kRecolour)));
  ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  std::ifstream in(stats);
  const nlohmann::json json = nlohmann::json::parse(in);
  const nlohmann::json& rendering = json["rendering"];
  ASSERT_EQ(rendering["frames"].get<int>(), 80) << json.dump();
  EXPECT_EQ(rendering["allocations_per_frame"].get<double>(), 0.0) << json.dump();
  EXPECT_LT(rendering["submissions_per_frame"].get<double>(), 1.5) << json.dump();
}

// A light edit is relit at once (docs/method.md#relighting): the frame after it shows the change
// before any step renders, so its latency is the edit's own work; a recolour shows after a step,
// presented at once rather than after a frame's budget of further steps.
TEST(ViewerHeadless, ARelitEditIsPresentedBeforeAnyStep) {
  const fs::path dir = test::temp_dir("viewer-headless-relit");
  const fs::path stats = dir / "stats.json";
  const fs::path script = write_script(
      dir, "edits.json",
      R"({"edits": [{"op": "emission", "material": "light", "set": {"emission_luminance": 2.0}},
                    {"op": "material", "material": "red", "set": {"base_color": [0.05, 0.1, 0.65]}}]})");
  const test::CommandResult result =
      test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + quoted(test::hipr_binary()) +
                        " view " + quoted(test::asset("cornell_box.gltf")) +
                        " --size 64x64 --tile 16 --spp 4 --max-depth 4 --script-start 20"
                        " --script-every 40 --headless --exit-after-frames 100 -q --stats-json " +
                        quoted(stats) + " --script " + quoted(script));
  ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  std::ifstream in(stats);
  const nlohmann::json json = nlohmann::json::parse(in);
  ASSERT_EQ(json["edits"].size(), 2u) << json.dump();
  const nlohmann::json& relit = json["edits"][0];
  const nlohmann::json& recolour = json["edits"][1];
  EXPECT_GE(relit["latency_seconds"].get<double>(), 0.0) << json.dump();
  EXPECT_EQ(relit["work_at_first_change"].get<double>(), 0.0)
      << "shown before any step: " << json.dump();
  EXPECT_GE(recolour["latency_seconds"].get<double>(), 0.0) << json.dump();
  EXPECT_GT(recolour["work_at_first_change"].get<double>(), 0.0)
      << "shown after a step: " << json.dump();
  EXPECT_EQ(relit["steps_at_first_change"].get<int>(), 0) << json.dump();
  EXPECT_EQ(recolour["steps_at_first_change"].get<int>(), 1)
      << "presented with its first step: " << json.dump();
}

// Valid input without a display: one line that says what to do, no crash.
TEST(ViewerCli, WithoutADisplayTheViewerSaysSo) {
  const test::CommandResult result =
      test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + quoted(test::hipr_binary()) +
                        " view " + quoted(test::asset("cornell_box.gltf")) + " -q");
  EXPECT_EQ(result.exit_code, kExitInternal) << result.output;
  const auto lines = test::lines_of(result.output);
  ASSERT_EQ(lines.size(), 1u) << result.output;
  EXPECT_NE(lines[0].find("xvfb-run"), std::string::npos) << lines[0];
}

}  // namespace
}  // namespace hipr
