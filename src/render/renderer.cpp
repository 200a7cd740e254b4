#include "hipr/renderer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"
#include "hipr/scene_diff.h"
#include "render/background_tiles.h"
#include "render/bsdf_tables.h"
#include "render/gpu_scene.h"
#include "render/kernel_features.h"
#include "render/radix_sorter.h"
#include "scene/default_camera.h"
#include "vk/compute_pipeline.h"

namespace hipr {

DisplayRule parse_display_rule(const std::string& name) {
  for (DisplayRule rule : {DisplayRule::Immediate, DisplayRule::Switch, DisplayRule::Blend})
    if (display_rule_name(rule) == name) return rule;
  throw InputError("unknown display rule '" + name + "' (immediate, switch, blend)");
}

std::string display_rule_name(DisplayRule rule) {
  switch (rule) {
    case DisplayRule::Immediate: return "immediate";
    case DisplayRule::Switch: return "switch";
    case DisplayRule::Blend: return "blend";
  }
  return "?";
}

uint32_t scatter_stride(uint32_t count) {
  if (count <= 2) return 1;
  uint32_t stride = std::max<uint32_t>(1, uint32_t(double(count) * 0.6180339887));
  while (std::gcd(stride, count) != 1) ++stride;
  return stride;
}

namespace {

abi::FrameParams make_frame_params(const Scene& scene, const GpuScene& gpu, const RenderSettings& s) {
  const Camera camera = resolve_camera(scene);
  abi::FrameParams f{};
  f.cameraPosition = glm::vec3(camera.camera_to_world[3]);
  f.cameraRight = glm::normalize(glm::vec3(camera.camera_to_world[0]));
  f.cameraUp = glm::normalize(glm::vec3(camera.camera_to_world[1]));
  f.cameraForward = -glm::normalize(glm::vec3(camera.camera_to_world[2]));
  f.tanHalfFovY = std::tan(0.5f * camera.yfov);
  f.aspect = float(s.width) / float(s.height);
  f.seed = s.seed;
  f.width = s.width;
  f.height = s.height;
  f.tileSize = s.tile_size;
  f.tilesX = (s.width + s.tile_size - 1) / s.tile_size;
  f.tilesY = (s.height + s.tile_size - 1) / s.tile_size;
  f.tileCount = f.tilesX * f.tilesY;
  f.maxDepth = s.max_depth;
  f.lightCount = uint32_t(gpu.light_tables().lights.size());
  f.environmentLight = gpu.light_tables().environment_index;
  if (scene.environment) {
    f.environmentWidth = scene.environment->width;
    f.environmentHeight = scene.environment->height;
    f.environmentIntensity = scene.environment->intensity;
    f.environmentRotation = scene.environment->rotation;
  }
  const HiprParameters& h = s.hipr;
  f.wLobe = glm::vec4(h.w_lobe[0], h.w_lobe[1], h.w_lobe[2], h.w_lobe[3]);
  f.wPath = glm::vec3(h.w_path[0], h.w_path[1], h.w_path[2]);
  f.wOcclusion = h.w_occlusion;
  f.depthEpsilon = h.depth_epsilon;
  // Finite extents can still overflow a radius; unit scale then (the loader rejects non-finite data).
  const float offset_scale = 2.0f * gpu.info().scene_radius;
  f.rayOffsetScale = std::isfinite(offset_scale) ? offset_scale : 1.0f;
  return f;
}

std::vector<vk::BindingSlot> trace_bindings(bool discovery) {
  std::vector<vk::BindingSlot> slots = {{abi::kBindingTlas, vk::BindingKind::AccelerationStructure}};
  for (uint32_t b = abi::kBindingPositions; b <= abi::kBindingFrame; ++b) slots.push_back({b});
  slots.push_back({abi::kBindingTileFlags});
  slots.push_back({abi::kBindingBsdfTables});
  slots.push_back({abi::kBindingTileBackground});
  if (discovery)
    for (uint32_t b : {abi::kBindingGBuffer, abi::kBindingChangedRecords, abi::kBindingTileWeights}) slots.push_back({b});
  return slots;
}

vk::ShaderDefines trace_defines(const RenderSettings& s, bool discovery, uint32_t features) {
  vk::ShaderDefines defines = kernel_feature_defines(features);
  defines.emplace_back("HIPR_LIGHT_SAMPLING", std::to_string(int(s.light_sampling)));
  defines.emplace_back("HIPR_DISCOVERY", discovery ? "1" : "0");
  return defines;
}

vk::Buffer storage(const vk::Context& ctx, size_t bytes) { return vk::Buffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT); }

// The image whose pixel i is radiance_of(texels[i]).
template <typename Texel, typename RadianceOf>
ImageRGB image_of(const RenderSettings& s, const std::vector<Texel>& texels, RadianceOf radiance_of) {
  ImageRGB image;
  image.width = s.width;
  image.height = s.height;
  image.rgb.resize(texels.size() * 3);
  for (size_t i = 0; i < texels.size(); ++i) {
    const glm::vec3 radiance = radiance_of(texels[i]);
    for (int c = 0; c < 3; ++c) image.rgb[i * 3 + size_t(c)] = radiance[c];
  }
  return image;
}

// Switch rule: a tile switches to its fresh estimate when D > kSwitchThreshold * V
// (resolve_display.comp): 2 means the stale estimate's squared error B = D - V exceeds V.
constexpr float kSwitchThreshold = 2.0f;

uint32_t groups_for(uint32_t items) { return (items + abi::kWorkgroupSize - 1) / abi::kWorkgroupSize; }

}  // namespace

