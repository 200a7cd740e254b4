// `hipr render SCENE -o OUT.exr|.png [--denoise [--raw-output RAW]] [--stats-json FILE]`
#include <nlohmann/json.hpp>

#include <algorithm>
#include <optional>
#include <vector>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/denoise_flags.h"
#include "app/display_flags.h"
#include "app/progress.h"
#include "core/error.h"
#include "core/file_util.h"
#include "core/log.h"
#include "core/memory_usage.h"
#include "core/timer.h"
#include "image/builtin_environments.h"
#include "image/image_io.h"
#include "render/gpu_scene.h"
#include "vk/buffer.h"

namespace hipr::app {
namespace {

struct RenderOptions {
  CommonOptions common;
  std::vector<std::filesystem::path> outputs;
  std::vector<std::filesystem::path> raw_outputs;  // the accumulation, where -o is denoised
  std::filesystem::path stats_json;
  DisplayFlags display;
  DenoiseSettings denoise;
  // Filter after every sample, each frame keeping part of the last (DenoiseSettings::history):
  // what a viewer converging a sample a frame shows.
  bool denoise_frames = false;
};

// The filter alone, run `runs` times: the median wall time of each run (submission and wait
// included) and the run of median device time (GPU timestamps), where the device has them.
struct FilterCost {
  double wall_seconds = 0.0;
  std::optional<DenoiseGpuSeconds> gpu;
};

FilterCost median_filter_cost(Renderer& renderer, const DenoiseSettings& settings, int runs) {
  std::vector<double> wall;
  std::vector<DenoiseGpuSeconds> gpu;
  for (int i = 0; i < runs; ++i) {
    const Timer timer;
    const std::optional<DenoiseGpuSeconds> device = renderer.run_denoiser(settings);
    wall.push_back(timer.seconds());
    if (device) gpu.push_back(*device);
  }
  FilterCost cost;
  std::nth_element(wall.begin(), wall.begin() + runs / 2, wall.end());
  cost.wall_seconds = wall[runs / 2];
  if (!gpu.empty()) {
    const auto by_total = [](const DenoiseGpuSeconds& a, const DenoiseGpuSeconds& b) {
      return a.total() < b.total();
    };
    std::nth_element(gpu.begin(), gpu.begin() + gpu.size() / 2, gpu.end(), by_total);
    cost.gpu = gpu[gpu.size() / 2];
  }
  return cost;
}

nlohmann::json gpu_seconds_json(const std::optional<DenoiseGpuSeconds>& gpu) {
  if (!gpu) return nullptr;
  return {{"total", gpu->total()},
          {"prepare", gpu->prepare},
          {"atrous", gpu->atrous},
          {"blend", gpu->blend},
          {"temporal", gpu->temporal}};
}

int run_render(RenderOptions& o) {
  validate_common_options(o.common);
  log::set_quiet(o.common.quiet);
  // Every output is checked before the render starts: a bad path must not cost a render, and
  // an error exit must not leave some of the outputs written.
  const auto check_folder = [](const std::filesystem::path& file) {
    const auto folder = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(folder))
      throw InputError("output folder does not exist: " + folder.string());
  };
  if (!o.raw_outputs.empty() && !o.denoise.enabled)
    throw InputError("--raw-output needs --denoise (without it -o writes the raw image)");
  if (o.denoise_frames && !o.denoise.enabled) throw InputError("--denoise-frames needs --denoise");
  std::vector<std::filesystem::path> all_outputs = o.outputs;
  all_outputs.insert(all_outputs.end(), o.raw_outputs.begin(), o.raw_outputs.end());
  for (const auto& output : all_outputs) {
    if (!is_supported_output(output))
      throw InputError("output " + output.string() + ": unsupported format (use .exr or .png)");
    check_folder(output);
  }
  if (!o.stats_json.empty()) check_folder(o.stats_json);
  const Timer load_timer;
  const Scene scene = load_scene(o.common.scene, o.common.load);
  const double load_seconds = load_timer.seconds();

  const Timer setup_timer;
  const vk::Context ctx(context_options(o.common));
  // A render is never edited: by default no light groups to relight with and no samples kept
  // for difference estimates (the pixels are the same bits either way).
  RenderSettings settings = o.common.render;
  if (o.common.light_groups < 0) settings.light_groups = 0;
  settings.difference_estimate = false;
  Renderer renderer(ctx, scene, settings);
  const double setup_seconds = setup_timer.seconds();
  log::info("rendering " + o.common.scene.filename().string() + " on " + ctx.device_name() + " (" +
            ctx.traversal_name() + " traversal, " +
            std::to_string(renderer.scene_stats().triangle_count) + " triangles, " +
            std::to_string(renderer.scene_stats().light_count) + " lights, environment " +
            environment_description(scene) + ")");

