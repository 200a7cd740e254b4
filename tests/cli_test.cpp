// The hipr binary as scripts use it (docs/method.md#command-line-and-edit-scripts): exit codes,
// one-line errors, outputs that appear whole or not at all, image metadata and --stats-json.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "hipr/edits.h"
#include "hipr/scene_loader.h"
#include "hipr/schedule_settings.h"
#include "image/auto_exposure.h"
#include "image/image_io.h"
#include "image/tonemap.h"
#include "test_support.h"

namespace hipr {
namespace {
using test::lines_of;
using test::quoted;
namespace fs = std::filesystem;

// The names in `dir`, sorted.
std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir))
    files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

// A refused command: exit code 2, exactly one line that starts with "hipr: error: ".
void expect_one_error_line(const test::CommandResult& result) {
  EXPECT_EQ(result.exit_code, kExitBadInput) << result.output;
  const std::vector<std::string> lines = lines_of(result.output);
  ASSERT_EQ(lines.size(), 1u) << result.output;
  EXPECT_EQ(lines[0].rfind("hipr: error: ", 0), 0u) << lines[0];
}

TEST(Cli, HelpExitsZero) {
  const test::CommandResult result = test::run_hipr("--help");
  EXPECT_EQ(result.exit_code, kExitOk) << result.output;
  EXPECT_NE(result.output.find("render"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("info"), std::string::npos) << result.output;
}

TEST(Cli, RenderHelpListsTheContractFlags) {
  const test::CommandResult result = test::run_hipr("render --help");
  EXPECT_EQ(result.exit_code, kExitOk) << result.output;
  for (const char* flag :
       {"--width", "--height", "--spp", "--seed", "--max-depth", "--tile", "--env", "--stats-json"})
    EXPECT_NE(result.output.find(flag), std::string::npos) << flag;
}

// The scheduling settings are declared once (hipr/schedule_settings.h): every command that
// schedules takes every one of them as a flag (bench lists its policies as --policies), and a
// value a setting cannot take is a one-line parse error.
TEST(Cli, EveryCommandThatSchedulesTakesEverySchedulingFlag) {
  for (const std::string command : {"replay", "bench", "view"}) {
    const test::CommandResult result = test::run_hipr(command + " --help");
    EXPECT_EQ(result.exit_code, kExitOk) << result.output;
    ScheduleSettings settings;
    for_each_schedule_setting(settings, [&](const ScheduleSettingInfo& info, auto&) {
      if (command == "bench" && std::string(info.flag) == "--policy") return;
      EXPECT_NE(result.output.find(std::string(info.flag) + " "), std::string::npos)
          << command << " " << info.flag;
    });
  }
  const std::string common =
      quoted(test::asset("cornell_box.gltf")) + " " + quoted(test::asset("cornell_box.edits.json"));
  const fs::path dir = test::temp_dir("schedule_flags");
  for (const std::string flags : {"--display sometimes", "--policy best"}) {
    const test::CommandResult result =
        test::run_hipr("replay " + common + " -o " + quoted(dir / "r") + " " + flags);
    EXPECT_EQ(result.exit_code, kExitBadInput) << flags;
    EXPECT_NE(result.output.find(flags.substr(0, flags.find(' '))), std::string::npos)
        << result.output;
    EXPECT_FALSE(fs::exists(dir / "r")) << flags;
  }
}

// A command line that must be refused before anything is written. "@" stands for the test's
// output folder, which holds nothing but an invalid scene; "$cornell" for the shipped Cornell box.
struct BadCommand {
  const char* name;
  const char* arguments;
};

std::ostream& operator<<(std::ostream& out, const BadCommand& command) {
  return out << command.arguments;
}

std::string expand(std::string arguments, const fs::path& out_dir) {
  const std::pair<std::string, std::string> substitutions[] = {
      {"@", out_dir.string()},
      {"$cornell", quoted(test::asset("cornell_box.gltf"))},
      {"$edits", quoted(test::asset("cornell_box.edits.json"))}};
  for (const auto& [from, to] : substitutions)
    for (size_t at; (at = arguments.find(from)) != std::string::npos;)
      arguments.replace(at, from.size(), to);
  return arguments;
}

class BadCommandLine : public testing::TestWithParam<BadCommand> {};

TEST_P(BadCommandLine, ExitsTwoWithOneLineAndWritesNothing) {
  const fs::path out_dir = test::temp_dir("cli-bad");
  std::ofstream(out_dir / "invalid.gltf")
      << R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 3}]})";
  expect_one_error_line(test::run_hipr(expand(GetParam().arguments, out_dir)));
  EXPECT_EQ(files_in(out_dir), std::vector<std::string>{"invalid.gltf"})
      << "no output and no temporary file";
}

std::string bad_command_name(const testing::TestParamInfo<BadCommand>& param_info) {
  return param_info.param.name;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadCommandLine,
    testing::Values(
        BadCommand{"no_subcommand", ""}, BadCommand{"unknown_subcommand", "paint $cornell"},
        BadCommand{"unknown_flag", "render $cornell -o @/out.exr --bogus"},
        BadCommand{"missing_output", "render $cornell"},
        BadCommand{"spp_zero", "render $cornell -o @/out.exr --spp 0"},
        BadCommand{"denoise_frames_without_denoise",
                   "render $cornell -o @/out.exr --spp 1 --denoise-frames"},
        BadCommand{"denoise_history_out_of_range",
                   "render $cornell -o @/out.exr --spp 1 --denoise --denoise-history 1"},
        BadCommand{"negative_width", "render $cornell -o @/out.exr --width -5"},
        BadCommand{"bmp_output", "render $cornell -o @/out.bmp --width 8 --height 8 --spp 1"},
        BadCommand{"one_bad_output_of_two", "render $cornell -o @/out.exr -o @/out.bmp --spp 1"},
        BadCommand{"missing_scene", "render @/missing.gltf -o @/out.exr --spp 1"},
        BadCommand{"scene_not_gltf", "render @/ -o @/out.exr --spp 1"},
        BadCommand{"invalid_scene",
                   "render @/invalid.gltf -o @/out.png --width 8 --height 8 --spp 1"},
        BadCommand{"invalid_scene_info", "info @/invalid.gltf"},
        BadCommand{"bench_unknown_policy", "bench $cornell $edits -o @/b --policies hipr,zigzag"},
        BadCommand{"bench_no_policy", "bench $cornell $edits -o @/b --policies ,"},
        BadCommand{"bench_bad_display", "bench $cornell $edits -o @/b --display sometimes"},
        BadCommand{"bench_ref_spp_zero", "bench $cornell $edits -o @/b --ref-spp 0"},
        BadCommand{"bench_first_visit_over_spp",
                   "bench $cornell $edits -o @/b --spp 2 --first-visit-spp 3"},
        BadCommand{"bench_edits_not_json", "bench $cornell $cornell -o @/b"},
        BadCommand{"bench_invalid_scene", "bench @/invalid.gltf $edits -o @/b"},
        BadCommand{"replay_oracle", "replay $cornell $edits -o @/b --policy oracle"},
        BadCommand{"render_unknown_tonemap",
                   "render $cornell -o @/out.png --spp 1 --tonemap filmic"},
        BadCommand{"render_exposure_nan", "render $cornell -o @/out.png --spp 1 --exposure nan"},
        BadCommand{"render_exposure_word",
                   "render $cornell -o @/out.png --spp 1 --exposure bright"},
        BadCommand{"render_exposure_trailing",
                   "render $cornell -o @/out.png --spp 1 --exposure 1x"},
        BadCommand{"replay_unknown_tonemap", "replay $cornell $edits -o @/b --tonemap none"},
        BadCommand{"bench_exposure_inf", "bench $cornell $edits -o @/b --exposure inf"},
        BadCommand{"view_unknown_tonemap", "view $cornell --tonemap reinhard --headless"},
        BadCommand{"compare_unknown_tonemap", "compare $cornell $cornell --tonemap x"},
        BadCommand{"render_unknown_camera", "render $cornell -o @/out.png --spp 1 --camera 3"},
        BadCommand{"info_unknown_camera", "info $cornell --camera side"},
        BadCommand{"view_unknown_camera", "view $cornell --camera side --headless"}),
    bad_command_name);

