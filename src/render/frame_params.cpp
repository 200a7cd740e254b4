#include "render/frame_params.h"

#include <algorithm>
#include <cmath>

#include "scene/default_camera.h"
#include "shaders/shared/abi.h"

namespace hipr {

abi::ViewFrame view_frame(const Camera& camera, float aspect) {
  abi::ViewFrame v{};
  v.position = glm::vec3(camera.camera_to_world[3]);
  v.right = glm::normalize(glm::vec3(camera.camera_to_world[0]));
  v.up = glm::normalize(glm::vec3(camera.camera_to_world[1]));
  v.forward = -glm::normalize(glm::vec3(camera.camera_to_world[2]));
  v.tanHalfFovY = std::tan(0.5f * camera.yfov);
  v.aspect = aspect;
  return v;
}

abi::FrameParams make_frame_params(const Scene& scene, const GpuScene& gpu,
                                   const RenderSettings& s) {
  const Camera camera = resolve_camera(scene);
  const abi::ViewFrame view = view_frame(camera, float(s.width) / float(s.height));
  abi::FrameParams f{};
  f.cameraPosition = view.position;
  f.cameraRight = view.right;
  f.cameraUp = view.up;
  f.cameraForward = view.forward;
  f.tanHalfFovY = view.tanHalfFovY;
  f.aspect = view.aspect;
  f.lensRadius = camera.aperture_radius;
  f.focusDistance = camera.focus_distance;
  f.seed = s.seed;
  f.sampleSequence = s.sampler == Sampler::Random ? abi::kSamplerRandom : abi::kSamplerSobol;
  f.width = s.width;
  f.height = s.height;
  f.tileSize = s.tile_size;
  f.tilesX = (s.width + s.tile_size - 1) / s.tile_size;
  f.tilesY = (s.height + s.tile_size - 1) / s.tile_size;
  f.tileCount = f.tilesX * f.tilesY;
  f.maxDepth = s.max_depth;
  f.lightCount = uint32_t(gpu.light_tables().lights.size());
  f.environmentLight = gpu.light_tables().environment_index;
  f.eachLightOffset = gpu.light_tables().each_offset;
  f.eachLightCount = gpu.light_tables().each_count;
  if (s.light_selection == LightSelection::Tree) {
    f.lightTreeProbability = gpu.light_tables().tree_probability;
    f.lightCdfOffset = gpu.light_tables().tree_cdf_offset();
  }
  if (scene.environment) {
    f.environmentWidth = scene.environment->width;
    f.environmentHeight = scene.environment->height;
    f.environmentIntensity = scene.environment->intensity;
    f.environmentRotation = scene.environment->rotation;
  }
  set_discovery_parameters(f, s.hipr);
  if (s.guiding) {
    // About 128 training paths per cell (each leaves a few vertices in it: a few hundred splats
    // over 128 bins): a cell that few paths reach learns noise. At least 8 cells, at most
    // kGuideMaxCells (512^2 pixels x 2 paths).
    const uint64_t paths = uint64_t(s.width) * s.height * s.guide_training_spp;
    set_guide_grid(f, scene.bounds(),
                   uint32_t(std::clamp<uint64_t>(paths / 128, 8, abi::kGuideMaxCells)));
  }
  // Finite extents can still overflow a radius; unit scale then (the loader rejects non-finite
  // data).
  const float offset_scale = 2.0f * gpu.info().scene_radius;
  f.rayOffsetScale = std::isfinite(offset_scale) ? offset_scale : 1.0f;
  return f;
}

void set_guide_grid(abi::FrameParams& f, std::pair<glm::vec3, glm::vec3> bounds,
                    uint32_t max_cells) {
  f.guideCells = 0;
  const auto [lo, hi] = bounds;
  const glm::vec3 extent = hi - lo;
  const float largest = std::max({extent.x, extent.y, extent.z});
  if (!std::isfinite(largest) || !(largest > 0.0f) || !std::isfinite(lo.x + lo.y + lo.z)) return;
  max_cells = std::clamp<uint32_t>(max_cells, 1, abi::kGuideMaxCells);
  // Cubic cells, as many as fit max_cells: a flat scene gets a flat grid (a thin axis is
  // given a hundredth of the largest extent so its cells are not needles).
  const glm::vec3 sides = glm::max(extent, glm::vec3(largest * 0.01f));
  const float cell = std::cbrt(sides.x * sides.y * sides.z / float(max_cells));
  glm::uvec3 resolution;
  for (int a = 0; a < 3; ++a)
    resolution[a] = uint32_t(std::clamp(std::floor(sides[a] / cell), 1.0f, float(max_cells)));
  while (uint64_t(resolution.x) * resolution.y * resolution.z > max_cells) {
    const int a = resolution.x >= resolution.y && resolution.x >= resolution.z ? 0
                  : resolution.y >= resolution.z                               ? 1
                                                                               : 2;
    resolution[a] -= 1;
  }
  f.guideLo = lo;
  f.guideInvCell = glm::vec3(resolution) / sides;
  f.guideResolutionX = resolution.x;
  f.guideResolutionY = resolution.y;
  f.guideResolutionZ = resolution.z;
  f.guideCells = resolution.x * resolution.y * resolution.z;
}

void set_discovery_parameters(abi::FrameParams& f, const HiprParameters& h) {
  f.wLobe = glm::vec4(h.w_lobe[0], h.w_lobe[1], h.w_lobe[2], h.w_lobe[3]);
  f.wPath = glm::vec3(h.w_path[0], h.w_path[1], h.w_path[2]);
  f.wOcclusion = h.w_occlusion;
  f.depthEpsilon = h.depth_epsilon;
}

}  // namespace hipr
