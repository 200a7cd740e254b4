#pragma once
// Progressive path tracing of a scene into a per-pixel accumulation, tile by tile.
// Samples are deterministic per (pixel, sample index, seed): any order of add_samples calls
// that gives every pixel the same count yields bit-identical images.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hipr/scene.h"
#include "image/image_io.h"

namespace hipr {
namespace vk {
class Context;
}

// Which estimators of direct light take part. Only Mis is for production; the others exist so
// tests can show that each estimator alone converges to the same image.
enum class LightSampling { Mis = 0, BsdfOnly = 1, LightOnly = 2 };

// HiPR discovery parameters (the paper's w_lobe, w_path, occlusion priority and epsilon).
// Defaults follow the paper's order: specular and direct ahead of diffuse, indirect and
// caustic trailing.
struct HiprParameters {
  float w_lobe[4] = {0.2f, 0.25f, 0.4f, 0.15f};  // diffuse, glossy, specular, transmission
  float w_path[3] = {0.6f, 0.25f, 0.15f};        // direct, indirect, caustic
  float w_occlusion = 0.5f;
  float depth_epsilon = 0.01f;  // relative to the G-buffer depth
};

struct RenderSettings {
  uint32_t width = 256;
  uint32_t height = 256;
  uint32_t seed = 0;
  uint32_t max_depth = 32;  // scattering events; 0 = emitters seen directly only
  uint32_t tile_size = 16;
  LightSampling light_sampling = LightSampling::Mis;
  // Compile the path-tracing kernel with only the features the scene uses (render/kernel_features.h;
  // false: the uber kernel with every feature, for comparison).
  bool specialize_kernel = true;
  // Tiles whose camera rays cannot hit anything take their samples without ray queries (same
  // values, bit for bit; render/background_tiles.h). false: every camera ray is traced.
  bool skip_background_tiles = true;
  HiprParameters hipr;
};

struct RenderCounters {
  uint64_t rays = 0;
  uint64_t samples = 0;
  uint32_t non_finite_samples = 0;
};

struct GpuSceneInfo;

// How the display follows the accumulation after an edit (shaders/resolve_display.comp):
// Immediate shows every re-rendered pixel at once; Switch keeps a tile's stale radiance until its
// fresh estimate is expected to be closer to the truth; Blend shows the mix of the two with the
// least expected error. All show the fresh estimate alone once it has caught up in samples.
enum class DisplayRule { Immediate = 0, Switch = 1, Blend = 2 };
DisplayRule parse_display_rule(const std::string& name);  // throws InputError
std::string display_rule_name(DisplayRule rule);

// The per-pixel state of a render (accumulation and display), to start several runs from one state.
struct RenderSnapshot {
  std::vector<abi::PixelAccum> accumulation;
  std::vector<abi::DisplayTexel> display;
};

class Renderer {
 public:
  Renderer(const vk::Context& ctx, const Scene& scene, const RenderSettings& settings);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  const RenderSettings& settings() const;
  uint32_t tiles_x() const;
  uint32_t tiles_y() const;
  uint32_t tile_count() const;
  const GpuSceneInfo& scene_info() const;
  // The kernel features (render/kernel_features.h bits) the kernel is compiled with.
  uint32_t kernel_features() const;

  // Adds `samples_per_pixel` samples to every pixel of the listed tiles (ids = y * tiles_x + x)
  // and waits for the GPU.
  void add_samples(std::span<const uint32_t> tiles, uint32_t samples_per_pixel);
  void add_samples_full_frame(uint32_t samples_per_pixel);

  // Brings the GPU scene up to date with `scene` after edits, touching only what `changes`
  // names (material table, TLAS + light tables, light tables, camera). Accumulated samples are
  // kept; callers decide which tiles restart.
  void update_scene(const Scene& scene, const struct ChangeSet& changes);