TEST(Cli, EveryCommandThatShowsPicturesTakesTheDisplayFlags) {
  for (const std::string command : {"render", "replay", "bench", "view", "compare"}) {
    const test::CommandResult result = test::run_hipr(command + " --help");
    EXPECT_EQ(result.exit_code, kExitOk) << result.output;
    for (const char* flag : {"--exposure ", "--tonemap "})
      EXPECT_NE(result.output.find(flag), std::string::npos) << command << " " << flag;
  }
}

// The PNG follows --tonemap and --exposure (auto: metered); the EXR stays linear radiance.
TEST(Cli, RenderToneMapsThePngOnly) {
  const fs::path dir = test::temp_dir("cli-tonemap");
  const std::string base = "render " + quoted(test::asset("cornell_box.gltf")) +
                           " --width 16 --height 16 --spp 1 --seed 3 -q";
  ASSERT_EQ(
      test::run_hipr(base + " -o " + quoted(dir / "clamp.png") + " -o " + quoted(dir / "clamp.exr"))
          .exit_code,
      kExitOk);
  const test::CommandResult agx =
      test::run_hipr(base + " -o " + quoted(dir / "agx.png") + " -o " + quoted(dir / "agx.exr") +
                     " --tonemap agx --exposure auto");
  ASSERT_EQ(agx.exit_code, kExitOk) << agx.output;
  const ImageRGB linear = read_image(dir / "clamp.exr");
  EXPECT_EQ(read_image(dir / "agx.exr").rgb, linear.rgb) << "EXR is radiance, never tone-mapped";
  const std::vector<uint8_t> expected =
      tonemap_srgb8(linear.rgb, DisplayTransform{metered_exposure_ev(linear.rgb), ToneMapper::Agx});
  const ImageRGB png = read_image(dir / "agx.png");
  ASSERT_EQ(png.rgb.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i)
    ASSERT_NEAR(png.rgb[i] * 255.0f, float(expected[i]), 0.01f) << i;
  EXPECT_NE(read_image(dir / "clamp.png").rgb, png.rgb);
}

// FLIP compares what a screen shows: a brighter copy that clamps to the same white is the same
// image under clamp, and a different one under a mapper that keeps highlights apart.
TEST(Cli, CompareFlipFollowsTheToneMapper) {
  const fs::path dir = test::temp_dir("cli-compare-tonemap");
  ImageRGB a{4, 4, std::vector<float>(48, 2.0f)}, b{4, 4, std::vector<float>(48, 8.0f)};
  write_image(dir / "a.exr", a);
  write_image(dir / "b.exr", b);
  const std::string args =
      "compare " + quoted(dir / "a.exr") + " " + quoted(dir / "b.exr") + " --threshold 0.01 -q";
  EXPECT_EQ(test::run_hipr(args).exit_code, kExitOk);
  EXPECT_EQ(test::run_hipr(args + " --tonemap aces").exit_code, kExitDifferent);
  EXPECT_EQ(test::run_hipr(args + " --tonemap aces --exposure -8").exit_code, kExitDifferent);
}

// `hipr info` lists the cameras as --camera counts them; a lens saved in extras reloads.
TEST(Cli, InfoListsCamerasAndTheirLens) {
  const fs::path dir = test::temp_dir("cli-cameras");
  const fs::path script = dir / "lens.json";
  std::ofstream(script)
      << R"({"edits": [{"op": "camera", "aperture": 0.02, "focus_distance": 1.2}]})";
  const test::CommandResult saved = test::run_hipr(
      "replay " + quoted(test::asset("cornell_box.gltf")) + " " + quoted(script) + " -o " +
      quoted(dir / "out") + " --width 8 --height 8 --spp 1 --policy full -q --save " +
      quoted(dir / "lens.gltf"));
  ASSERT_EQ(saved.exit_code, kExitOk) << saved.output;
  const test::CommandResult info =
      test::run_hipr("info " + quoted(dir / "lens.gltf") + " --camera 0");
  ASSERT_EQ(info.exit_code, kExitOk) << info.output;
  EXPECT_NE(info.output.find("cameras    0 camera: yfov 39.3 deg, lens radius 0.02"),
            std::string::npos)
      << info.output;
  EXPECT_NE(info.output.find("(used)"), std::string::npos) << info.output;
}

TEST(Cli, MissingOutputFolderIsABadInput) {
  const fs::path out_dir = test::temp_dir("cli-no-folder");
  expect_one_error_line(test::run_hipr("render " + quoted(test::asset("cornell_box.gltf")) +
                                       " -o " + quoted(out_dir / "missing" / "out.exr") +
                                       " --width 8 --height 8 --spp 1 --quiet"));
}

TEST(Cli, BadStatsPathWritesNoImage) {
  // Every output is checked before rendering: an error exit never leaves some outputs behind.
  const fs::path out_dir = test::temp_dir("cli-bad-stats");
  const test::CommandResult result =
      test::run_hipr("render " + quoted(test::asset("cornell_box.gltf")) + " -o " +
                     quoted(out_dir / "out.exr") + " --stats-json " +
                     quoted(out_dir / "missing" / "stats.json") + " --width 8 --height 8 --spp 1");
  EXPECT_EQ(result.exit_code, kExitBadInput) << result.output;
  EXPECT_FALSE(fs::exists(out_dir / "out.exr"))
      << "an image was written although the command failed";
}

