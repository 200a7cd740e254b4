#pragma once
// SceneDiff: what changed between two states of the same scene, as the changed set E of the
// HiPR paper (instances whose transform, visibility, material or emission changed; lights that
// changed) plus the kinds of change, which decide the cheapest GPU update.
#include <cstdint>
#include <vector>

#include "hipr/scene.h"

namespace hipr {

// An emitter whose radiance an edit scaled, per channel, leaving everything else about it as it
// was: a punctual light's intensity or colour, a material's emission, the environment's intensity.
struct EmitterScale {
  enum class Kind { PunctualLight, Material, Environment };
  Kind kind = Kind::PunctualLight;
  uint32_t index = 0;  // the light's node, the material; 0 for the environment
  glm::vec3 factor{1.0f};
};

// A punctual light as it shines: its parameters and where its node puts it.
struct PlacedLight {
  PunctualLight light;
  glm::mat4 world{1.0f};
  bool operator==(const PlacedLight&) const = default;
};

// A punctual light an edit changed (moved, re-aimed or re-parametrized), before and after: stage 1
// looks for the surfaces it reaches in either state.
struct LightChange {
  uint32_t node = 0;
  PlacedLight before, after;
  bool operator==(const LightChange&) const = default;
};

struct ChangeSet {
  // Indices into the edited scene's Scene::instances(): the changed set E (instances moved,
  // shown, hidden, added, deformed or re-materialed).
  std::vector<uint32_t> instances;
  // Nodes whose instances left the scene (deleted): E's part that only the image before the
  // edit shows.
  std::vector<uint32_t> departed;
  std::vector<LightChange> lights;  // punctual lights that changed
  bool materials = false;           // material parameters changed: patch the material table
  bool transforms = false;          // an instance moved, appeared or disappeared: rebuild the TLAS
  bool geometry = false;      // meshes added, removed or deformed: upload vertices, build BLASes
  bool light_tables = false;  // emitters or punctual lights changed: rebuild light tables
  bool camera = false;        // the view changed
  Camera camera_before;       // the view before the edit (when `camera`)
  bool lens = false;          // a camera with an open lens before or after: no reprojection
  // The environment changed (intensity, rotation or map). Like a punctual light it reaches
  // every tile without being visible in a G-buffer, so everything restarts.
  bool environment = false;
  // The map itself changed (switched, switched on or off, the sky re-made): upload it again.
  bool environment_map = false;
  // When the edit changed nothing but emitters' brightness and colour, each by a finite factor
  // per channel (radiance is linear in them: the converged image can be relit, docs/method.md).
  // Empty for any other edit.
  std::vector<EmitterScale> emitter_scales;

  // Nothing but the view changed, through pinholes: the image before the edit can be
  // reprojected into the new one.
  bool camera_only() const {
    return camera && !lens && instances.empty() && departed.empty() && lights.empty() &&
           !materials && !transforms && !geometry && !light_tables && !environment;
  }

  bool empty() const {
    return instances.empty() && departed.empty() && lights.empty() && !materials && !transforms &&
           !geometry && !light_tables && !camera && !environment;
  }
};

// Both states must come from the same loaded scene, edited: instances are paired by their node
// (edits keep node indices), meshes by index and revision.
ChangeSet diff_scenes(const Scene& before, const Scene& after);

// What diff_scenes reads of a scene, copied without the geometry (vertex positions only when the
// default camera, which frames the bounds, is in use): a cheap "before" for every edit.
Scene diff_snapshot(const Scene& scene);

}  // namespace hipr