  // Batches grow until one submission takes ~0.25 s: few submissions, steady progress.
  const Timer timer;
  const CpuTimer cpu_timer;
  ProgressBar progress(o.common.spp, !o.common.quiet);
  uint32_t done = 0, batch = 1;
  // --denoise-frames: the filter of every frame, kept out of the render's own times (and of
  // its samples and rays per second).
  double frames_denoise_seconds = 0.0, frames_denoise_cpu_seconds = 0.0;
  while (done < o.common.spp) {
    const uint32_t now = o.denoise_frames ? 1 : std::min(batch, o.common.spp - done);
    const Timer batch_timer;
    renderer.add_samples_full_frame(now);
    if (o.denoise_frames) {
      const Timer frame_timer;
      const CpuTimer frame_cpu_timer;
      renderer.resolve_display_all(DisplayRule::Immediate);
      renderer.run_denoiser(o.denoise);
      frames_denoise_seconds += frame_timer.seconds();
      frames_denoise_cpu_seconds += frame_cpu_timer.seconds();
    }
    done += now;
    progress.update(done, timer.seconds());
    const double seconds = batch_timer.seconds();
    if (seconds < 0.25) batch = std::min<uint32_t>(batch * 2, 256);
  }
  const double render_seconds = timer.seconds() - frames_denoise_seconds;
  const double render_cpu_seconds = cpu_timer.seconds() - frames_denoise_cpu_seconds;
  progress.finish();

  const ImageRGB raw = renderer.image();
  // The denoised image is a copy made from the display: the accumulation stays as rendered.
  ImageRGB denoised;
  double denoise_first_seconds = 0.0, denoise_seconds = 0.0;
  FilterCost filter_cost;
  if (o.denoise.enabled) {
    renderer.resolve_display_all(DisplayRule::Immediate);
    const Timer first_timer;
    denoised = renderer.denoised_image(o.denoise);
    denoise_first_seconds = first_timer.seconds();
    if (!o.stats_json.empty()) {  // again, its kernels compiled: what each later filter costs
      const Timer again_timer;
      denoised = renderer.denoised_image(o.denoise);
      denoise_seconds = again_timer.seconds();
      filter_cost = median_filter_cost(renderer, o.denoise, 5);
    }
  }
  const ImageRGB& image = o.denoise.enabled ? denoised : raw;
  const RenderCounters counters = renderer.counters();
  const GuideCost guide = renderer.guide_cost();
  check_validation(ctx);
  if (counters.non_finite_samples > 0)
    log::warn(std::to_string(counters.non_finite_samples) + " non-finite samples were dropped");

  const ImageMetadata metadata = {
      {"hipr:spp", std::to_string(o.common.spp)},
      {"hipr:seed", std::to_string(o.common.render.seed)},
      {"hipr:sampler", sampler_name(o.common.render.sampler)},
      {"hipr:light_selection", light_selection_name(o.common.render.light_selection)},
      {"hipr:guiding", o.common.render.guiding
                           ? std::to_string(o.common.render.guide_training_spp) + " training spp"
                           : "off"},
      {"hipr:scene_hash", scene.content_hash},
      {"hipr:render_seconds", std::to_string(render_seconds)},
      {"hipr:max_depth", std::to_string(o.common.render.max_depth)},
      {"Software", "hipr"},
  };
  ImageMetadata denoised_metadata = metadata;
  denoised_metadata.emplace_back("hipr:denoised", "strength " + std::to_string(o.denoise.strength) +
                                                      ", " + std::to_string(o.denoise.passes) +
                                                      " passes");
  // Both images share the raw image's exposure, so the two compare as they are.
  const DisplayTransform display = display_transform(o.display, raw);
  if (!o.display.exposure_ev)
    log::info("metered exposure " + std::to_string(display.exposure_ev) + " EV");
  for (const auto& output : o.outputs)
    write_image(output, image, o.denoise.enabled ? denoised_metadata : metadata, display);
  for (const auto& output : o.raw_outputs) write_image(output, raw, metadata, display);