TEST(Cli, RequiredUnsupportedExtensionIsABadInput) {
  // The Cornell box, but requiring an extension the renderer does not implement.
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(test::asset("cornell_box.gltf")));
  scene["extensionsUsed"].push_back("EXT_hipr_made_up");
  scene["extensionsRequired"] = {"EXT_hipr_made_up"};
  const fs::path dir = test::temp_dir("cli-required-extension");
  std::ofstream(dir / "scene.gltf") << scene.dump();
  const test::CommandResult result =
      test::run_hipr("render " + quoted(dir / "scene.gltf") + " -o " + quoted(dir / "out.png") +
                     " --width 8 --height 8 --spp 1");
  expect_one_error_line(result);
  EXPECT_NE(result.output.find("requires unsupported glTF extension EXT_hipr_made_up"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

// One render of the Cornell box to EXR + PNG + stats, shared by the tests that inspect it.
class CornellRender : public testing::Test {
 protected:
  static constexpr uint32_t kSize = 32;
  static constexpr uint32_t kSpp = 2;
  static constexpr uint32_t kSeed = 7;

  static void SetUpTestSuite() {
    s_dir = test::temp_dir("cli-render");
    s_result = test::run_hipr("render " + quoted(test::asset("cornell_box.gltf")) + " -o " +
                              quoted(exr()) + " -o " + quoted(png()) +
                              " --width 32 --height 32 --spp 2 --seed 7 --stats-json " +
                              quoted(stats()) + " --validate");
  }
  void SetUp() override { ASSERT_EQ(s_result.exit_code, kExitOk) << s_result.output; }

  static fs::path exr() { return s_dir / "cornell.exr"; }
  static fs::path png() { return s_dir / "cornell.png"; }
  static fs::path stats() { return s_dir / "stats.json"; }

  static inline fs::path s_dir;
  static inline test::CommandResult s_result;
};

TEST_F(CornellRender, ExrIsTheRenderedImage) {
  const ImageRGB image = read_image(exr());
  EXPECT_EQ(image.width, kSize);
  EXPECT_EQ(image.height, kSize);
  EXPECT_TRUE(test::all_finite(image));
  EXPECT_GT(test::mean(image), 0.01) << "the lit Cornell box rendered black";
}

TEST_F(CornellRender, ExrCarriesProvenance) {
  EXPECT_EQ(read_image_attribute(exr(), "hipr:spp"), std::to_string(kSpp));
  EXPECT_EQ(read_image_attribute(exr(), "hipr:seed"), std::to_string(kSeed));
  const std::string hash = read_image_attribute(exr(), "hipr:scene_hash");
  EXPECT_EQ(hash.size(), 16u) << hash;
  EXPECT_EQ(hash.find_first_not_of("0123456789abcdef"), std::string::npos) << hash;
  EXPECT_EQ(hash, load_scene(test::asset("cornell_box.gltf")).content_hash);
}

TEST_F(CornellRender, PngIsTheSrgbEncodedExr) {
  const ImageRGB linear = read_image(exr());
  const ImageRGB encoded = read_image(png());
  ASSERT_EQ(encoded.width, kSize);
  ASSERT_EQ(encoded.height, kSize);
  EXPECT_EQ(read_image_attribute(png(), "oiio:ColorSpace"), "sRGB");
  for (size_t i = 0; i < encoded.rgb.size(); ++i) {
    const float v = encoded.rgb[i];
    ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << "value " << i << " = " << v;
    ASSERT_NEAR(v * 255.0f, std::round(v * 255.0f), 1e-3f) << "value " << i << " is not 8-bit";
    ASSERT_NEAR(v, srgb_encode(linear.rgb[i]), 0.51f / 255.0f) << "value " << i;
  }
}

TEST_F(CornellRender, StatsJsonHasTheContractKeys) {
  std::ifstream in(stats());
  ASSERT_TRUE(in) << "no " << stats();
  const nlohmann::json json = nlohmann::json::parse(in);
  for (const char* key : {"render_seconds", "samples_per_second", "rays_per_second",
                          "nonfinite_samples", "spp", "width", "height"})
    ASSERT_TRUE(json.contains(key) && json[key].is_number()) << key << " in " << json.dump();
  EXPECT_EQ(json["spp"], kSpp);
  EXPECT_EQ(json["width"], kSize);
  EXPECT_EQ(json["height"], kSize);
  EXPECT_EQ(json["nonfinite_samples"], 0);
  const double seconds = json["render_seconds"];
  EXPECT_GT(seconds, 0.0);
  EXPECT_LT(seconds, 60.0);
  const double samples = double(kSize) * kSize * kSpp;
  EXPECT_NEAR(json["samples_per_second"].get<double>() * seconds, samples, samples * 1e-6);
  // Every sample traces at least its camera ray.
  EXPECT_GE(json["rays_per_second"].get<double>(), json["samples_per_second"].get<double>());
}

// What the big-scene measurements read (BENCHMARKS.md "Big scenes"): the acceleration structure
// build is part of the set-up, and the device holds at least the scene's triangles.
TEST_F(CornellRender, StatsJsonStatesBuildTimeAndMemory) {
  std::ifstream in(stats());
  const nlohmann::json json = nlohmann::json::parse(in);
  const double blas = json.at("blas_build_seconds");
  EXPECT_GT(blas, 0.0);
  EXPECT_LE(blas, json.at("setup_seconds").get<double>());
  const uint64_t triangles = json.at("triangles");
  EXPECT_GE(json.at("device_bytes").get<uint64_t>(), triangles * 3 * sizeof(float) * 3);
  EXPECT_GT(json.at("peak_resident_bytes").get<uint64_t>(), 0u);
}

// Rays by kind: every sample of the closed box starts with one camera ray, a lit point casts a
// shadow ray, and the kinds add up to all the rays.
TEST_F(CornellRender, StatsJsonSplitsTheRaysByKind) {
  std::ifstream in(stats());
  const nlohmann::json json = nlohmann::json::parse(in);
  const uint64_t camera = json.at("camera_rays"), extension = json.at("extension_rays"),
                 shadow = json.at("shadow_rays"), all = json.at("rays");
  EXPECT_EQ(camera + extension + shadow, all);
  EXPECT_EQ(camera, uint64_t(kSize) * kSize * kSpp);
  EXPECT_GT(shadow, camera / 2);
  EXPECT_GT(extension, 0u);
}

TEST_F(CornellRender, NothingElseIsLeftInTheOutputFolder) {
  EXPECT_EQ(files_in(s_dir),
            (std::vector<std::string>{"cornell.exr", "cornell.png", "stats.json"}));
}

// `hipr info` on every scene we ship prints its triangle count.
class InfoOnShippedScene : public testing::TestWithParam<std::string> {};

size_t triangles_in_scene(const Scene& scene) {
  size_t triangles = 0;
  for (const Instance& instance : scene.instances())
    for (const MeshPrimitive& p : scene.meshes[instance.mesh].primitives)
      triangles += p.indices.size() / 3;
  return triangles;
}

TEST_P(InfoOnShippedScene, PrintsTheTriangleCount) {
  const fs::path scene = test::asset(GetParam());
  const test::CommandResult result = test::run_hipr("info " + quoted(scene));
  EXPECT_EQ(result.exit_code, kExitOk) << result.output;
  const std::string expected =
      "triangles  " + std::to_string(triangles_in_scene(load_scene(scene))) + " in the scene";
  EXPECT_NE(result.output.find(expected), std::string::npos) << "no '" << expected << "' in\n"
                                                             << result.output;
}

// `hipr info` lists the kernel features the scene uses, every one it skips, and the rays left out.
TEST(Info, ListsKernelFeaturesSkippedFeaturesAndRays) {
  const auto line = [](const std::string& output, const std::string& key) {
    for (const std::string& l : test::lines_of(output))
      if (l.rfind(key, 0) == 0) return l;
    return std::string();
  };
  const test::CommandResult box = test::run_hipr("info " + quoted(test::asset("cornell_box.gltf")));
  ASSERT_EQ(box.exit_code, kExitOk) << box.output;
  EXPECT_EQ(line(box.output, "bsdf"), "bsdf       diffuse");
  EXPECT_EQ(line(box.output, "kernel"), "kernel     emissive triangles");
  for (const char* skipped : {"specular", "coat", "textures", "normal maps", "punctual lights",
                              "environment", "opacity cutout", "volume absorption"})
    EXPECT_NE(line(box.output, "skipped").find(skipped), std::string::npos) << skipped << "\n"
                                                                            << box.output;
  EXPECT_EQ(line(box.output, "rays"), "rays       every ray is needed");

  // The unlit furnace sphere without the built-in studio: nothing to sample, nothing emits, and
  // the frame's corners are empty.
  const test::CommandResult furnace =
      test::run_hipr("info " + quoted(test::asset("furnace_sphere.gltf")) +
                     " --env none --width 128 --height 128 --tile 16");
  ASSERT_EQ(furnace.exit_code, kExitOk) << furnace.output;
  EXPECT_EQ(line(furnace.output, "kernel"), "kernel     no other feature");
  const std::string rays = line(furnace.output, "rays");
  EXPECT_NE(rays.find("all of them (nothing emits"), std::string::npos) << rays;
  EXPECT_NE(rays.find(" of 64 tiles (background only at 128x128, tile 16)"), std::string::npos)
      << rays;
  const std::string bad_tile = "info " + quoted(test::asset("furnace_sphere.gltf")) + " --tile 0";
  EXPECT_EQ(test::run_hipr(bad_tile).exit_code, kExitBadInput);
}

// A scene that brings no light is lit by the built-in studio unless told otherwise, and says so;
// a black render because nothing emits says so too.
TEST(EnvironmentChoice, UnlitSceneGetsTheStudioAndSaysSo) {
  const std::string scene = quoted(test::asset("furnace_sphere.gltf"));
  const test::CommandResult info = test::run_hipr("info " + scene);
  ASSERT_EQ(info.exit_code, kExitOk) << info.output;
  EXPECT_NE(info.output.find("env        studio (built in)"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("brings no light: lit by the built-in studio"), std::string::npos)
      << info.output;
  const test::CommandResult lit = test::run_hipr("info " + quoted(test::asset("cornell_box.gltf")));
  EXPECT_NE(lit.output.find("env        none"), std::string::npos) << lit.output;

  const auto dir = test::temp_dir("env_choice");
  const std::string size = " --width 16 --height 16 --spp 2 -q";
  const test::CommandResult studio =
      test::run_hipr("render " + scene + " -o " + quoted(dir / "studio.exr") + size);
  ASSERT_EQ(studio.exit_code, kExitOk) << studio.output;
  EXPECT_GT(test::mean(read_image(dir / "studio.exr")), 0.1);

  const test::CommandResult none =
      test::run_hipr("render " + scene + " -o " + quoted(dir / "none.exr") + size + " --env none");
  ASSERT_EQ(none.exit_code, kExitOk) << none.output;
  EXPECT_EQ(test::mean(read_image(dir / "none.exr")), 0.0);
  const std::vector<std::string> lines = test::lines_of(none.output);
  ASSERT_EQ(lines.size(), 1u) << none.output;
  EXPECT_NE(lines[0].find("nothing in the scene emits light"), std::string::npos) << none.output;

  const test::CommandResult sky =
      test::run_hipr("render " + scene + " -o " + quoted(dir / "sky.exr") + size +
                     " --env sky --sun-elevation 20 --turbidity 4");
  ASSERT_EQ(sky.exit_code, kExitOk) << sky.output;
  EXPECT_GT(test::mean(read_image(dir / "sky.exr")), 1000.0);  // daylight, in nits
  for (const char* bad : {" --turbidity 20", " --sun-elevation -5", " --sun-azimuth nan"}) {
    const test::CommandResult result = test::run_hipr(
        "render " + scene + " -o " + quoted(dir / "bad.exr") + size + " --env sky" + bad);
    EXPECT_EQ(result.exit_code, kExitBadInput) << bad;
    EXPECT_EQ(test::lines_of(result.output).size(), 1u) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.exr"));
  }
}

std::string scene_test_name(const testing::TestParamInfo<std::string>& param_info) {
  std::string name = param_info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, InfoOnShippedScene,
                         testing::Values("cornell_box.gltf", "cornell_box_moved.gltf",
                                         "cornell_sphere.glb", "furnace_sphere.gltf"),
                         scene_test_name);

// `hipr replay`: every policy ends in the same final image (bit for bit: the schedule changes
// only the order of samples, never their values), with the step and debug images asked for.
TEST(Replay, PoliciesEndInTheSameFinalImage) {
  const fs::path dir = test::temp_dir("replay");
  const std::string common = quoted(test::asset("cornell_box.gltf")) + " " +
                             quoted(test::asset("cornell_box.edits.json")) +
                             " --width 32 --height 32 --spp 2 --tile 8 --max-depth 4 --validate -q";
  std::vector<float> reference;
  for (const char* policy : {"hipr", "full", "spiral"}) {
    const fs::path out = dir / policy;
    const test::CommandResult result = test::run_hipr("replay " + common + " -o " + quoted(out) +
                                                      " --policy " + policy + " --dump-steps 1,3");
    ASSERT_EQ(result.exit_code, kExitOk) << result.output;
    for (const char* file :
         {"final.exr", "final.png", "edit1_step1.exr", "edit2_step3.png", "summary.json"})
      EXPECT_TRUE(fs::exists(out / file)) << policy << ": " << file;
    const ImageRGB final_image = read_image(out / "final.exr");
    if (reference.empty()) reference = final_image.rgb;
    EXPECT_EQ(final_image.rgb, reference) << policy;
  }
  for (const char* file : {"edit1_objects.png", "edit1_weights.png", "edit1_tiles.png"})
    EXPECT_TRUE(fs::exists(dir / "hipr" / file)) << file;
}

// An edit that switches the environment (studio -> sky with its sun) is re-rendered like any
// other: every policy ends on the full-frame render of the scene loaded with that sky.
TEST(Replay, EnvironmentSwitchEndsOnARenderOfTheNewLight) {
  const fs::path dir = test::temp_dir("replay_env");
  const fs::path script = dir / "sky.json";
  std::ofstream(script) << R"({"edits": [{"op": "environment", "source": "sky",
                                          "set": {"sun_elevation": 25, "intensity": 0.0005}}]})";
  const std::string size = " --width 32 --height 32 --spp 2 --tile 8 --max-depth 4 -q";
  const fs::path rendered = dir / "sky.exr";
  ASSERT_EQ(test::run_hipr("render " + quoted(test::asset("furnace_sphere.gltf")) +
                           " --env sky --sun-elevation 25" + " --env-intensity 0.0005 -o " +
                           quoted(rendered) + size)
                .exit_code,
            kExitOk);
  const ImageRGB expected = read_image(rendered);
  for (const char* policy : {"hipr", "full"}) {
    const fs::path out = dir / policy;
    const test::CommandResult result = test::run_hipr(
        "replay " + quoted(test::asset("furnace_sphere.gltf")) + " " + quoted(script) +
        " --env studio -o " + quoted(out) + " --policy " + policy + size);
    ASSERT_EQ(result.exit_code, kExitOk) << result.output;
    EXPECT_EQ(read_image(out / "final.exr").rgb, expected.rgb) << policy;
  }
}