struct Renderer::Impl {
  Impl(const vk::Context& c, const Scene& scene, const RenderSettings& s)
      : ctx(c),
        settings(s),
        gpu(c, scene),
        tiles_x((s.width + s.tile_size - 1) / s.tile_size),
        tiles_y((s.height + s.tile_size - 1) / s.tile_size),
        pixels(s.width * s.height),
        features(s.specialize_kernel ? hipr::kernel_features(scene) : all_kernel_features()),
        trace(make_trace(false)),
        accumulation(storage(c, size_t(pixels) * sizeof(abi::PixelAccum))),
        stats(storage(c, sizeof(abi::RenderStats))),
        frame(storage(c, sizeof(abi::FrameParams))),
        tile_list(storage(c, size_t(tiles_x) * tiles_y * sizeof(uint32_t))),
        tile_flags(storage(c, size_t(tiles_x) * tiles_y * sizeof(uint32_t))),
        bsdf_tables(vk::make_storage_buffer(c, bsdf_table_data())),
        background(scene),
        tile_background(storage(c, size_t(tiles_x) * tiles_y * sizeof(uint32_t))),
        display(storage(c, size_t(pixels) * sizeof(abi::DisplayTexel))),
        mark_owed(c, "mark_owed.comp", {},
                  {{abi::kBindingFrame}, {abi::kBindingAccumulation}, {abi::kBindingTileFlags}}, 0),
        resolve(c, "resolve_display.comp", {},
                {{abi::kBindingFrame}, {abi::kBindingTileList}, {abi::kBindingAccumulation}, {abi::kBindingTileFlags},
                 {abi::kBindingDisplay}, {abi::kBindingGBuffer}},
                sizeof(abi::ResolvePush)),
        // The display pass reads the G-buffer from the start (it says which surface a pixel
        // shows), so the G-buffers exist even in renders that never run HiPR's stages.
        gbuffer(storage(c, size_t(pixels) * sizeof(abi::GBufferTexel))),
        previous_gbuffer(storage(c, size_t(pixels) * sizeof(abi::GBufferTexel))) {
    all_tiles.resize(size_t(tiles_x) * tiles_y);
    std::iota(all_tiles.begin(), all_tiles.end(), 0u);
    accumulation.clear();
    stats.clear();
    tile_flags.clear();
    display.clear();
    mark_owed.bind_buffer(abi::kBindingFrame, frame);
    mark_owed.bind_buffer(abi::kBindingAccumulation, accumulation);
    mark_owed.bind_buffer(abi::kBindingTileFlags, tile_flags);
    resolve.bind_buffer(abi::kBindingFrame, frame);
    resolve.bind_buffer(abi::kBindingTileList, tile_list);
    resolve.bind_buffer(abi::kBindingAccumulation, accumulation);
    resolve.bind_buffer(abi::kBindingTileFlags, tile_flags);
    resolve.bind_buffer(abi::kBindingDisplay, display);
    resolve.bind_buffer(abi::kBindingGBuffer, gbuffer);
    update_background(scene);
    bind_scene(scene);
  }

