#pragma once
// Attention-guided rendering (docs/method.md#focus): what the user looks at, as seeds for HiPR's
// order. A focus is treated like a changed set for ordering only: stage 1 marks the tiles where
// a seed is visible, stage 2 discovers where its light paths go, stage 3 orders the rest
// outward. It changes no radiance and restarts no pixel; after an edit the edit's tiles come
// first, then the focus's.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "hipr/edits.h"
#include "hipr/scene.h"

namespace hipr {

// One seed: objects (instances, as numbered by Scene::instances()) or a disc on screen, with a
// weight that orders the tiles of several seeds (a tile scores the summed weight of its pixels).
struct FocusSeed {
  std::vector<uint32_t> instances;
  std::optional<glm::vec2> pixel;  // the disc's centre in pixels (x right, y down)
  float radius = 0.0f;             // pixels
  float weight = 1.0f;             // (0, kMaxFocusWeight]

  bool operator==(const FocusSeed&) const = default;
};

struct Focus {
  std::vector<FocusSeed> seeds;

  bool empty() const { return seeds.empty(); }
  bool operator==(const Focus&) const = default;
};

inline constexpr float kMaxFocusWeight = 1000.0f;
inline constexpr size_t kMaxFocusDiscs = 16;  // screen discs one focus may hold

// A seed of the instances of node `node` and of its subtree (hidden ones included: they seed
// nothing until they show). Throws InputError for a node index out of range.
FocusSeed focus_on_node(const Scene& scene, size_t node, float weight = 1.0f);

// Checks a seed's numbers: a finite weight in (0, kMaxFocusWeight], a disc with a finite centre
// and a positive finite radius. Throws InputError naming `where`.
void validate_focus_seed(const FocusSeed& seed, const std::string& where);

// `focus` after a script's focus op: its seed added (a node's subtree, a disc, or both), or
// every seed dropped ("clear"). Throws InputError for an unknown node or bad numbers, or when
// the focus would hold more than kMaxFocusDiscs discs.
Focus with_focus_edit(const Scene& scene, Focus focus, const FocusEdit& edit);

// `focus` after an edit that added or removed instances (Scene::instances() before and after
// it): each seed's instances renumbered by their node, those that left dropped.
Focus follow_instances(const Focus& focus, const std::vector<Instance>& before,
                       const std::vector<Instance>& after);

// The pixels the focus covers, row-major, 1 where a pixel sees one of its instances
// (`pixel_instances`: the instance each pixel sees, as Renderer::gbuffer_instances) or where its
// centre lies in one of its discs; stage 1 marks the tiles of these pixels.
std::vector<uint8_t> focus_pixels(const Focus& focus, const std::vector<uint32_t>& pixel_instances,
                                  uint32_t width, uint32_t height);

// A one-line description ("tall_block, disc (12, 40) r 8").
std::string describe(const Scene& scene, const Focus& focus);

}  // namespace hipr