// Focus ops (docs/method.md#focus) order the re-render of the edits after them and change
// nothing else: hipr with a focus ends on the image every other policy ends on.
TEST(Replay, FocusOpsChangeTheOrderOnly) {
  const fs::path dir = test::temp_dir("replay_focus");
  const fs::path script = dir / "focus.json";
  std::ofstream(script) << R"({"edits": [
      {"op": "focus", "node": "tall_block"},
      {"op": "transform", "node": "short_block", "translate": [0.05, 0, 0]},
      {"op": "focus", "pixel": [20, 8], "radius": 6, "weight": 2},
      {"op": "material", "material": "red", "set": {"base_color": [0.1, 0.2, 0.7]}},
      {"op": "focus", "clear": true}]})";
  const std::string common = quoted(test::asset("cornell_box.gltf")) + " " + quoted(script) +
                             " --width 32 --height 32 --spp 2 --tile 8 --max-depth 4 -q";
  std::vector<float> reference;
  for (const char* policy : {"hipr", "full"}) {
    const fs::path out = dir / policy;
    const test::CommandResult result =
        test::run_hipr("replay " + common + " -o " + quoted(out) + " --policy " + policy);
    ASSERT_EQ(result.exit_code, kExitOk) << result.output;
    const ImageRGB final_image = read_image(out / "final.exr");
    if (reference.empty()) reference = final_image.rgb;
    EXPECT_EQ(final_image.rgb, reference) << policy;
    std::ifstream summary_file(out / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(summary_file);
    ASSERT_EQ(summary.at("edits").size(), 5u);
    EXPECT_EQ(summary["edits"][0].at("focus"), "tall_block");
    EXPECT_EQ(summary["edits"][2].at("focus"), "tall_block; disc (20, 8) r 6 x2");
    EXPECT_EQ(summary["edits"][4].at("focus"), "none");
  }
  const fs::path bad = dir / "bad.json";
  std::ofstream(bad) << R"({"edits": [{"op": "focus", "node": "teapot"}]})";
  const test::CommandResult result =
      test::run_hipr("replay " + quoted(test::asset("cornell_box.gltf")) + " " + quoted(bad) +
                     " -o " + quoted(dir / "x"));
  expect_one_error_line(result);
  EXPECT_NE(result.output.find("teapot"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "x"));
}