  std::unique_ptr<vk::ComputePipeline> make_trace(bool discovery) const {
    return std::make_unique<vk::ComputePipeline>(ctx, "trace_tiles.comp", trace_defines(settings, discovery, features),
                                                 trace_bindings(discovery), sizeof(abi::TracePush));
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
    trace = make_trace(false);
    if (discover) {
      discover = make_trace(true);
      bind_hipr();
    }
  }

  // Which tiles' camera rays cannot hit anything, for the scene's camera and instances.
  void update_background(const Scene& scene) {
    std::vector<uint32_t> mask(all_tiles.size(), 0u);
    if (settings.skip_background_tiles)
      mask = background.mask(scene, settings.width, settings.height, settings.tile_size);
    tile_background.upload(mask.data(), mask.size() * sizeof(uint32_t));
  }

  // HiPR's stage-1..3 pipelines and buffers are made on first use: plain renders never pay for
  // them (the G-buffers are not among them: the display pass reads those for every policy).
  void ensure_hipr() {
    if (discover) return;
    const size_t tiles = all_tiles.size();
    changed_records = storage(ctx, std::max<size_t>(gpu.record_count(), 1) * 4);
    tile_weights = storage(ctx, tiles * 8);
    row_distance = storage(ctx, tiles * 4);
    tile_change = storage(ctx, tiles * 4);
    sorter = std::make_unique<RadixSorter>(ctx, uint32_t(tiles));
    discover = make_trace(true);
    // Stage 1 declares the path tracer's scene bindings too: its opacity cutout reads them.
    std::vector<vk::BindingSlot> visibility_slots = trace_bindings(false);
    visibility_slots.push_back({abi::kBindingGBuffer});
    visibility = std::make_unique<vk::ComputePipeline>(ctx, "visibility.comp", vk::ShaderDefines{}, visibility_slots, 0);
    mark_active = std::make_unique<vk::ComputePipeline>(
        ctx, "mark_active.comp", vk::ShaderDefines{},
        std::vector<vk::BindingSlot>{{abi::kBindingFrame}, {abi::kBindingGBuffer}, {abi::kBindingPreviousGBuffer},
                                     {abi::kBindingChangedRecords}, {abi::kBindingTileFlags}, {abi::kBindingTileChange}},
        0);
    keys = std::make_unique<vk::ComputePipeline>(
        ctx, "schedule_keys.comp", vk::ShaderDefines{},
        std::vector<vk::BindingSlot>{{abi::kBindingFrame}, {abi::kBindingTileFlags}, {abi::kBindingTileWeights},
                                     {abi::kBindingTileRowDistance}, {abi::kBindingTileChange}, {abi::kBindingSortKeys},
                                     {abi::kBindingSortValues}},
        sizeof(uint32_t));
    bind_hipr();
    bind_scene_buffers(*discover);
    bind_scene_buffers(*visibility);
    // The first G-buffer describes the scene as it is now, so the first edit has a "before".
    ctx.submit_and_wait([&](VkCommandBuffer cmd) { visibility->dispatch(cmd, nullptr, groups_for(pixels)); });
    gbuffer_current = true;
  }