  // ---- HiPR stages (DESIGN.md). Each records GPU work and waits; none reads results back.
  // Stage 1: G-buffer of the edited scene (the previous one is kept), active tiles where an
  // element of `changes` is visible now or was before, each with a change score. A camera
  // change, a light edit or an environment edit makes every tile active. Returns |A| (the one
  // read-back: stage 2 is split into steps). (Pixels owing a restart are marked separately:
  // mark_all_owed.)
  uint32_t stage1_visibility(const ChangeSet& changes);
  // Stage 2: path-traces the active tiles (restarting them) with discovery on: all of them
  // (after ordering the schedule), or the active tiles among schedule entries [offset, offset + count).
  void stage2_discover(uint32_t samples_per_pixel);
  // With `then_resolve`, the display of those tiles is resolved in the same submission.
  void stage2_discover(uint32_t offset, uint32_t count, uint32_t samples_per_pixel,
                       std::optional<DisplayRule> then_resolve = std::nullopt);
  // Stage 3 order on the GPU: active tiles by change score, then discovered by weight, then by
  // distance to A.
  void build_schedule();
  // A CPU-made order (scanline, spiral, random policies) replaces the schedule.
  void set_schedule(std::span<const uint32_t> order);
  // Every pixel owes a restart (its next visit drops the old samples).
  void mark_all_owed();
  // Renders entries [offset, offset + count) of the schedule; skip_active leaves out tiles
  // stage 2 already rendered.
  void render_schedule(uint32_t offset, uint32_t count, uint32_t samples_per_pixel, bool skip_active,
                       std::optional<DisplayRule> then_resolve = std::nullopt);

  // ---- Display: what the screen shows. Pixels keep their previous radiance until a resolve
  // lets their fresh estimate take over; the render calls above resolve the tiles they rendered
  // when given `then_resolve`. This one resolves every tile, in id order.
  void resolve_display_all(DisplayRule rule);
  // At an edit: what every pixel shows becomes the stale estimate fresh samples are weighed against.
  void capture_stale_display();
  ImageRGB displayed_image() const;

  RenderSnapshot snapshot() const;
  void restore(const RenderSnapshot& snapshot);

  // Read-backs for inspection (debug images, tests); not used on the render path.
  std::vector<uint32_t> gbuffer_instances() const;  // per pixel: instance index or UINT32_MAX
  std::vector<uint32_t> tile_flags() const;
  std::vector<double> tile_weights() const;
  std::vector<uint32_t> schedule() const;
  // What shaders/common/material_inputs.glsl gives the BSDF at a point of a GeometryRecord's
  // triangle (object space, seen from its front).
  abi::MaterialInputsProbe material_inputs_at(uint32_t record, uint32_t primitive, glm::vec2 barycentrics) const;

  ImageRGB image() const;                     // per-pixel mean radiance
  std::vector<uint32_t> sample_counts() const;  // per pixel
  RenderCounters counters() const;
  void reset_counters();  // on the GPU, no read-back
  void reset();

  // ---- For the interactive viewer (src/app/viewer).
  // New discovery weights and depth tolerance; they take effect from the next stage 2 on.
  void set_hipr_parameters(const HiprParameters& parameters);
  // Runs the stage-1 visibility pass for the scene as it is now, leaving the previous
  // G-buffer and the tile flags alone: picking after edits under policies that skip stage 1.
  void refresh_gbuffer();
  // What the G-buffer holds at one pixel (read-back of one texel).
  struct PixelHit {
    uint32_t instance = UINT32_MAX;  // index into Scene::instances(), UINT32_MAX for background
    float depth = 0.0f;              // camera-space depth along the view axis
  };
  PixelHit gbuffer_at(uint32_t x, uint32_t y) const;
  // Per tile: how many of its pixels still show radiance from before the last edit (they owe
  // a restart at their next visit).
  std::vector<uint32_t> owed_tiles() const;
  // Lavapipe (llvmpipe) compiles a kernel when it is first dispatched, and the path-tracing
  // kernels take seconds to a minute on a CPU: left to the first edit, that edit would freeze
  // the viewer. This dispatches the trace kernels (plain and discovery) over every tile with a
  // flag no tile carries, so they compile but render and count nothing, and the schedule sort
  // on its own scratch buffers (the schedule itself is untouched).
  void warm_up_kernels();

 private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

// A stride coprime to `count`, near count * 0.618, for the workgroup scatter mapping.
uint32_t scatter_stride(uint32_t count);

}  // namespace hipr