// Geometry edits through `hipr replay`: every policy ends on the same image, --save writes a
// validator-clean scene whose render is the edited scene's (a duplicate, a deform, a delete),
// and an import (which saving cannot hold yet) or a path out of the script's folder is bad
// input that writes nothing.
TEST(Replay, GeometryEditsSaveAndRenderAsTheEditedScene) {
  const fs::path dir = test::temp_dir("replay_geometry");
  const fs::path script = dir / "geometry.json";
  std::ofstream(script) << R"({"edits": [
      {"op": "duplicate", "node": "short_block", "as": "short_block_2", "translate": [-0.25, 0, 0.2]},
      {"op": "deform", "node": "tall_block", "matrix": [1,0,0,0, 0,1.3,0,0, 0,0,1,0, 0,0,0,1]},
      {"op": "delete", "node": "short_block"}]})";
  const std::string size = " --width 32 --height 32 --spp 2 --tile 8 --max-depth 4 -q";
  std::vector<float> reference;
  for (const char* policy : {"hipr", "full"}) {
    const fs::path out = dir / policy;
    const test::CommandResult result = test::run_hipr(
        "replay " + quoted(test::asset("cornell_box.gltf")) + " " + quoted(script) + " -o " +
        quoted(out) + " --policy " + policy + " --save " + quoted(out / "edited.gltf") + size);
    ASSERT_EQ(result.exit_code, kExitOk) << result.output;
    const ImageRGB final_image = read_image(out / "final.exr");
    if (reference.empty()) reference = final_image.rgb;
    EXPECT_EQ(final_image.rgb, reference) << policy;
  }
  const fs::path saved = dir / "hipr" / "edited.gltf";
  ASSERT_TRUE(fs::exists(saved));
  const Scene reloaded = load_scene(saved);
  EXPECT_THROW(find_node(reloaded, "short_block"), InputError) << "deleted";
  EXPECT_NO_THROW(find_node(reloaded, "short_block_2"));
  ASSERT_EQ(test::run_hipr("render " + quoted(saved) + " -o " + quoted(dir / "saved.exr") + size)
                .exit_code,
            kExitOk);
  EXPECT_EQ(read_image(dir / "saved.exr").rgb, reference)
      << "the saved scene renders as the edited one";

  // An import of a file beside the script (its meshes, materials and lamp), saved as .glb.
  fs::copy_file(test::asset("cornell_sphere.glb"), dir / "sphere.glb");
  const fs::path import_script = dir / "import.json";
  std::ofstream(import_script)
      << R"({"edits": [{"op": "import", "file": "sphere.glb", "translate": [0.3, 0.1, 0]}]})";
  const std::string import_base =
      "replay " + quoted(test::asset("cornell_box.gltf")) + " " + quoted(import_script);
  ASSERT_EQ(test::run_hipr(import_base + " -o " + quoted(dir / "imported") + " --save " +
                           quoted(dir / "imported.glb") + size)
                .exit_code,
            kExitOk);
  ASSERT_EQ(test::run_hipr("render " + quoted(dir / "imported.glb") + " -o " +
                           quoted(dir / "imported.exr") + size)
                .exit_code,
            kExitOk);
  // Within float rounding rather than bit for bit: the saved file composes the import's
  // translation with the imported nodes' transforms in another order than the edit did, so
  // points on the imported objects sit a rounding apart, and the light tree's probabilities
  // (docs/method.md#many-light-sampling) depend on the shading point.
  const ImageRGB imported = read_image(dir / "imported.exr");
  const ImageRGB replayed = read_image(dir / "imported" / "final.exr");
  ASSERT_EQ(imported.rgb.size(), replayed.rgb.size());
  for (size_t i = 0; i < imported.rgb.size(); ++i)
    ASSERT_NEAR(imported.rgb[i], replayed.rgb[i], 1e-6f * std::max(1.0f, std::abs(replayed.rgb[i])))
        << i;

  // A save the writer refuses (here a format it does not write) is bad input, before any render.
  test::CommandResult result = test::run_hipr(import_base + " -o " + quoted(dir / "no") +
                                              " --save " + quoted(dir / "no.obj") + size);
  expect_one_error_line(result);
  EXPECT_FALSE(fs::exists(dir / "no"));

  const fs::path escape = dir / "escape.json";
  std::ofstream(escape) << R"({"edits": [{"op": "import", "file": "../x.glb"}]})";
  result = test::run_hipr("replay " + quoted(test::asset("cornell_box.gltf")) + " " +
                          quoted(escape) + " -o " + quoted(dir / "esc") + size);
  expect_one_error_line(result);
  EXPECT_FALSE(fs::exists(dir / "esc"));
}

// Edits in a scene without a camera (most real assets) keep the view decided at load: a move
// that grows the scene's bounds (the tall block in front of the box) shows the block moved, and
// the image is what a script that first pinned the view as a camera node (a camera edit of
// nothing) ends on, and what the file --save wrote renders, bit for bit.
TEST(Replay, EditsInASceneWithoutACameraKeepTheView) {
  const fs::path dir = test::temp_dir("replay_camera_less");
  const fs::path scene = test::camera_less_cornell_box(dir);
  const char* move = R"({"op": "transform", "node": "tall_block", "translate": [0, 0, 0.6]})";
  std::ofstream(dir / "move.json") << "{\"edits\": [" << move << "]}";
  std::ofstream(dir / "pinned.json")
      << R"({"edits": [{"op": "camera", "translate": [0, 0, 0]}, )" << move << "]}";
  const std::string size = " --width 32 --height 32 --spp 2 --tile 8 --max-depth 3 --env studio -q";
  for (const char* script : {"move", "pinned"})
    ASSERT_EQ(test::run_hipr("replay " + quoted(scene) + " " +
                             quoted(dir / (std::string(script) + ".json")) + " -o " +
                             quoted(dir / script) + " --save " +
                             quoted(dir / script / "saved.gltf") + size)
                  .exit_code,
              kExitOk);
  ASSERT_EQ(test::run_hipr("render " + quoted(scene) + " -o " + quoted(dir / "unmoved.exr") + size)
                .exit_code,
            kExitOk);
  ASSERT_EQ(test::run_hipr("render " + quoted(dir / "move" / "saved.gltf") + " -o " +
                           quoted(dir / "saved.exr") + size)
                .exit_code,
            kExitOk);
  const ImageRGB moved = read_image(dir / "move" / "final.exr");
  EXPECT_NE(moved.rgb, read_image(dir / "unmoved.exr").rgb) << "the block moved on screen";
  EXPECT_EQ(moved.rgb, read_image(dir / "pinned" / "final.exr").rgb) << "the view did not move";
  EXPECT_EQ(moved.rgb, read_image(dir / "saved.exr").rgb)
      << "the saved file renders as the edit was seen";

  // hipr bench: the edit's reference (the edited scene, converged) is the same image both ways.
  const std::string bench =
      " --width 24 --height 24 --tile 8 --spp 2 --ref-spp 4 --max-depth 3 --env studio "
      "--policies hipr,full --no-ref-cache -q -o ";
  for (const char* script : {"move", "pinned"})
    ASSERT_EQ(test::run_hipr("bench " + quoted(scene) + " " +
                             quoted(dir / (std::string(script) + ".json")) + bench +
                             quoted(dir / (std::string("bench_") + script)))
                  .exit_code,
              kExitOk);
  EXPECT_EQ(read_image(dir / "bench_move" / "edit1_reference.exr").rgb,
            read_image(dir / "bench_pinned" / "edit2_reference.exr").rgb);
}

// Hostile inputs, made by hand once and crashes or memory kills then: each is one line and exit
// 2 under both traversals, and writes nothing. A node whose transform reaches 3e38 (finite, but
// its bounds overflow: the software BVH binned NaN), moves that add up to it, an accessor of two
// billion elements with no data behind it, and an edit script reading a file outside its folder.
TEST(Cli, HostileInputsAreOneLineErrors) {
  const fs::path dir = test::temp_dir("hostile");
  nlohmann::json box;
  std::ifstream(test::asset("cornell_box.gltf")) >> box;
  fs::copy_file(test::asset("cornell_box.bin"), dir / "cornell_box.bin");
  nlohmann::json huge = box;
  for (auto& node : huge["nodes"])
    if (node["name"] == "tall_block") {
      node.erase("translation"), node.erase("rotation"), node.erase("scale");
      node["matrix"] = {3e38, 0, 0, 0, 0, 3e38, 0, 0, 0, 0, 3e38, 0, 3e38, 0, 0, 1};
    }
  std::ofstream(dir / "huge_transform.gltf") << huge.dump();
  nlohmann::json empty_accessor = box;
  empty_accessor["accessors"].push_back(
      {{"componentType", 5126}, {"type", "VEC3"}, {"count", 2000000000}});
  std::ofstream(dir / "empty_accessor.gltf") << empty_accessor.dump();
  std::ofstream(dir / "moves.json") << R"({"edits": [
      {"op": "transform", "node": "tall_block", "translate": [3e38, 0, 0]},
      {"op": "transform", "node": "tall_block", "translate": [3e38, 0, 0]}]})";
  std::ofstream(dir / "environment.json")
      << R"({"edits": [{"op": "environment", "source": "/etc/hostname"}]})";
  const std::string cornell = quoted(test::asset("cornell_box.gltf"));
  const std::string size = " --width 16 --height 16 --spp 1 --tile 8 -q --traversal ";
  for (const char* traversal : {"ray-query", "software"}) {
    const fs::path out = dir / traversal;
    fs::create_directories(out);
    const std::pair<std::string, const char*> commands[] = {
        {"render " + quoted(dir / "huge_transform.gltf") + " -o " + quoted(out / "a.exr"),
         "out of range"},
        {"render " + quoted(dir / "empty_accessor.gltf") + " -o " + quoted(out / "b.exr"),
         "no bufferView"},
        {"replay " + cornell + " " + quoted(dir / "moves.json") + " -o " + quoted(out / "c"),
         "out of range"},
        {"replay " + cornell + " " + quoted(dir / "environment.json") + " -o " + quoted(out / "d"),
         "script's folder"}};
    for (const auto& [command, why] : commands) {
      SCOPED_TRACE(command);
      const test::CommandResult result = test::run_hipr(command + size + traversal);
      expect_one_error_line(result);
      EXPECT_NE(result.output.find(why), std::string::npos) << result.output;
    }
    EXPECT_TRUE(files_in(out).empty()) << "nothing written";
  }
}

