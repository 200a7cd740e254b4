// The engine: wires the passes that share one render's state. Each pass owns its kernel and
// its own bindings (shaders/shared/bindings/); the scene's set is GpuScene's.
#include "hipr/renderer.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "render/background_tiles.h"
#include "render/frame_params.h"
#include "render/kernel_features.h"
#include "render/render_state.h"

namespace hipr {

const char* sampler_name(Sampler sampler) {
  return sampler == Sampler::Random ? "random" : "sobol";
}

std::optional<Sampler> parse_sampler(std::string_view name) {
  if (name == "sobol") return Sampler::Sobol;
  if (name == "random") return Sampler::Random;
  return std::nullopt;
}

const char* light_selection_name(LightSelection selection) {
  return selection == LightSelection::Power ? "power" : "tree";
}

std::optional<LightSelection> parse_light_selection(std::string_view name) {
  if (name == "tree") return LightSelection::Tree;
  if (name == "power") return LightSelection::Power;
  return std::nullopt;
}

struct Renderer::Impl : RenderState {
  Impl(const vk::Context& c, const Scene& scene, const RenderSettings& s)
      : RenderState(c, scene, s), background(scene) {
    layout_seen = gpu.layout_generation();
    overlay_records_seen = gpu.records_generation();
    update_background(scene);
    gpu.set_frame(make_frame_params(scene, gpu, settings));
    warm_up_trace();
  }

  // An edit that brings in a feature the kernels lack (a material that becomes emissive,
  // transmissive or cut out, a light...) recompiles them with it (features are only ever added,
  // so editing back and forth compiles once). Accumulation, schedule and G-buffers are buffers,
  // untouched.
  void ensure_features(const Scene& scene) {
    if (!settings.specialize_kernel) return;
    const uint32_t needed = hipr::kernel_features(scene);
    if ((needed & ~features) == 0) return;
    features |= needed;
    trace.set_features(features);
    if (guide) guide->set_features(features);
    warm_up_trace();
    if (extension) extension->kernel_features_changed(features);
  }

  // An edit that replaced buffers the passes bind beside the scene's set (GpuScene::
  // layout_generation): bind them again; one that added or removed instances: the overlay's
  // records follow.
  void rebind_if_replaced() {
    if (overlays && gpu.records_generation() != overlay_records_seen) overlays->update_records(gpu);
    overlay_records_seen = gpu.records_generation();
    if (gpu.layout_generation() == layout_seen) return;
    layout_seen = gpu.layout_generation();
    trace.rebind();
    if (guide) guide->rebind();
    if (extension) extension->scene_buffers_replaced();
  }

  // Which tiles' camera rays cannot hit anything, for the scene's camera and instances.
  void update_background(const Scene& scene) {
    tiles.set_background(
        settings.skip_background_tiles
            ? background.mask(scene, settings.width, settings.height, settings.tile_size)
            : std::vector<uint32_t>(tiles.count(), 0u));
  }

  BackgroundTiles background;
  uint64_t layout_seen = 0;  // GpuScene::layout_generation the passes are bound to
};

Renderer::Renderer(const Device& device, const Scene& scene, const RenderSettings& settings) {
  const auto* ctx = dynamic_cast<const vk::Context*>(&device);
  if (!ctx) throw InternalError("a device that is not hipr's (open_device makes one)");
  if (settings.width == 0 || settings.height == 0 || settings.width > 16384 ||
      settings.height > 16384)
    throw InputError("image size must be between 1x1 and 16384x16384");
  if (settings.tile_size < 1 || settings.tile_size > 256)
    throw InputError("tile size must be between 1 and 256");
  m = std::make_unique<Impl>(*ctx, scene, settings);
}

Renderer::~Renderer() = default;

const RenderSettings& Renderer::settings() const { return m->settings; }
uint32_t Renderer::tiles_x() const { return m->tiles.tiles_x(); }
uint32_t Renderer::tiles_y() const { return m->tiles.tiles_y(); }
uint32_t Renderer::tile_count() const { return m->tiles.count(); }
TileGrid Renderer::tile_grid() const {
  const RenderSettings& s = m->settings;
  return {s.width, s.height, s.tile_size, tiles_x(), tiles_y(), s.seed};
}
SceneStats Renderer::scene_stats() const { return m->gpu.info(); }
uint32_t Renderer::kernel_features() const { return m->features; }

void Renderer::add_samples(std::span<const uint32_t> tiles, uint32_t samples_per_pixel) {
  if (tiles.empty() || samples_per_pixel == 0) return;
  for (uint32_t t : tiles)
    if (t >= tile_count()) throw InternalError("tile id out of range");
  m->tiles.schedule.upload(tiles.data(), tiles.size_bytes());
  m->ensure_guide();
  const abi::TracePush push = m->trace.push(0, uint32_t(tiles.size()), samples_per_pixel);
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) { m->trace.record(cmd, push); });
}

void Renderer::add_samples_full_frame(uint32_t samples_per_pixel) {
  add_samples(m->tiles.all(), samples_per_pixel);
}