  // (Re)binds everything the scene owns: after an update some buffers are new objects.
  void bind_scene(const Scene& scene) {
    const abi::FrameParams params = make_frame_params(scene, gpu, settings);
    frame.upload(&params, sizeof params);
    bind_scene_buffers(*trace);
    if (discover) bind_scene_buffers(*discover);
    if (visibility) bind_scene_buffers(*visibility);
    if (probe) bind_scene_buffers(*probe);
  }

  void bind_scene_buffers(vk::ComputePipeline& pipeline) {
    pipeline.bind_acceleration_structure(abi::kBindingTlas, gpu.tlas());
    const std::pair<uint32_t, const vk::Buffer*> buffers[] = {
        {abi::kBindingPositions, &gpu.positions}, {abi::kBindingNormals, &gpu.normals},
        {abi::kBindingTangents, &gpu.tangents},   {abi::kBindingUvs, &gpu.uvs},
        {abi::kBindingIndices, &gpu.indices},     {abi::kBindingGeometries, &gpu.geometries},
        {abi::kBindingMaterials, &gpu.materials}, {abi::kBindingTextures, &gpu.textures},
        {abi::kBindingTexels, &gpu.texels},       {abi::kBindingLights, &gpu.lights},
        {abi::kBindingLightCdf, &gpu.light_cdf},  {abi::kBindingEnvironment, &gpu.environment},
        {abi::kBindingTileList, &tile_list},      {abi::kBindingAccumulation, &accumulation},
        {abi::kBindingStats, &stats},             {abi::kBindingFrame, &frame},
        {abi::kBindingTileFlags, &tile_flags},    {abi::kBindingBsdfTables, &bsdf_tables},
        {abi::kBindingTileBackground, &tile_background},
    };
    for (const auto& [binding, buffer] : buffers) pipeline.bind_buffer(binding, *buffer);
  }

  // The inspection pass of material_inputs_at, made on first use.
  void ensure_probe() {
    if (probe) return;
    std::vector<vk::BindingSlot> slots = trace_bindings(false);
    slots.push_back({abi::kBindingMaterialProbe});
    probe = std::make_unique<vk::ComputePipeline>(ctx, "material_probe.comp", vk::ShaderDefines{}, slots,
                                                  sizeof(abi::ProbePush));
    probe_output = storage(ctx, sizeof(abi::MaterialInputsProbe));
    probe->bind_buffer(abi::kBindingMaterialProbe, probe_output);
    bind_scene_buffers(*probe);
  }

  void bind_hipr() {
    discover->bind_buffer(abi::kBindingGBuffer, gbuffer);
    discover->bind_buffer(abi::kBindingChangedRecords, changed_records);
    discover->bind_buffer(abi::kBindingTileWeights, tile_weights);
    visibility->bind_buffer(abi::kBindingGBuffer, gbuffer);
    mark_active->bind_buffer(abi::kBindingFrame, frame);
    mark_active->bind_buffer(abi::kBindingGBuffer, gbuffer);
    mark_active->bind_buffer(abi::kBindingPreviousGBuffer, previous_gbuffer);
    mark_active->bind_buffer(abi::kBindingChangedRecords, changed_records);
    mark_active->bind_buffer(abi::kBindingTileFlags, tile_flags);
    mark_active->bind_buffer(abi::kBindingTileChange, tile_change);
    keys->bind_buffer(abi::kBindingFrame, frame);
    keys->bind_buffer(abi::kBindingTileFlags, tile_flags);
    keys->bind_buffer(abi::kBindingTileWeights, tile_weights);
    keys->bind_buffer(abi::kBindingTileRowDistance, row_distance);
    keys->bind_buffer(abi::kBindingTileChange, tile_change);
    keys->bind_buffer(abi::kBindingSortKeys, sorter->keys);
    keys->bind_buffer(abi::kBindingSortValues, sorter->values);
  }

