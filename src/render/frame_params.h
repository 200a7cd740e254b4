#pragma once
// The FrameParams every kernel reads: camera, image and tile geometry, lights, environment and
// HiPR's discovery weights, from the scene, its GPU form and the render settings.
#include "hipr/renderer.h"
#include "render/gpu_scene.h"
#include "shaders/shared/abi.h"

namespace hipr {

// The camera as the kernels see it (FrameParams' camera fields), for an image of this aspect.
abi::ViewFrame view_frame(const Camera& camera, float aspect);

abi::FrameParams make_frame_params(const Scene& scene, const GpuScene& gpu,
                                   const RenderSettings& settings);

// The path guide's grid over the scene's bounds, at most `max_cells` cubic cells (FrameParams'
// guide fields; no cells when the bounds are empty or not finite).
void set_guide_grid(abi::FrameParams& frame, std::pair<glm::vec3, glm::vec3> bounds,
                    uint32_t max_cells);

// Copies the discovery parameters into `frame` (the rest stays).
void set_discovery_parameters(abi::FrameParams& frame, const HiprParameters& parameters);

}  // namespace hipr