TEST(Replay, BadPolicyOrUnknownNameWritesNothing) {
  const fs::path dir = test::temp_dir("replay-bad");
  const fs::path script = dir / "edits.json";
  std::ofstream(script)
      << R"({"edits": [{"op": "transform", "node": "teapot", "translate": [0, 0, 0]}]})";
  const std::string scene = quoted(test::asset("cornell_box.gltf"));
  test::CommandResult result =
      test::run_hipr("replay " + scene + " " + quoted(script) + " -o " + quoted(dir / "a"));
  EXPECT_EQ(result.exit_code, kExitBadInput);
  EXPECT_NE(result.output.find("teapot"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(dir / "a"));
  result = test::run_hipr("replay " + scene + " " + quoted(test::asset("cornell_box.edits.json")) +
                          " -o " + quoted(dir / "b") + " --policy zigzag");
  EXPECT_EQ(result.exit_code, kExitBadInput);
  EXPECT_FALSE(fs::exists(dir / "b"));
}

TEST(Replay, HiprParametersAreValidated) {
  const fs::path dir = test::temp_dir("replay-params");
  const std::string base = "replay " + quoted(test::asset("cornell_box.gltf")) + " " +
                           quoted(test::asset("cornell_box.edits.json")) +
                           " --width 16 --height 16 --spp 1 -q -o ";
  EXPECT_EQ(test::run_hipr(base + quoted(dir / "ok") + " --preset mirror --w-path 2,1,1 --eps 0.02")
                .exit_code,
            kExitOk);
  for (const char* bad : {"--preset shiny", "--w-lobe 1,2", "--w-lobe 0,0,0,0", "--w-path -1,1,1",
                          "--eps 0", "--eps 2", "--w-occlusion -1"}) {
    const test::CommandResult result = test::run_hipr(base + quoted(dir / "bad") + " " + bad);
    EXPECT_EQ(result.exit_code, kExitBadInput) << bad << "\n" << result.output;
    EXPECT_FALSE(fs::exists(dir / "bad")) << bad;
  }
}

// `hipr bench`: the three outputs, every policy ending on the same image, `full` showing the stale
// image for exactly its first pass, references cached, and results that do not depend on the run.
TEST(Bench, WritesCurvesSummaryAndPlot) {
  const fs::path dir = test::temp_dir("bench");
  const std::string command =
      "bench " + quoted(test::asset("cornell_box.gltf")) + " " +
      quoted(test::asset("cornell_box.edits.json")) +
      " --width 24 --height 24 --tile 8 --spp 2 --ref-spp 8 --max-depth 3 -q --ref-cache " +
      quoted(dir / "cache") + " -o ";
  const test::CommandResult result = test::run_hipr(command + quoted(dir / "a"));
  ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  for (const char* file :
       {"curves.csv", "summary.json", "plot.png", "edit1_reference.png", "edit1_reference.exr",
        "edit2_hipr_work0.png", "edit2_hipr_work0.exr", "edit2_hipr_work1.png"})
    EXPECT_TRUE(fs::exists(dir / "a" / file)) << file;
  EXPECT_EQ(files_in(dir / "cache").size(), 3u)
      << "one reference per scene state: before the edits, after each";

  std::ifstream summary_file(dir / "a" / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  ASSERT_EQ(summary.at("edits").size(), 2u);
  for (const auto& edit : summary.at("edits")) {
    // Stage 1's active tiles against those the references say changed.
    EXPECT_LE(edit.at("active_and_changed_tiles").get<size_t>(),
              edit.at("reference_changed_tiles").get<size_t>());
    EXPECT_LE(edit.at("active_and_changed_tiles").get<size_t>(),
              edit.at("changed_tiles").get<size_t>());
    EXPECT_LE(edit.at("reference_changed_tiles").get<size_t>(), edit.at("tiles").get<size_t>());
    const auto& policies = edit.at("policies");
    ASSERT_EQ(policies.size(), 6u);
    const double final_relmse = policies.at("hipr").at("final_relmse");
    for (const auto& [name, p] : policies.items()) {
      for (const char* key : {"auc_relmse", "auc_flip", "first_feedback_work",
                              "changed_tiles_shown_work", "overhead_share"})
        EXPECT_TRUE(p.contains(key)) << name << " " << key;
      EXPECT_TRUE(p.at("converged").get<bool>()) << name;
      EXPECT_EQ(p.at("final_relmse").get<double>(), final_relmse)
          << name << ": every policy ends on the same image";
      EXPECT_EQ(p.at("nonfinite_samples").get<int>(), 0) << name;
    }
    const auto& full = policies.at("full");
    EXPECT_DOUBLE_EQ(full.at("auc_relmse").get<double>(), full.at("stale_relmse").get<double>())
        << "full shows the stale image until its first pass ends, at one work unit";
    EXPECT_DOUBLE_EQ(full.at("first_feedback_work").get<double>(), 1.0);
  }
  for (const char* key : {"hipr_vs_full_auc_relmse", "hipr_vs_oracle_auc_relmse",
                          "hipr_vs_full_auc_flip", "hipr_vs_oracle_auc_flip"})
    EXPECT_GT(summary.at("ratios").at(key).get<double>(), 0.0) << key;

  std::ifstream curves_file(dir / "a" / "curves.csv");
  std::string header;
  std::getline(curves_file, header);
  EXPECT_EQ(header, "edit,policy,step,work,wall_ms,relmse,flip,focus_relmse,focus_flip");

  // Again, with the references from the cache: the same errors (wall times aside).
  ASSERT_EQ(test::run_hipr(command + quoted(dir / "b")).exit_code, kExitOk);
  EXPECT_EQ(files_in(dir / "cache").size(), 3u);
  std::ifstream again_file(dir / "b" / "summary.json");
  const nlohmann::json again = nlohmann::json::parse(again_file);
  for (size_t e = 0; e < 2; ++e)
    for (const auto& [name, p] : summary["edits"][e]["policies"].items())
      for (const char* key : {"auc_relmse", "auc_flip", "auc_relmse_16", "final_relmse"})
        EXPECT_EQ(p.at(key), again["edits"][e]["policies"][name].at(key)) << name << " " << key;
}

}  // namespace
// `hipr bench --drag`: the edits as one drag, measured against the scene as it is at each step;
// every policy still ends on the same image.
TEST(Bench, DragMeasuresDuringAndAfterTheDrag) {
  const fs::path dir = test::temp_dir("bench_drag");
  const test::CommandResult result =
      test::run_hipr("bench " + quoted(test::asset("cornell_box.gltf")) + " " +
                     quoted(test::asset("cornell_box.edits.json")) +
                     " --drag 0.25 --policies hipr,full,oracle --width 24 --height 24 --tile 8 "
                     "--spp 2 --ref-spp 8 --max-depth 3 -q"
                     " --no-ref-cache -o " +
                     quoted(dir));
  ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  std::ifstream summary_file(dir / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  ASSERT_EQ(summary.at("edits").size(), 1u) << "one drag";
  const auto& policies = summary.at("edits")[0].at("policies");
  const double final_relmse = policies.at("hipr").at("final_relmse");
  for (const auto& [name, p] : policies.items()) {
    EXPECT_GE(p.at("drag_work").get<double>(), 0.25)
        << name << ": the second edit comes after 0.25 work";
    for (const char* key : {"auc_relmse_during_drag", "auc_flip_during_drag",
                            "auc_relmse_after_drag", "auc_flip_after_drag"})
      EXPECT_TRUE(p.contains(key)) << name << " " << key;
    EXPECT_TRUE(p.at("converged").get<bool>()) << name;
    EXPECT_EQ(p.at("final_relmse").get<double>(), final_relmse)
        << name << ": every policy ends on the same image";
  }
  EXPECT_GT(summary.at("ratios").at("hipr_vs_full_auc_relmse_during_drag").get<double>(), 0.0);
  EXPECT_EQ(test::run_hipr("bench " + quoted(test::asset("cornell_box.gltf")) + " " +
                           quoted(test::asset("cornell_box.edits.json")) + " --drag -1 -o " +
                           quoted(dir / "bad"))
                .exit_code,
            kExitBadInput);
}

// `hipr bench --cold-start` with a focus: the scene from nothing, then a camera edit, each
// measured for hipr with and without the focus, the focus region's error beside the frame's.
TEST(Bench, ColdStartAndCameraEditWithAFocus) {
  const fs::path dir = test::temp_dir("bench_focus");
  const fs::path script = dir / "focus.json";
  std::ofstream(script) << R"({"edits": [{"op": "focus", "node": "tall_block"},
                                         {"op": "camera", "translate": [0.02, 0, 0]}]})";
  const std::string flags =
      " --policies hipr,full --width 24 --height 24 --tile 8 --spp 2 --ref-spp 8 --max-depth 3 -q"
      " --no-ref-cache";
  const test::CommandResult result =
      test::run_hipr("bench " + quoted(test::asset("cornell_box.gltf")) + " " + quoted(script) +
                     " --cold-start" + flags + " -o " + quoted(dir / "a"));
  ASSERT_EQ(result.exit_code, kExitOk) << result.output;
  std::ifstream summary_file(dir / "a" / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  ASSERT_EQ(summary.at("edits").size(), 2u);
  EXPECT_EQ(summary["edits"][0].at("name"), "cold start");
  EXPECT_EQ(summary["edits"][1].at("name"), "camera");
  for (const auto& edit : summary.at("edits")) {
    const auto& policies = edit.at("policies");
    ASSERT_EQ(policies.size(), 3u);
    const double final_relmse = policies.at("hipr").at("final_relmse");
    for (const char* name : {"hipr", "full", "hipr+focus"}) {
      const auto& p = policies.at(name);
      EXPECT_TRUE(p.at("converged").get<bool>()) << name;
      EXPECT_GE(p.at("auc_focus_relmse").get<double>(), 0.0) << name;
      EXPECT_GE(p.at("auc_focus_flip").get<double>(), 0.0) << name;
      EXPECT_EQ(p.at("final_relmse").get<double>(), final_relmse)
          << name << ": the focus changes the order only";
    }
  }
  EXPECT_GT(summary.at("ratios").at("hipr+focus_vs_hipr_auc_focus_relmse").get<double>(), 0.0);
  EXPECT_GT(summary.at("ratios").at("hipr+focus_vs_hipr_auc_focus_flip").get<double>(), 0.0);
  // A drag measures edits only; a script of focus ops alone measures nothing without --cold-start.
  expect_one_error_line(test::run_hipr("bench " + quoted(test::asset("cornell_box.gltf")) + " " +
                                       quoted(script) + " --drag 0.5" + flags + " -o " +
                                       quoted(dir / "b")));
  const fs::path only_focus = dir / "only.json";
  std::ofstream(only_focus) << R"({"edits": [{"op": "focus", "node": "tall_block"}]})";
  expect_one_error_line(test::run_hipr("bench " + quoted(test::asset("cornell_box.gltf")) + " " +
                                       quoted(only_focus) + flags + " -o " + quoted(dir / "c")));
  EXPECT_FALSE(fs::exists(dir / "b"));
  EXPECT_FALSE(fs::exists(dir / "c"));
}