  abi::TracePush trace_push(uint32_t offset, uint32_t count, uint32_t spp) const {
    abi::TracePush push{};
    push.listOffset = offset;
    push.tileCount = count;
    push.groupsPerTile = (settings.tile_size * settings.tile_size + abi::kWorkgroupSize - 1) / abi::kWorkgroupSize;
    const uint64_t groups = uint64_t(count) * push.groupsPerTile;
    if (groups > UINT32_MAX) throw InputError("too many tiles in one dispatch");
    push.tileStride = scatter_stride(uint32_t(groups));
    push.samplesPerPixel = spp;
    return push;
  }

  // The display pass over schedule entries [offset, offset + count) (offset kInvalidIndex: tile ids
  // 0 .. count - 1), after whatever the command buffer wrote before.
  void record_resolve(VkCommandBuffer cmd, uint32_t offset, uint32_t count, uint32_t rule, uint32_t require_flags,
                      uint32_t skip_flags) const {
    const abi::ResolvePush push{offset,          count, require_flags, skip_flags, rule, kSwitchThreshold,
                                gbuffer_current ? 1u : 0u};
    vk::compute_to_compute_barrier(cmd);
    resolve.dispatch(cmd, &push, count);
  }

  void dispatch_trace(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline, const abi::TracePush& push) const {
    pipeline.dispatch(cmd, &push, push.tileCount * push.groupsPerTile);
  }

  const vk::Context& ctx;
  RenderSettings settings;
  GpuScene gpu;
  uint32_t tiles_x, tiles_y, pixels;
  uint32_t features;  // kernel features (kernel_features.h) the trace kernels are compiled with
  std::unique_ptr<vk::ComputePipeline> trace;
  vk::Buffer accumulation, stats, frame, tile_list, tile_flags, bsdf_tables;
  BackgroundTiles background;
  vk::Buffer tile_background;  // per tile: 1 = background only (BackgroundTiles)
  vk::Buffer display;          // DisplayTexel per pixel
  vk::ComputePipeline mark_owed, resolve;
  vk::Buffer gbuffer, previous_gbuffer;  // stage 1 (GBufferTexel per pixel), also read by the display pass
  bool gbuffer_current = false;          // the G-buffer shows the scene as it is now
  std::vector<uint32_t> all_tiles;
  // HiPR (made by ensure_hipr)
  vk::Buffer changed_records, tile_weights, row_distance, tile_change;
  std::unique_ptr<RadixSorter> sorter;
  std::unique_ptr<vk::ComputePipeline> discover, visibility, mark_active, keys;
  std::unique_ptr<vk::ComputePipeline> probe;  // material_inputs_at
  vk::Buffer probe_output;
};

Renderer::Renderer(const vk::Context& ctx, const Scene& scene, const RenderSettings& settings) {
  if (settings.width == 0 || settings.height == 0 || settings.width > 16384 || settings.height > 16384)
    throw InputError("image size must be between 1x1 and 16384x16384");
  if (settings.tile_size < 1 || settings.tile_size > 256) throw InputError("tile size must be between 1 and 256");
  m = std::make_unique<Impl>(ctx, scene, settings);
}

Renderer::~Renderer() = default;

const RenderSettings& Renderer::settings() const { return m->settings; }
uint32_t Renderer::tiles_x() const { return m->tiles_x; }
uint32_t Renderer::tiles_y() const { return m->tiles_y; }
uint32_t Renderer::tile_count() const { return m->tiles_x * m->tiles_y; }
const GpuSceneInfo& Renderer::scene_info() const { return m->gpu.info(); }
uint32_t Renderer::kernel_features() const { return m->features; }

void Renderer::add_samples(std::span<const uint32_t> tiles, uint32_t samples_per_pixel) {
  if (tiles.empty() || samples_per_pixel == 0) return;
  for (uint32_t t : tiles)
    if (t >= tile_count()) throw InternalError("tile id out of range");
  m->tile_list.upload(tiles.data(), tiles.size_bytes());
  const abi::TracePush push = m->trace_push(0, uint32_t(tiles.size()), samples_per_pixel);
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) { m->dispatch_trace(cmd, *m->trace, push); });
}

