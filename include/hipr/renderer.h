#pragma once
// Progressive path tracing of a scene into a per-pixel accumulation, tile by tile, with a
// display apart from it and HiPR's stages. Samples are deterministic per (pixel, sample index,
// seed): any order of renders that gives every pixel the same count yields bit-identical images.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hipr/denoise.h"
#include "hipr/device.h"
#include "hipr/display_rule.h"
#include "hipr/hipr_parameters.h"
#include "hipr/image.h"
#include "hipr/progressive_renderer.h"
#include "hipr/scene.h"
#include "hipr/scene_diff.h"

namespace hipr {
// Which estimators of direct light take part. Only Mis is for production; the others exist so
// tests can show that each estimator alone converges to the same image.
enum class LightSampling { Mis = 0, BsdfOnly = 1, LightOnly = 2 };

// How next-event estimation picks a light. Tree: the lights at finite distance through the
// light tree, by how much each could send the shading point (render/light_tree.h); the
// environment and suns by power. Power: one CDF over every light by its estimated power (the
// selection before the tree, kept for comparison).
enum class LightSelection { Tree = 0, Power = 1 };
const char* light_selection_name(LightSelection selection);                  // "tree", "power"
std::optional<LightSelection> parse_light_selection(std::string_view name);  // nullopt: unknown

// The random numbers of paths. Sobol: Owen-scrambled, shuffled 4D Sobol blocks (lower error
// per sample). Random: independent hashes, the sampler before Sobol, kept for comparison.
enum class Sampler { Sobol = 0, Random = 1 };
const char* sampler_name(Sampler sampler);                    // "sobol", "random"
std::optional<Sampler> parse_sampler(std::string_view name);  // nullopt for an unknown name

struct RenderSettings {
  uint32_t width = 256;
  uint32_t height = 256;
  uint32_t seed = 0;
  uint32_t max_depth = 32;  // scattering events; 0 = emitters seen directly only
  uint32_t tile_size = 16;
  LightSampling light_sampling = LightSampling::Mis;
  Sampler sampler = Sampler::Sobol;
  LightSelection light_selection = LightSelection::Tree;
  // Compile the path-tracing kernel with only the features the scene uses (kernel features;
  // false: the uber kernel with every feature, for comparison).
  bool specialize_kernel = true;
  // Tiles whose camera rays cannot hit anything take their samples without ray queries (same
  // values, bit for bit). false: every camera ray is traced.
  bool skip_background_tiles = true;
  // Some drivers (lavapipe) compile a kernel at its first dispatch, which takes seconds on a
  // CPU. true: every kernel is dispatched once over no tile as soon as it is made, so no later
  // step (the first edit in the viewer, a timed benchmark step) pays for a compilation.
  bool compile_kernels_early = false;
  // Light groups kept apart in the film (at most abi::kMaxLightGroups = 8; 0: none), so that an
  // edit of an emitter's intensity or colour relights the converged image at once (HiPR policy).
  // Costs 24 bytes per pixel and group; radiance is the same bit for bit with or without.
  uint32_t light_groups = 8;
  // Keep each pixel's first samples (64 bytes per pixel), so that after an edit the display can
  // show the converged image plus the change, estimated with the same random numbers
  // (DisplayRule::Difference). Radiance is the same bit for bit with or without.
  bool difference_estimate = true;
  // Path guiding (docs/method.md#path-guiding): at every scene state (load, each edit) a
  // training pass of `guide_training_spp` paths per pixel learns where light comes from, per
  // cell of a grid over the scene; paths then sample directions from it in MIS with the BSDF.
  // The training depends on the scene state and the seed alone, so every schedule still ends on
  // the same image. false: BSDF sampling alone (the kernels and images as without it).
  bool guiding = false;
  uint32_t guide_training_spp = 4;
  HiprParameters hipr;
};

struct RenderCounters {
  uint64_t rays = 0;  // every ray traced: camera_rays + shadow_rays + the paths' later segments
  uint64_t samples = 0;
  uint32_t non_finite_samples = 0;
  uint64_t camera_rays = 0;  // a path's first segment (skipped where the camera sees nothing)
  uint64_t shadow_rays = 0;  // toward a light sample (next-event estimation)
  uint64_t guide_rays = 0;   // traced by the path guide's training (not in `rays`)
};

// What the path guide (RenderSettings::guiding) has cost so far; zeros without one.
struct GuideCost {
  uint32_t trainings = 0;         // one per scene state samples were added to
  double training_seconds = 0.0;  // their wall time, the device's work waited for
  uint64_t bytes = 0;             // the guide and its training sums, on the device
};

// How far the film's image still is from its converged limit, as its own samples tell
// (Renderer::noise): what a noise target stops rendering at.
struct FilmNoise {
  // The expected relMSE (src/image/error_metrics.h) of each pixel's mean against the mean of
  // infinitely many samples, from the pixel's sample variance, averaged over the pixels whose
  // noise can be told. Like any sample variance it underestimates paths too rare to have been
  // sampled yet (fireflies still to come).
  double relmse = 0.0;
  uint64_t unknown_pixels = 0;  // owed (still holding samples from before an edit) or < 2 samples
  uint64_t pixels = 0;