  const double pixels = double(o.common.render.width) * o.common.render.height;
  const double samples = pixels * o.common.spp;
  if (!o.stats_json.empty()) {
    nlohmann::json stats = {
        {"render_seconds", render_seconds},
        {"render_cpu_seconds", render_cpu_seconds},  // all threads: robust to a busy machine
        {"load_seconds", load_seconds},
        // --denoise: the filter and its read-back, the first time (its kernels compiled then,
        // its guides traced) and again (what each later image costs); 0 without.
        {"denoise_first_seconds", denoise_first_seconds},
        {"denoise_seconds", denoise_seconds},
        // --denoise-frames: the filters of every frame together (the display resolve's
        // included), outside render_seconds; 0 without.
        {"denoise_frames_seconds", frames_denoise_seconds},
        // The filter alone, as a viewer's frame pays it: no read-back (median of 5, each waited
        // for: a submission's own overhead included).
        {"denoise_filter_seconds", filter_cost.wall_seconds},
        // The same runs as the device timed them (its timestamps; the run of median total, by
        // kernel); null where the device has no timestamps or without --denoise.
        {"denoise_filter_gpu_seconds", gpu_seconds_json(filter_cost.gpu)},
        {"setup_seconds", setup_seconds},
        // Of the set-up: building the meshes' acceleration structures, device wait included.
        {"blas_build_seconds", renderer.scene_stats().blas_build_seconds},
        {"device_bytes", vk::device_bytes_in_use()},  // every buffer and image hipr allocated
        {"peak_resident_bytes", peak_resident_bytes()},
        {"samples_per_second", samples / render_seconds},
        {"rays_per_second", double(counters.rays) / render_seconds},
        {"nonfinite_samples", counters.non_finite_samples},
        // The image's expected relMSE against its converged limit, from its own sample
        // variances (FilmNoise): what the viewer's noise target stops at.
        {"noise_relmse", renderer.noise().relmse},
        {"spp", o.common.spp},
        {"width", o.common.render.width},
        {"height", o.common.render.height},
        {"rays", counters.rays},
        {"rays_per_sample", double(counters.rays) / samples},
        // By kind (the throughput work of issue 41): extension rays are a path's later segments.
        {"camera_rays", counters.camera_rays},
        {"extension_rays", counters.rays - counters.camera_rays - counters.shadow_rays},
        {"shadow_rays", counters.shadow_rays},
        {"guide_rays", counters.guide_rays},  // the guide's training (not in `rays`)
        {"guide_trainings", guide.trainings},
        {"guide_training_seconds", guide.training_seconds},  // inside render_seconds
        {"guide_bytes", guide.bytes},
        {"device", ctx.device_name()},
        {"traversal", ctx.traversal_name()},
        {"scene_hash", scene.content_hash},
        {"triangles", renderer.scene_stats().triangle_count},
        {"tile", o.common.render.tile_size},
        {"max_depth", o.common.render.max_depth},
        {"sampler", sampler_name(o.common.render.sampler)},
        {"light_selection", light_selection_name(o.common.render.light_selection)},
        {"guiding", o.common.render.guiding},
        {"guide_training_spp", o.common.render.guide_training_spp},
    };
    write_text_atomically(o.stats_json, stats.dump(2) + "\n");
  }
  log::info("wrote " + o.outputs.front().string() + (o.outputs.size() > 1 ? " (and more)" : "") +
            ": " + std::to_string(o.common.spp) + " spp in " + std::to_string(render_seconds) +
            " s (" + std::to_string(samples / render_seconds / 1e6) + " M samples/s, " +
            std::to_string(double(counters.rays) / render_seconds / 1e6) + " M rays/s)");
  return kExitOk;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd =
      app.add_subcommand("render", "Render a glTF scene to an EXR (linear) or PNG (sRGB) image");
  cmd->add_option("scene", options->common.scene, "Scene file (.gltf or .glb)")->required();
  cmd->add_option("-o,--output", options->outputs,
                  "Output image (.exr linear or .png sRGB); repeat for several")
      ->required()
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--raw-output", options->raw_outputs,
                  "With --denoise: also write the image as rendered (.exr or .png); repeat for "
                  "several")
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--stats-json", options->stats_json, "Write render statistics as JSON");
  add_denoise_flags(*cmd, options->denoise);
  cmd->add_flag("--denoise-frames", options->denoise_frames,
                "With --denoise: filter after every sample, as a viewer converging a sample a "
                "frame shows it (each frame keeps part of the last: --denoise-history); -o "
                "writes the last frame");
  add_display_flags(*cmd, options->display, "PNG output");
  add_common_options(*cmd, options->common);
  return {cmd, [options] { return run_render(*options); }};
}

}  // namespace hipr::app