void Renderer::add_samples_full_frame(uint32_t samples_per_pixel) { add_samples(m->all_tiles, samples_per_pixel); }

void Renderer::update_scene(const Scene& scene, const ChangeSet& changes) {
  if (changes.materials) m->gpu.update_materials(scene);
  m->ensure_features(scene);  // materials, lights: anything may bring in a feature
  if (changes.transforms) m->gpu.update_instances(scene);  // includes the light tables
  else if (changes.light_tables) m->gpu.update_lights(scene);
  if (changes.transforms || changes.camera) m->update_background(scene);
  if (!changes.empty()) m->gbuffer_current = false;
  m->bind_scene(scene);
}

uint32_t Renderer::stage1_visibility(const ChangeSet& changes) {
  m->ensure_hipr();
  // One pass over the records: a flag per instance, then each record looks up its own.
  const std::vector<uint32_t>& record_instance = m->gpu.record_instance();
  std::vector<bool> instance_changed;
  for (uint32_t instance : changes.instances) {
    if (instance >= instance_changed.size()) instance_changed.resize(instance + 1, false);
    instance_changed[instance] = true;
  }
  std::vector<uint32_t> changed(std::max<size_t>(record_instance.size(), 1), 0);
  for (size_t r = 0; r < record_instance.size(); ++r)
    changed[r] = record_instance[r] < instance_changed.size() && instance_changed[record_instance[r]] ? 1 : 0;
  m->changed_records.upload(changed.data(), changed.size() * 4);
  // What no G-buffer shows (a moved camera, a punctual light's or the environment's reach) makes
  // every tile active.
  const bool everything = changes.camera || !changes.lights.empty() || changes.environment;
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    const VkBufferCopy copy{0, 0, m->gbuffer.size()};
    vkCmdCopyBuffer(cmd, m->gbuffer.handle(), m->previous_gbuffer.handle(), 1, &copy);
    vkCmdFillBuffer(cmd, m->tile_flags.handle(), 0, VK_WHOLE_SIZE, everything ? abi::kTileActive : 0u);
    vkCmdFillBuffer(cmd, m->tile_weights.handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, m->tile_change.handle(), 0, VK_WHOLE_SIZE, 0);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
    m->visibility->dispatch(cmd, nullptr, groups_for(m->pixels));
    vk::compute_to_compute_barrier(cmd);
    m->mark_active->dispatch(cmd, nullptr, groups_for(m->pixels));
  });
  m->gbuffer_current = true;
  // The one number the CPU needs: stage 2 is split into steps of equal work over |A| tiles.
  const std::vector<uint32_t> flags = m->tile_flags.download_all<uint32_t>();
  return uint32_t(std::count_if(flags.begin(), flags.end(), [](uint32_t f) { return (f & abi::kTileActive) != 0; }));
}

void Renderer::mark_all_owed() {
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) { m->mark_owed.dispatch(cmd, nullptr, groups_for(m->pixels)); });
}

void Renderer::stage2_discover(uint32_t samples_per_pixel) {
  // The dispatch covers the whole schedule (which the sort guarantees to list every tile, active
  // ones first); tiles without kTileActive leave at once.
  build_schedule();
  stage2_discover(0, tile_count(), samples_per_pixel, std::nullopt);
}

void Renderer::stage2_discover(uint32_t offset, uint32_t count, uint32_t samples_per_pixel,
                               std::optional<DisplayRule> then_resolve) {
  m->ensure_hipr();
  if (offset >= tile_count() || count == 0) return;
  abi::TracePush push = m->trace_push(offset, std::min(count, tile_count() - offset), samples_per_pixel);
  push.requireFlags = abi::kTileActive;
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    m->dispatch_trace(cmd, *m->discover, push);
    if (then_resolve) m->record_resolve(cmd, push.listOffset, push.tileCount, uint32_t(*then_resolve), push.requireFlags, 0);
  });
}