  // Every pixel's noise is known and the estimate is at most `target`.
  bool within(double target) const { return unknown_pixels == 0 && relmse <= target; }
};

// What the renderer holds of the scene.
struct SceneStats {
  size_t instance_count = 0;
  size_t triangle_count = 0;  // over all visible instances
  size_t light_count = 0;  // entries of the light table (emissive triangles, lights, environment)
  size_t cutout_geometries = 0;  // geometries that need an alpha test (not marked opaque)
  float scene_radius = 1.0f;
  // The mesh acceleration structures the last update_scene built (a new, deformed or re-cut
  // mesh each), and the time they took, device wait included.
  uint32_t blas_builds = 0;
  double blas_build_seconds = 0.0;
};

class Renderer final : public ProgressiveRenderer {
 public:
  Renderer(const Device& device, const Scene& scene, const RenderSettings& settings);
  ~Renderer() override;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  const RenderSettings& settings() const;
  uint32_t tiles_x() const;
  uint32_t tiles_y() const;
  uint32_t tile_count() const;
  TileGrid tile_grid() const override;
  SceneStats scene_stats() const;
  // The kernel features (bits of the HIPR_FEATURE_* table) the kernels are compiled with.
  uint32_t kernel_features() const;

  // ---- Progressive tracing
  // Adds `samples_per_pixel` samples to every pixel of the listed tiles (ids = y * tiles_x + x)
  // and waits for the GPU.
  void add_samples(std::span<const uint32_t> tiles, uint32_t samples_per_pixel);
  void add_samples_full_frame(uint32_t samples_per_pixel);
  void update_scene(const Scene& scene, const ChangeSet& changes) override;
  void set_schedule(std::span<const uint32_t> order) override;
  void render_schedule(uint32_t offset, uint32_t count, uint32_t samples_per_pixel,
                       bool skip_active,
                       std::optional<DisplayRule> then_resolve = std::nullopt) override;
  void render_lead(uint32_t offset, uint32_t count,
                   std::optional<DisplayRule> then_resolve = std::nullopt) override;
  void mark_all_owed() override;
  void set_sample_target(uint32_t target, uint32_t focus_target = 0,
                         uint32_t lead_target = 0) override;
  std::pair<uint32_t, uint32_t> sample_count_range() const override;  // reads the accumulation back
  ImageRGB image() const;                                             // per-pixel mean radiance
  std::vector<uint32_t> sample_counts() const;                        // per pixel
  uint64_t total_samples() const;  // their sum, added up on the GPU (8 bytes read back)
  // The accumulation's noise, estimated on the GPU (8 bytes per 64 pixels read back).
  FilmNoise noise() const;
  RenderCounters counters() const;
  GuideCost guide_cost() const;
  uint64_t samples_since_reset() const override { return counters().samples; }
  void reset_counters() override;  // on the GPU, no read-back
  void reset();

  // ---- Display (what the screen shows)
  void resolve_display_all(DisplayRule rule) override;
  void capture_stale_display() override;
  ImageRGB displayed_image() const override;
  // What the display shows, denoised by `settings` (enabled or not: disabled, or strength 0,
  // gives displayed_image() as it is). The display and the accumulation are left unchanged.
  ImageRGB denoised_image(const DenoiseSettings& settings);
  // The filter alone, its result left on the device (what a frame of the viewer pays for it);
  // the device's own time of it where its queue has timestamps.
  std::optional<DenoiseGpuSeconds> run_denoiser(const DenoiseSettings& settings);
  bool relight(const std::vector<EmitterScale>& scales) override;

  // ---- The device state (methods attach their passes to it: HiPR's stages; the library's
  // read-backs, snapshots and the viewer's sources read it: src/render/render_readback.h,
  // render_snapshot.h, viewer_sources.h)
  RenderState* render_state() override;  // never null
  const RenderState& state() const;
  void refresh_gbuffer() override;
  // New discovery weights and depth tolerance; they take effect from the next stage 2 on.
  void set_hipr_parameters(const HiprParameters& parameters);

  // ---- Picking and light groups
  std::vector<uint32_t> gbuffer_instances() const;  // per pixel: instance index or UINT32_MAX
  struct PixelHit {
    uint32_t instance = UINT32_MAX;  // index into Scene::instances(), UINT32_MAX for background
    float depth = 0.0f;              // camera-space depth along the view axis
  };
  PixelHit gbuffer_at(uint32_t x, uint32_t y) const;  // one texel read back
  // The light groups (names, in group order; emitters over the budget are pooled) and one group's
  // share of image().
  std::vector<std::string> light_group_names() const;
  std::vector<std::string> pooled_emitters() const;
  ImageRGB light_group_image(uint32_t group) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

}  // namespace hipr