void Renderer::update_scene(const Scene& scene, const ChangeSet& changes) {
  m->gpu.reset_build_stats();
  if (changes.geometry) {
    m->gpu.update_geometry(scene);  // includes materials, instances and light tables
    m->background.update_meshes(scene);
  } else if (changes.materials) {
    m->gpu.update_materials(scene);
  }
  m->ensure_features(scene);  // materials, lights, imports: anything may bring in a feature
  if (changes.environment_map) m->gpu.update_environment(scene);  // its light entry follows below
  if (changes.transforms && !changes.geometry)
    m->gpu.update_instances(scene);  // includes the light tables
  else if (changes.light_tables && !changes.geometry)
    m->gpu.update_lights(scene);
  if (changes.transforms || changes.geometry || changes.camera) m->update_background(scene);
  m->rebind_if_replaced();
  if (!changes.empty()) {
    m->gbuffers.set_stale();
    if (m->denoiser) m->denoiser->set_guides_stale();
  }
  m->gpu.set_frame(make_frame_params(scene, m->gpu, m->settings));
  // A new scene state gets its own guide before any of its samples (every schedule then renders
  // it with the same one).
  if (!changes.empty()) m->guide_stale = true;
}

void Renderer::set_schedule(std::span<const uint32_t> order) { m->tiles.set_schedule(order); }

void Renderer::render_schedule(uint32_t offset, uint32_t count, uint32_t samples_per_pixel,
                               bool skip_active, std::optional<DisplayRule> then_resolve) {
  m->trace_entries(m->trace, offset, count, samples_per_pixel, 0u,
                   skip_active ? abi::kTileActive : 0u, then_resolve);
}

void Renderer::render_lead(uint32_t offset, uint32_t count,
                           std::optional<DisplayRule> then_resolve) {
  if (m->sample_target.focus == 0 && m->sample_target.lead == 0) return;
  m->trace_entries(m->trace, offset, count, 1, abi::kTileLead, 0u, then_resolve);
}

void Renderer::set_sample_target(uint32_t target, uint32_t focus_target, uint32_t lead_target) {
  m->sample_target = {target, focus_target, lead_target};
}

std::pair<uint32_t, uint32_t> Renderer::sample_count_range() const {
  const auto accum = m->film.accumulation.download_all<abi::PixelAccum>();  // one read-back
  uint32_t fewest = UINT32_MAX, most = 0;
  for (const abi::PixelAccum& pixel : accum) {
    const uint32_t count = (pixel.count & abi::kPixelOwed) ? 0 : pixel.count & abi::kPixelCountMask;
    fewest = std::min(fewest, count);
    most = std::max(most, count);
  }
  return {accum.empty() ? 0 : fewest, most};
}

void Renderer::mark_all_owed() {
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) { m->film.record_mark_all_owed(cmd); });
}

ImageRGB Renderer::image() const { return m->film.image(); }
std::vector<uint32_t> Renderer::sample_counts() const { return m->film.sample_counts(); }
uint64_t Renderer::total_samples() const { return m->film.total_samples(); }
FilmNoise Renderer::noise() const { return m->film.noise(); }
RenderCounters Renderer::counters() const { return m->film.counters(); }

GuideCost Renderer::guide_cost() const {
  GuideCost cost = m->guide_cost;
  if (m->guide) cost.bytes = m->gpu.guide.size() + m->gpu.guide_counts.size();
  return cost;
}
void Renderer::reset_counters() { m->film.reset_counters(); }

void Renderer::reset() {
  m->film.clear();
  m->resolve.clear();
  m->relight.clear();
}

bool Renderer::relight(const std::vector<EmitterScale>& scales) {
  if (scales.empty()) return false;
  const std::optional<std::vector<glm::vec3>> factors = m->gpu.light_groups().factors(scales);
  if (!factors) return false;
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) { m->relight.record(cmd, *factors); });
  return true;
}

void Renderer::resolve_display_all(DisplayRule rule) {
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    m->resolve.record(cmd, {abi::kInvalidIndex, tile_count()}, rule);
  });
}

void Renderer::capture_stale_display() {
  m->ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) { m->resolve.record_capture_stale(cmd, tile_count()); });
}

ImageRGB Renderer::displayed_image() const { return m->resolve.displayed_image(); }

ImageRGB Renderer::denoised_image(const DenoiseSettings& settings) {
  run_denoiser(settings);
  return m->denoise_pass().result_image();
}

std::optional<DenoiseGpuSeconds> Renderer::run_denoiser(const DenoiseSettings& settings) {
  return m->denoise_pass().run(settings);
}

RenderState* Renderer::render_state() { return m.get(); }
const RenderState& Renderer::state() const { return *m; }

void Renderer::refresh_gbuffer() { m->gbuffers.render(); }

void Renderer::set_hipr_parameters(const HiprParameters& parameters) {
  m->settings.hipr = parameters;
  abi::FrameParams frame = m->gpu.frame();
  set_discovery_parameters(frame, parameters);
  m->gpu.set_frame(frame);
}

std::vector<uint32_t> Renderer::gbuffer_instances() const {
  const auto texels = m->rendered_gbuffers().current.download_all<abi::GBufferTexel>();
  std::vector<uint32_t> out(texels.size(), UINT32_MAX);
  for (size_t i = 0; i < texels.size(); ++i)
    if (texels[i].record != abi::kInvalidIndex) out[i] = m->gpu.record_instance()[texels[i].record];
  return out;
}

Renderer::PixelHit Renderer::gbuffer_at(uint32_t x, uint32_t y) const {
  const GBufferPass::Hit hit = m->rendered_gbuffers().at(x, y);
  if (hit.record == UINT32_MAX) return {};
  return {m->gpu.record_instance()[hit.record], hit.depth};
}

std::vector<std::string> Renderer::light_group_names() const { return m->gpu.light_groups().names; }
std::vector<std::string> Renderer::pooled_emitters() const { return m->gpu.light_groups().pooled; }
ImageRGB Renderer::light_group_image(uint32_t group) const { return m->film.group_image(group); }

}  // namespace hipr