void Renderer::build_schedule() {
  m->ensure_hipr();
  const uint32_t tiles = tile_count();
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    for (uint32_t pass = 0; pass < 2; ++pass) {
      m->keys->dispatch(cmd, &pass, groups_for(tiles));
      vk::compute_to_compute_barrier(cmd);
    }
    m->sorter->record(cmd, tiles);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0,
                         nullptr, 0, nullptr);
    const VkBufferCopy copy{0, 0, VkDeviceSize(tiles) * 4};
    vkCmdCopyBuffer(cmd, m->sorter->values.handle(), m->tile_list.handle(), 1, &copy);
  });
}

void Renderer::set_schedule(std::span<const uint32_t> order) {
  if (order.size() != tile_count()) throw InternalError("a schedule lists every tile once");
  m->tile_list.upload(order.data(), order.size_bytes());
}

void Renderer::render_schedule(uint32_t offset, uint32_t count, uint32_t samples_per_pixel, bool skip_active,
                               std::optional<DisplayRule> then_resolve) {
  if (offset >= tile_count() || count == 0) return;
  count = std::min(count, tile_count() - offset);
  abi::TracePush push = m->trace_push(offset, count, samples_per_pixel);
  push.skipFlags = skip_active ? abi::kTileActive : 0u;
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    m->dispatch_trace(cmd, *m->trace, push);
    if (then_resolve) m->record_resolve(cmd, offset, count, uint32_t(*then_resolve), 0, push.skipFlags);
  });
}

void Renderer::resolve_display_all(DisplayRule rule) {
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) { m->record_resolve(cmd, abi::kInvalidIndex, tile_count(), uint32_t(rule), 0, 0); });
}

void Renderer::capture_stale_display() {
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) { m->record_resolve(cmd, abi::kInvalidIndex, tile_count(), abi::kDisplayCapture, 0, 0); });
}

ImageRGB Renderer::displayed_image() const {
  return image_of(m->settings, m->display.download_all<abi::DisplayTexel>(),
                  [](const abi::DisplayTexel& t) { return t.shown; });
}

RenderSnapshot Renderer::snapshot() const {
  return {m->accumulation.download_all<abi::PixelAccum>(), m->display.download_all<abi::DisplayTexel>()};
}

void Renderer::restore(const RenderSnapshot& snapshot) {
  if (snapshot.accumulation.size() != m->pixels || snapshot.display.size() != m->pixels)
    throw InternalError("a snapshot of another image size");
  m->accumulation.upload(snapshot.accumulation.data(), snapshot.accumulation.size() * sizeof(abi::PixelAccum));
  m->display.upload(snapshot.display.data(), snapshot.display.size() * sizeof(abi::DisplayTexel));
}

std::vector<uint32_t> Renderer::gbuffer_instances() const {
  m->ensure_hipr();
  const auto texels = m->gbuffer.download_all<abi::GBufferTexel>();
  std::vector<uint32_t> out(texels.size(), UINT32_MAX);
  for (size_t i = 0; i < texels.size(); ++i)
    if (texels[i].record != abi::kInvalidIndex) out[i] = m->gpu.record_instance()[texels[i].record];
  return out;
}

abi::MaterialInputsProbe Renderer::material_inputs_at(uint32_t record, uint32_t primitive, glm::vec2 barycentrics) const {
  if (record >= m->gpu.record_count()) throw InternalError("probe of a missing geometry record");
  m->ensure_probe();
  const abi::ProbePush push{record, primitive, barycentrics};
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) { m->probe->dispatch(cmd, &push, 1); });
  return m->probe_output.download_all<abi::MaterialInputsProbe>()[0];
}

std::vector<uint32_t> Renderer::tile_flags() const {
  m->ensure_hipr();
  return m->tile_flags.download_all<uint32_t>();
}

std::vector<double> Renderer::tile_weights() const {
  m->ensure_hipr();
  const auto fixed = m->tile_weights.download_all<uint64_t>();
  std::vector<double> out(fixed.size());
  for (size_t i = 0; i < fixed.size(); ++i) out[i] = double(fixed[i]) / abi::kWeightScale;
  return out;
}