// ---- hipr compare: for screenshot-regression suites

// A 16 x 12 grey image; `patch` brightens x 4..7, y 2..5 by that much.
ImageRGB grey_image(float patch = 0.0f) {
  ImageRGB image{16, 12, std::vector<float>(16 * 12 * 3, 0.25f)};
  for (uint32_t y = 2; y <= 5; ++y)
    for (uint32_t x = 4; x <= 7; ++x)
      for (int c = 0; c < 3; ++c) image.rgb[(size_t(y) * 16 + x) * 3 + size_t(c)] += patch;
  return image;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// hipr compare DIR/a.exr DIR/b.exr FLAGS --json DIR/r.json
test::CommandResult compare_in(const fs::path& dir, const std::string& flags) {
  return test::run_hipr("compare " + quoted(dir / "a.exr") + " " + quoted(dir / "b.exr") + " " +
                        flags + " --json " + quoted(dir / "r.json"));
}

TEST(Compare, EqualImagesAreTheSame) {
  const fs::path dir = test::temp_dir("compare_same");
  write_image(dir / "a.exr", grey_image());
  write_image(dir / "b.exr", grey_image());
  for (const char* metric : {"flip", "relmse", "rmse", "max"}) {
    const auto result = compare_in(dir, std::string("--metric ") + metric);
    ASSERT_EQ(result.exit_code, kExitOk) << metric << ": " << result.output;
    const nlohmann::json r = read_json(dir / "r.json");
    EXPECT_EQ(r.at("value").get<double>(), 0.0) << metric;
    EXPECT_EQ(r.at("pixels_over").get<int>(), 0) << metric;
    EXPECT_TRUE(r.at("box").is_null()) << metric;
  }
}

TEST(Compare, SaysWhereImagesDiffer) {
  const fs::path dir = test::temp_dir("compare_diff");
  write_image(dir / "a.exr", grey_image(0.5f));
  write_image(dir / "b.exr", grey_image());
  const std::string images = quoted(dir / "a.exr") + " " + quoted(dir / "b.exr");
  const auto result =
      test::run_hipr("compare " + images + " --metric max --threshold 0.1 --json " +
                     quoted(dir / "r.json") + " --heatmap " + quoted(dir / "heat.png"));
  EXPECT_EQ(result.exit_code, kExitDifferent) << result.output;
  const nlohmann::json r = read_json(dir / "r.json");
  EXPECT_NEAR(r.at("value").get<double>(), 0.5, 1e-6);
  EXPECT_EQ(r.at("pixels_over").get<int>(), 16);
  EXPECT_NEAR(r.at("share_over").get<double>(), 16.0 / (16 * 12), 1e-12);
  EXPECT_EQ(r.at("box"), nlohmann::json({4, 2, 7, 5}));
  EXPECT_FALSE(r.at("same").get<bool>());
  const ImageRGB heat = read_image(dir / "heat.png");
  EXPECT_EQ(heat.width, 16u);
  EXPECT_GT(heat.rgb[(3 * 16 + 5) * 3], 0.5f) << "the patch is hot";
  EXPECT_EQ(heat.rgb[0], 0.0f) << "the rest is cold";
  // A threshold above the difference: the same.
  EXPECT_EQ(test::run_hipr("compare " + images + " --metric max --threshold 0.6 -q").exit_code,
            kExitOk);
  // FLIP sees the patch too (its filters spread a difference over neighbouring pixels).
  ASSERT_EQ(
      test::run_hipr("compare " + images + " --threshold 0.01 --json " + quoted(dir / "f.json"))
          .exit_code,
      kExitDifferent);
  const nlohmann::json f = read_json(dir / "f.json");
  EXPECT_GT(f.at("value").get<double>(), 0.01);
  const auto fbox = f.at("box");
  EXPECT_TRUE(fbox[0] <= 4 && fbox[1] <= 2 && fbox[2] >= 7 && fbox[3] >= 5) << fbox;
}

// A few wrong pixels: their mean passes a golden threshold, their 99.9th percentile does not.
TEST(Compare, APercentileCatchesTheWorstPixels) {
  const fs::path dir = test::temp_dir("compare_percentile");
  ImageRGB a{64, 64, std::vector<float>(64 * 64 * 3, 0.25f)};
  const ImageRGB b = a;
  for (const size_t pixel : {100u, 1000u, 2000u, 3000u, 4000u})
    for (size_t c = 0; c < 3; ++c) a.rgb[pixel * 3 + c] = 0.9f;
  write_image(dir / "a.exr", a);
  write_image(dir / "b.exr", b);
  auto result = compare_in(dir, "--metric max --threshold 0.1");
  EXPECT_EQ(result.exit_code, kExitDifferent) << result.output;
  result = compare_in(dir, "--metric relmse --threshold 0.01");
  EXPECT_EQ(result.exit_code, kExitOk) << "the mean lets 5 pixels in 4096 pass: " << result.output;
  result = compare_in(dir, "--metric relmse --percentile 99.9 --threshold 0.01");
  EXPECT_EQ(result.exit_code, kExitDifferent) << result.output;
  EXPECT_NEAR(read_json(dir / "r.json").at("value").get<double>(),
              0.65 * 0.65 / (0.0625 + 0.01) / 2, 1e-5);
  result = compare_in(dir, "--metric relmse --percentile 99");
  EXPECT_EQ(result.exit_code, kExitOk) << "99% of the pixels are equal: " << result.output;
  EXPECT_EQ(read_json(dir / "r.json").at("percentile").get<double>(), 99.0);
  for (const char* bad : {"0", "101", "-5"}) {
    result = compare_in(dir, std::string("--percentile ") + bad);
    EXPECT_EQ(result.exit_code, kExitBadInput) << bad << ": " << result.output;
  }
}

// A NaN is a difference whatever the threshold: a broken render never passes.
TEST(Compare, ANonFiniteValueIsNeverTheSame) {
  const fs::path dir = test::temp_dir("compare_nan");
  ImageRGB broken = grey_image();
  broken.rgb[(5 * 16 + 9) * 3 + 1] = std::nanf("");
  write_image(dir / "a.exr", broken);
  write_image(dir / "b.exr", grey_image());
  for (const char* metric : {"flip", "relmse", "rmse", "max"}) {
    const auto result = compare_in(dir, std::string("--metric ") + metric + " --threshold 1e30");
    EXPECT_EQ(result.exit_code, kExitDifferent) << metric << ": " << result.output;
    const nlohmann::json r = read_json(dir / "r.json");
    EXPECT_EQ(r.at("nonfinite_pixels").get<int>(), 1) << metric;
    EXPECT_EQ(r.at("box"), nlohmann::json({9, 5, 9, 5})) << metric;
  }
}

TEST(Compare, BadInputIsOneLineAndExitTwo) {
  const fs::path dir = test::temp_dir("compare_bad");
  write_image(dir / "a.exr", grey_image());
  ImageRGB wide{20, 12, std::vector<float>(20 * 12 * 3, 0.25f)};
  write_image(dir / "wide.exr", wide);
  for (const std::string& args :
       {quoted(dir / "a.exr") + " " + quoted(dir / "wide.exr"),
        quoted(dir / "a.exr") + " " + quoted(dir / "missing.exr"),
        quoted(dir / "a.exr") + " " + quoted(dir / "a.exr") + " --metric psnr",
        quoted(dir / "a.exr") + " " + quoted(dir / "a.exr") + " --threshold -1"}) {
    const auto result = test::run_hipr("compare " + args + " --json " + quoted(dir / "r.json"));
    EXPECT_EQ(result.exit_code, kExitBadInput) << args << ": " << result.output;
    EXPECT_EQ(lines_of(result.output).size(), 1u) << result.output;
    EXPECT_FALSE(fs::exists(dir / "r.json")) << "nothing written on bad input";
  }
}

// The determinism contract (docs/method.md#determinism): the same build, device, scene,
// settings and seed give bit-identical EXR pixels from two processes.
TEST(Compare, TwoProcessesRenderTheSamePixels) {
  const fs::path dir = test::temp_dir("determinism");
  const std::string render = "render " + quoted(test::asset("cornell_sphere.glb")) +
                             " --width 32 --height 24 --spp 3 --seed 9 --max-depth 5 -q -o ";
  ASSERT_EQ(test::run_hipr(render + quoted(dir / "a.exr")).exit_code, kExitOk);
  ASSERT_EQ(test::run_hipr(render + quoted(dir / "b.exr")).exit_code, kExitOk);
  EXPECT_EQ(read_image(dir / "a.exr").rgb, read_image(dir / "b.exr").rgb);
  EXPECT_EQ(test::run_hipr("compare " + quoted(dir / "a.exr") + " " + quoted(dir / "b.exr") +
                           " --metric max -q")
                .exit_code,
            kExitOk);
}

// --traversal software renders through hipr's own BVH (what a device without ray queries uses),
// says so in the statistics, and gives the same picture as ray queries up to rounding.
TEST(Cli, TraversalIsChosenNamedAndChecked) {
  const fs::path dir = test::temp_dir("traversal");
  const std::string render =
      "render " + quoted(test::asset("cornell_sphere.glb")) +
      " --width 32 --height 24 --spp 4 --seed 3 --max-depth 4 -q --validate -o ";
  if (!test::context().has_ray_queries())
    GTEST_SKIP() << test::context().device_name() << " has no ray queries";
  for (const char* traversal : {"ray-query", "software"}) {
    const fs::path out = dir / (std::string(traversal) + ".exr");
    const fs::path stats = dir / (std::string(traversal) + ".json");
    const auto result = test::run_hipr(render + quoted(out) + " --traversal " + traversal +
                                       " --stats-json " + quoted(stats));
    ASSERT_EQ(result.exit_code, kExitOk) << result.output;
    std::ifstream in(stats);
    EXPECT_EQ(nlohmann::json::parse(in)["traversal"], traversal);
  }
  const ImageRGB queries = read_image(dir / "ray-query.exr"),
                 software = read_image(dir / "software.exr");
  EXPECT_NEAR(test::mean(software), test::mean(queries), 0.02 * test::mean(queries));

  const auto bad_option = test::run_hipr(render + quoted(dir / "x.exr") + " --traversal magic");
  EXPECT_EQ(bad_option.exit_code, kExitBadInput) << bad_option.output;
  EXPECT_EQ(lines_of(bad_option.output).size(), 1u) << bad_option.output;
  const auto bad_environment = test::run_command(
      "HIPR_TRAVERSAL=magic " + quoted(test::hipr_binary()) + " " + render + quoted(dir / "y.exr"));
  EXPECT_EQ(bad_environment.exit_code, kExitBadInput) << bad_environment.output;
  EXPECT_EQ(lines_of(bad_environment.output).size(), 1u) << bad_environment.output;
  EXPECT_FALSE(fs::exists(dir / "x.exr") || fs::exists(dir / "y.exr"));
}

// A name with bytes that are not UTF-8 (and a terminal escape) reaches stderr escaped, on one line.
TEST(Cli, ErrorLinesStayCleanWithBrokenBytes) {
  const fs::path dir = test::temp_dir("broken_bytes");
  const test::CommandResult result = test::run_hipr("render " +
                                                    quoted(dir / ("sc\xff"
                                                                  "ene\x1b"
                                                                  "[31m.gltf")) +
                                                    " -o " + quoted(dir / "out.exr"));
  EXPECT_EQ(result.exit_code, kExitBadInput);
  ASSERT_EQ(lines_of(result.output).size(), 1u) << result.output;
  EXPECT_NE(result.output.find("sc\\xffene\\x1b[31m.gltf"), std::string::npos) << result.output;
  for (char c : result.output)
    EXPECT_TRUE(c == '\n' || static_cast<unsigned char>(c) >= 0x20) << int(c);
}

}  // namespace hipr
