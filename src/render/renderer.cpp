#include "hipr/renderer.h"

#include <cmath>
#include <numeric>

#include "core/error.h"
#include "hipr/scene_diff.h"
#include "render/gpu_scene.h"
#include "scene/default_camera.h"
#include "vk/compute_pipeline.h"

namespace hipr {

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
  f.sceneScale = gpu.info().scene_radius;
  f.seed = s.seed;
  f.width = s.width;
  f.height = s.height;
  f.tileSize = s.tile_size;
  f.tilesX = (s.width + s.tile_size - 1) / s.tile_size;
  f.maxDepth = s.max_depth;
  f.lightCount = uint32_t(gpu.light_tables().lights.size());
  f.environmentLight = gpu.light_tables().environment_index;
  if (scene.environment) {
    f.environmentWidth = scene.environment->width;
    f.environmentHeight = scene.environment->height;
    f.environmentIntensity = scene.environment->intensity;
    f.environmentRotation = scene.environment->rotation;
  }
  return f;
}

std::vector<vk::BindingSlot> trace_bindings() {
  std::vector<vk::BindingSlot> slots = {{abi::kBindingTlas, vk::BindingKind::AccelerationStructure}};
  for (uint32_t b = abi::kBindingPositions; b <= abi::kBindingFrame; ++b) slots.push_back({b});
  return slots;
}

}  // namespace

struct Renderer::Impl {
  Impl(const vk::Context& c, const Scene& scene, const RenderSettings& s)
      : ctx(c),
        settings(s),
        gpu(c, scene),
        pipeline(c, "trace_tiles.comp", {{"HIPR_LIGHT_SAMPLING", std::to_string(int(s.light_sampling))}},
                 trace_bindings(), sizeof(abi::TracePush)),
        accumulation(c, size_t(s.width) * s.height * sizeof(abi::PixelAccum), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
        stats(c, sizeof(abi::RenderStats), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
        frame(c, sizeof(abi::FrameParams), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {
    tiles_x = (s.width + s.tile_size - 1) / s.tile_size;
    tiles_y = (s.height + s.tile_size - 1) / s.tile_size;
    all_tiles.resize(size_t(tiles_x) * tiles_y);
    std::iota(all_tiles.begin(), all_tiles.end(), 0u);
    tile_list = vk::Buffer(c, all_tiles.size() * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    accumulation.clear();
    stats.clear();
    bind_scene(scene);
  }

  // (Re)binds everything the scene owns: after an update some buffers are new objects.
  void bind_scene(const Scene& scene) {
    const abi::FrameParams params = make_frame_params(scene, gpu, settings);
    frame.upload(&params, sizeof params);
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
    };
    for (const auto& [binding, buffer] : buffers) pipeline.bind_buffer(binding, *buffer);
  }

  const vk::Context& ctx;
  RenderSettings settings;
  GpuScene gpu;
  vk::ComputePipeline pipeline;
  vk::Buffer accumulation, stats, frame, tile_list;
  std::vector<uint32_t> all_tiles;
  uint32_t tiles_x = 0, tiles_y = 0;
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

void Renderer::add_samples(std::span<const uint32_t> tiles, uint32_t samples_per_pixel) {
  if (tiles.empty() || samples_per_pixel == 0) return;
  for (uint32_t t : tiles)
    if (t >= tile_count()) throw InternalError("tile id out of range");
  m->tile_list.upload(tiles.data(), tiles.size_bytes());
  const uint32_t tile_pixels = m->settings.tile_size * m->settings.tile_size;
  abi::TracePush push{};
  push.tileCount = uint32_t(tiles.size());
  push.groupsPerTile = (tile_pixels + abi::kWorkgroupSize - 1) / abi::kWorkgroupSize;
  const uint64_t groups = uint64_t(push.tileCount) * push.groupsPerTile;
  if (groups > UINT32_MAX) throw InputError("too many tiles in one dispatch");
  push.tileStride = scatter_stride(uint32_t(groups));
  push.samplesPerPixel = samples_per_pixel;
  m->ctx.submit_and_wait([&](VkCommandBuffer cmd) { m->pipeline.dispatch(cmd, &push, uint32_t(groups)); });
}

void Renderer::update_scene(const Scene& scene, const ChangeSet& changes) {
  if (changes.materials) m->gpu.update_materials(scene);
  if (changes.transforms) m->gpu.update_instances(scene);  // includes the light tables
  else if (changes.light_tables) m->gpu.update_lights(scene);
  m->bind_scene(scene);
}

void Renderer::add_samples_full_frame(uint32_t samples_per_pixel) { add_samples(m->all_tiles, samples_per_pixel); }

ImageRGB Renderer::image() const {
  const auto accum = m->accumulation.download_all<abi::PixelAccum>();
  ImageRGB image;
  image.width = m->settings.width;
  image.height = m->settings.height;
  image.rgb.resize(accum.size() * 3);
  for (size_t i = 0; i < accum.size(); ++i) {
    const float scale = accum[i].count ? 1.0f / float(accum[i].count) : 0.0f;
    for (int c = 0; c < 3; ++c) image.rgb[i * 3 + size_t(c)] = accum[i].sum[c] * scale;
  }
  return image;
}

std::vector<uint32_t> Renderer::sample_counts() const {
  const auto accum = m->accumulation.download_all<abi::PixelAccum>();
  std::vector<uint32_t> counts(accum.size());
  for (size_t i = 0; i < accum.size(); ++i) counts[i] = accum[i].count;
  return counts;
}

RenderCounters Renderer::counters() const {
  abi::RenderStats s{};
  m->stats.download(&s, sizeof s);
  return {s.rays, s.samples, s.nonFiniteSamples};
}

void Renderer::reset() {
  m->accumulation.clear();
  m->stats.clear();
}

}  // namespace hipr