std::vector<uint32_t> Renderer::schedule() const { return m->tile_list.download_all<uint32_t>(); }

ImageRGB Renderer::image() const {
  return image_of(m->settings, m->accumulation.download_all<abi::PixelAccum>(), [](const abi::PixelAccum& a) {
    const uint32_t count = a.count & abi::kPixelCountMask;
    return count ? a.sum * (1.0f / float(count)) : glm::vec3(0.0f);
  });
}

std::vector<uint32_t> Renderer::sample_counts() const {
  const auto accum = m->accumulation.download_all<abi::PixelAccum>();
  std::vector<uint32_t> counts(accum.size());
  for (size_t i = 0; i < accum.size(); ++i) counts[i] = accum[i].count & abi::kPixelCountMask;
  return counts;
}

RenderCounters Renderer::counters() const {
  abi::RenderStats s{};
  m->stats.download(&s, sizeof s);
  return {s.rays, s.samples, s.nonFiniteSamples};
}

void Renderer::reset_counters() { m->stats.clear(); }

void Renderer::reset() {
  m->accumulation.clear();
  m->display.clear();
  m->stats.clear();
}

void Renderer::set_hipr_parameters(const HiprParameters& parameters) {
  m->settings.hipr = parameters;
  // Patch the uploaded frame parameters instead of rebuilding them: that needs the scene.
  abi::FrameParams f{};
  m->frame.download(&f, sizeof f);
  f.wLobe = glm::vec4(parameters.w_lobe[0], parameters.w_lobe[1], parameters.w_lobe[2],
                      parameters.w_lobe[3]);
  f.wPath = glm::vec3(parameters.w_path[0], parameters.w_path[1], parameters.w_path[2]);
  f.wOcclusion = parameters.w_occlusion;
  f.depthEpsilon = parameters.depth_epsilon;
  m->frame.upload(&f, sizeof f);
}

void Renderer::refresh_gbuffer() {
  m->ensure_hipr();
  m->ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) { m->visibility->dispatch(cmd, nullptr, groups_for(m->pixels)); });
  m->gbuffer_current = true;
}

Renderer::PixelHit Renderer::gbuffer_at(uint32_t x, uint32_t y) const {
  if (x >= m->settings.width || y >= m->settings.height) return {};
  m->ensure_hipr();
  abi::GBufferTexel texel{};
  m->gbuffer.download(&texel, sizeof texel,
                      (VkDeviceSize(y) * m->settings.width + x) * sizeof texel);
  if (texel.record == abi::kInvalidIndex) return {};
  return {m->gpu.record_instance()[texel.record], texel.depth};
}

std::vector<uint32_t> Renderer::owed_tiles() const {
  const auto accum = m->accumulation.download_all<abi::PixelAccum>();
  const uint32_t width = m->settings.width, tile = m->settings.tile_size;
  std::vector<uint32_t> owed(tile_count(), 0);
  for (size_t i = 0; i < accum.size(); ++i)
    if (accum[i].count & abi::kPixelOwed)
      ++owed[(i / width / tile) * m->tiles_x + (i % width) / tile];
  return owed;
}

void Renderer::warm_up_kernels() {
  m->ensure_hipr();
  // Bit 31 is no kTile* flag: every workgroup leaves at its first check.
  abi::TracePush push = m->trace_push(0, tile_count(), 1);
  push.requireFlags = 1u << 31;
  const uint32_t tiles = tile_count();
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    m->dispatch_trace(cmd, *m->trace, push);
    m->dispatch_trace(cmd, *m->discover, push);
    for (uint32_t pass = 0; pass < 2; ++pass) {
      m->keys->dispatch(cmd, &pass, groups_for(tiles));
      vk::compute_to_compute_barrier(cmd);
    }
    m->sorter->record(cmd, tiles);
  });
}

}  // namespace hipr
