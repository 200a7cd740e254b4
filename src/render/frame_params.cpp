#include "render/frame_params.h"

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
  // Finite extents can still overflow a radius; unit scale then (the loader rejects non-finite
  // data).
  const float offset_scale = 2.0f * gpu.info().scene_radius;
  f.rayOffsetScale = std::isfinite(offset_scale) ? offset_scale : 1.0f;
  return f;
}

void set_discovery_parameters(abi::FrameParams& f, const HiprParameters& h) {
  f.wLobe = glm::vec4(h.w_lobe[0], h.w_lobe[1], h.w_lobe[2], h.w_lobe[3]);
  f.wPath = glm::vec3(h.w_path[0], h.w_path[1], h.w_path[2]);
  f.wOcclusion = h.w_occlusion;
  f.depthEpsilon = h.depth_epsilon;
}

}  // namespace hipr
