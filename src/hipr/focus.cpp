#include "hipr/focus.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"

namespace hipr {

FocusSeed focus_on_node(const Scene& scene, size_t node, float weight) {
  if (node >= scene.nodes.size()) throw InputError("focus: no node #" + std::to_string(node));
  FocusSeed seed;
  seed.weight = weight;
  const std::vector<Instance> instances = scene.instances();
  for (uint32_t i = 0; i < instances.size(); ++i) {
    // In the subtree when `node` is the instance's node or one of its ancestors.
    for (int n = int(instances[i].node); n >= 0; n = scene.nodes[size_t(n)].parent)
      if (size_t(n) == node) {
        seed.instances.push_back(i);
        break;
      }
  }
  return seed;
}

Focus follow_instances(const Focus& focus, const std::vector<Instance>& before,
                       const std::vector<Instance>& after) {
  std::vector<uint32_t> now_of_node;  // node -> its instance after, or UINT32_MAX
  for (uint32_t i = 0; i < after.size(); ++i) {
    if (after[i].node >= now_of_node.size()) now_of_node.resize(after[i].node + 1, UINT32_MAX);
    now_of_node[after[i].node] = i;
  }
  Focus followed = focus;
  for (FocusSeed& seed : followed.seeds) {
    std::vector<uint32_t> instances;
    for (uint32_t i : seed.instances) {
      if (i >= before.size() || before[i].node >= now_of_node.size()) continue;
      if (const uint32_t now = now_of_node[before[i].node]; now != UINT32_MAX)
        instances.push_back(now);
    }
    seed.instances = std::move(instances);
  }
  return followed;
}

void validate_focus_seed(const FocusSeed& seed, const std::string& where) {
  if (!std::isfinite(seed.weight) || seed.weight <= 0.0f || seed.weight > kMaxFocusWeight)
    throw InputError(where + ": a focus weight must be in (0, " +
                     std::to_string(int(kMaxFocusWeight)) + "]");
  if (seed.pixel) {
    if (!std::isfinite(seed.pixel->x) || !std::isfinite(seed.pixel->y))
      throw InputError(where + ": a focus pixel must be finite");
    if (!std::isfinite(seed.radius) || seed.radius <= 0.0f)
      throw InputError(where + ": a focus disc needs a positive, finite \"radius\" in pixels");
  }
}

Focus with_focus_edit(const Scene& scene, Focus focus, const FocusEdit& edit) {
  if (edit.clear) return {};
  FocusSeed seed = edit.node ? focus_on_node(scene, find_node(scene, *edit.node), edit.weight)
                             : FocusSeed{.weight = edit.weight};
  seed.pixel = edit.pixel;
  seed.radius = edit.radius;
  validate_focus_seed(seed, describe(Edit{edit}));
  if (seed.pixel) {
    const auto discs = std::count_if(focus.seeds.begin(), focus.seeds.end(),
                                     [](const FocusSeed& s) { return s.pixel.has_value(); });
    if (size_t(discs) >= kMaxFocusDiscs)
      throw InputError(describe(Edit{edit}) + ": a focus holds at most " +
                       std::to_string(kMaxFocusDiscs) + " discs");
  }
  focus.seeds.push_back(std::move(seed));
  return focus;
}

std::vector<uint8_t> focus_pixels(const Focus& focus, const std::vector<uint32_t>& pixel_instances,
                                  uint32_t width, uint32_t height) {
  std::vector<uint8_t> covered(size_t(width) * height, 0);
  for (const FocusSeed& seed : focus.seeds) {
    for (size_t p = 0; p < covered.size() && p < pixel_instances.size(); ++p)
      if (std::find(seed.instances.begin(), seed.instances.end(), pixel_instances[p]) !=
          seed.instances.end())
        covered[p] = 1;
    if (!seed.pixel) continue;
    for (uint32_t y = 0; y < height; ++y)
      for (uint32_t x = 0; x < width; ++x) {
        const glm::vec2 centre(float(x) + 0.5f, float(y) + 0.5f);
        const glm::vec2 d = centre - *seed.pixel;
        if (std::sqrt(d.x * d.x + d.y * d.y) <= seed.radius) covered[size_t(y) * width + x] = 1;
      }
  }
  return covered;
}

std::string describe(const Scene& scene, const Focus& focus) {
  if (focus.empty()) return "none";
  const std::vector<Instance> instances = scene.instances();
  std::string text;
  for (const FocusSeed& seed : focus.seeds) {
    if (!text.empty()) text += "; ";
    std::string names;
    size_t named = 0;
    for (uint32_t i : seed.instances) {
      if (i >= instances.size()) continue;
      if (++named > 3) continue;  // counted below
      const std::string& name = scene.nodes[instances[i].node].name;
      if (!names.empty()) names += ", ";
      names += name.empty() ? "#" + std::to_string(instances[i].node) : name;
    }
    if (named > 3) names += " and " + std::to_string(named - 3) + " more";
    text += names;
    if (seed.pixel) {
      char disc[96];
      std::snprintf(disc, sizeof disc, "%sdisc (%g, %g) r %g", names.empty() ? "" : ", ",
                    seed.pixel->x, seed.pixel->y, seed.radius);
      text += disc;
    }
    if (seed.weight != 1.0f) {
      char weight[32];
      std::snprintf(weight, sizeof weight, " x%g", seed.weight);
      text += weight;
    }
  }
  return text;
}

}  // namespace hipr
