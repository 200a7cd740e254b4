#include "render/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/packing.hpp>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace hipr {
namespace shader {
using namespace glm;
using namespace abi;
#include "shaders/common/light_tree_cone.glsl"
}  // namespace shader

namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kBuckets = 12;
constexpr int kMaxCostDepth = 48;
// The most lights a node taken by power (abi::kLightTreeByPower) holds, as Cycles' light tree
// bounds its leaves: a larger group whose split the cost does not favour may still hold lights
// that the importance tells apart further down.
constexpr size_t kMaxPowerLights = 8;

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// A cone of directions: every direction within `angle` (radians) of `axis`; pi holds them all.
struct Cone {
  glm::vec3 axis{0.0f, 0.0f, 1.0f};
  float angle = 0.0f;
};

// The smallest cone around both (for two cones that do not nest: the one whose edge touches
// both far edges, its axis turned from a's toward b's).
Cone cone_union(const Cone& a, const Cone& b) {
  if (a.angle >= kPi || b.angle >= kPi) return {a.axis, kPi};
  // (The same axis: acos of its rounded dot with itself need not be 0.)
  if (a.axis == b.axis) return a.angle >= b.angle ? a : b;
  const float between = std::acos(std::clamp(glm::dot(a.axis, b.axis), -1.0f, 1.0f));
  if (between + b.angle <= a.angle) return a;
  if (between + a.angle <= b.angle) return b;
  const float angle = 0.5f * (a.angle + between + b.angle);
  if (angle >= kPi) return {a.axis, kPi};
  const glm::vec3 toward = b.axis - a.axis * glm::dot(a.axis, b.axis);
  const float length = glm::length(toward);
  if (!(length > 1e-7f)) return {a.axis, kPi};  // opposite axes: every direction
  const float turn = angle - a.angle;
  return {glm::normalize(a.axis * std::cos(turn) + (toward / length) * std::sin(turn)), angle};
}

// Bounds of a group of lights while the tree is built.
struct Group {
  glm::vec3 lo{INFINITY}, hi{-INFINITY};
  float power = 0.0f;
  Cone cone;
  float reach = 0.0f;  // theta_e
  bool two_sided = false;
  // Every light is a one-sided surface facing exactly cone.axis (bit for bit: a plane bound
  // with normals a rounding apart would not hold far from the lights).
  bool one_facing = false;
  bool empty = true;

  void add(const LightBounds& l) {
    const Cone c{l.axis, std::acos(std::clamp(l.cos_spread, -1.0f, 1.0f))};
    const float r = std::acos(std::clamp(l.cos_reach, -1.0f, 1.0f));
    add(Group{l.lo, l.hi, l.power, c, r, l.two_sided, l.one_sided_surface && !l.two_sided, false});
  }
  void add(const Group& g) {
    if (g.empty) return;
    one_facing = (empty || (one_facing && cone.axis == g.cone.axis)) && g.one_facing;
    lo = glm::min(lo, g.lo);
    hi = glm::max(hi, g.hi);
    power += g.power;
    cone = empty ? g.cone : cone_union(cone, g.cone);
    reach = std::max(reach, g.reach);
    two_sided = two_sided || g.two_sided;
    empty = false;
  }

  // The plane of a facing node (abi::kLightTreeFacing): the lowest dot(axis, y) over the corners of
  // the box (so over every point of its lights), less a rounding's slack, so that a point on the
  // lights' plane keeps the bound it had without the plane.
  float front() const {
    if (!one_facing) return -INFINITY;
    const glm::vec3& a = cone.axis;
    float lowest = 0.0f, scale = 0.0f;
    for (int k = 0; k < 3; ++k) {
      lowest += a[k] * (a[k] >= 0.0f ? lo[k] : hi[k]);
      scale += std::abs(a[k]) * std::max(std::abs(lo[k]), std::abs(hi[k]));
    }
    const float front = lowest - 1e-5f * scale;
    return std::isfinite(front) ? front : -INFINITY;
  }
};

// How much a group's light spreads over directions: the solid angle its cone of normals and
// reach sweep, weighed by cosine (Conty Estevez and Kulla 2018, eq. 1).
float orientation_measure(const Group& g) {
  const float o = g.cone.angle;
  const float w = std::min(o + g.reach, kPi);
  return 2.0f * kPi * (1.0f - std::cos(o)) + 0.5f * kPi *
                                                 (2.0f * w * std::sin(o) - std::cos(o - 2.0f * w) -
                                                  2.0f * o * std::sin(o) + std::cos(o));
}

// The cost of a child in a split: power x orientation x surface area, the box padded by a
// fraction of the parent's size (points and flat boxes would cost nothing otherwise).
float split_cost(const Group& g, float pad) {
  if (g.empty) return 0.0f;
  const glm::vec3 d = g.hi - g.lo + glm::vec3(pad);
  const float area = 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  return g.power * orientation_measure(g) * area;
}

// (Halves first: lo + hi of finite extremes could overflow.)
glm::vec3 centre(const LightBounds& l) { return 0.5f * l.lo + 0.5f * l.hi; }

// (cos + 1) / 2 as unorm16, a step below its rounding down: the decoded cone is never narrower
// than the built one, whatever rounding a device's division makes (2.5 ulp in Vulkan).
uint32_t unorm_below(float cos) {
  const float u = std::clamp(0.5f * cos + 0.5f, 0.0f, 1.0f);
  if (u >= 1.0f) return 65535u;
  const uint32_t q = uint32_t(std::floor(u * 65535.0f));
  return q > 0u ? q - 1u : 0u;
}

// The node's sphere: around the box's centre, through its corners, rounded up (with a
// millionth's slack for the device's own rounding of distances).
void set_sphere(abi::LightTreeNode& n, const glm::vec3& lo, const glm::vec3& hi) {
  n.centre = 0.5f * lo + 0.5f * hi;
  const glm::dvec3 half =
      glm::max(glm::dvec3(hi) - glm::dvec3(n.centre), glm::dvec3(n.centre) - glm::dvec3(lo));
  const double r2 = glm::dot(half, half) * (1.0 + 1e-6);
  float f = float(std::min(r2, double(std::numeric_limits<float>::max())));
  if (double(f) < r2) f = std::nextafter(f, INFINITY);
  n.radius2 = f;
}

class Builder {
 public:
  Builder(std::vector<LightBounds>& bounds, std::vector<abi::Light>& lights)
      : m_bounds(bounds), m_lights(lights) {}

  std::vector<abi::LightTreeNode> build() {
    if (m_bounds.empty()) return {};
    m_nodes.emplace_back();
    fill(0, 0, m_bounds.size(), abi::kInvalidIndex, 0, false);
    return std::move(m_nodes);
  }

 private:
  // `by_power`: an ancestor is taken by power (so every node below it is).
  void fill(uint32_t node, size_t begin, size_t end, uint32_t parent, int depth, bool by_power) {
    Group group;
    for (size_t i = begin; i < end; ++i) group.add(m_bounds[i]);
    abi::LightTreeNode n{};
    set_sphere(n, group.lo, group.hi);
    n.power = group.power;
    n.axis = group.cone.axis;
    n.parent = parent;
    const float front = group.front();
    uint32_t flags = group.two_sided ? abi::kLightTreeTwoSided : 0u;
    if (std::isfinite(front)) {
      flags |= abi::kLightTreeFacing;
      n.cone = glm::floatBitsToUint(front);
    } else {
      n.cone = unorm_below(std::cos(group.cone.angle)) | unorm_below(std::cos(group.reach)) << 16;
    }
    if (end - begin == 1) {
      const uint32_t light = m_bounds[begin].light;
      n.child = light | abi::kLightTreeLeaf | flags;
      m_lights[light].treeLeaf = node;
      m_nodes[node] = n;
      return;
    }
    const Split halves = split(begin, end, group, depth < kMaxCostDepth);
    // The surface-area-orientation cost of the node whole against its best split (Conty
    // Estevez and Kulla 2018; Cycles makes such a node a leaf): a split that costs no less
    // divides the lights into groups no smaller in power, cone or box, whose importances at any
    // point stay in about the ratio of their powers. Two triangles of one quad lamp: each
    // triangle's box is the quad's, so each half costs half the whole.
    by_power = by_power ||
               (end - begin <= kMaxPowerLights && halves.cost >= split_cost(group, halves.pad));
    if (by_power) flags |= abi::kLightTreeByPower;
    n.child = uint32_t(m_nodes.size()) | flags;
    m_nodes[node] = n;
    m_nodes.emplace_back();
    m_nodes.emplace_back();
    const uint32_t first = n.child & abi::kLightTreeIndexMask;
    fill(first, begin, halves.middle, node, depth + 1, by_power);
    fill(first + 1, halves.middle, end, node, depth + 1, by_power);
  }

  struct Split {
    size_t middle = 0;
    float cost = INFINITY;  // of the two halves
    float pad = 0.0f;       // the padding split_cost gave their boxes
  };

  // Partitions [begin, end) at the returned index: the cheapest of 11 planes on each axis of
  // the centres' bounds, or the median of the longest axis where no plane separates them (and
  // below kMaxCostDepth, so that no tree grows deeper than that plus log2 of its lights).
  Split split(size_t begin, size_t end, const Group& all, bool by_cost) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (size_t i = begin; i < end; ++i) {
      lo = glm::min(lo, centre(m_bounds[i]));
      hi = glm::max(hi, centre(m_bounds[i]));
    }
    const glm::vec3 extent = hi - lo;
    const float size = std::max({all.hi.x - all.lo.x, all.hi.y - all.lo.y, all.hi.z - all.lo.z});
    const float pad = 1e-3f * size;
    float best_cost = INFINITY;
    int best_axis = -1, best_plane = 0;
    for (int axis = 0; by_cost && axis < 3; ++axis) {
      if (!(extent[axis] > 0.0f)) continue;
      std::array<Group, kBuckets> buckets;
      for (size_t i = begin; i < end; ++i)
        buckets[bucket_of(m_bounds[i], axis, lo, extent)].add(m_bounds[i]);
      // Long thin groups split across their length: the cost is scaled by how far this axis
      // falls short of the longest one.
      const float stretch = std::max({extent.x, extent.y, extent.z}) / extent[axis];
      for (int plane = 0; plane + 1 < kBuckets; ++plane) {
        Group below, above;
        for (int b = 0; b <= plane; ++b) below.add(buckets[b]);
        for (int b = plane + 1; b < kBuckets; ++b) above.add(buckets[b]);
        if (below.empty || above.empty) continue;
        const float cost = stretch * (split_cost(below, pad) + split_cost(above, pad));
        if (cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_plane = plane;
        }
      }
    }
    const auto first = m_bounds.begin() + std::ptrdiff_t(begin);
    const auto last = m_bounds.begin() + std::ptrdiff_t(end);
    if (best_axis >= 0) {
      const auto middle = std::partition(first, last, [&](const LightBounds& l) {
        return bucket_of(l, best_axis, lo, extent) <= best_plane;
      });
      if (middle != first && middle != last)
        return {size_t(middle - m_bounds.begin()), best_cost, pad};
    }
    const int axis = int(std::max_element(&extent.x, &extent.x + 3) - &extent.x);
    const auto middle = first + (last - first) / 2;
    std::nth_element(first, middle, last, [&](const LightBounds& a, const LightBounds& b) {
      return centre(a)[axis] < centre(b)[axis];
    });
    // (Lights sharing a centre may still face apart: a card's two faces.)
    Group below, above;
    for (auto l = first; l != middle; ++l) below.add(*l);
    for (auto l = middle; l != last; ++l) above.add(*l);
    return {size_t(middle - m_bounds.begin()), split_cost(below, pad) + split_cost(above, pad),
            pad};
  }

  static int bucket_of(const LightBounds& l, int axis, const glm::vec3& lo,
                       const glm::vec3& extent) {
    // Clamped as a float: an extent that overflowed to infinity gives NaN, which no int holds.
    const float b = float(kBuckets) * (centre(l)[axis] - lo[axis]) / extent[axis];
    return b >= 0.0f ? int(std::min(b, float(kBuckets - 1))) : 0;
  }

  std::vector<LightBounds>& m_bounds;
  std::vector<abi::Light>& m_lights;
  std::vector<abi::LightTreeNode> m_nodes;
};

}  // namespace

LightBounds light_bounds(const abi::Light& light, float emitted_luminance, bool two_sided) {
  LightBounds b;
  switch (light.type) {
    case abi::kLightTriangle: {
      const glm::vec3 v1 = light.position + light.edge1, v2 = light.position + light.edge2;
      b.lo = glm::min(light.position, glm::min(v1, v2));
      b.hi = glm::max(light.position, glm::max(v1, v2));
      const glm::vec3 n = glm::cross(light.edge1, light.edge2);
      const float length = glm::length(n);
      if (!(length > 0.0f) || !std::isfinite(length)) return b;  // degenerate: no power
      b.axis = n / length;
      b.cos_spread = 1.0f;  // one normal
      b.cos_reach = 0.0f;   // a surface emits up to 90 degrees from it
      b.two_sided = two_sided;
      b.one_sided_surface = !two_sided;
      b.power = emitted_luminance * light.area;
      break;
    }
    case abi::kLightPoint:
      b.lo = b.hi = light.position;
      b.cos_spread = -1.0f;  // every direction
      b.power = luminance(light.intensity);
      break;
    case abi::kLightSpot:
      b.lo = b.hi = light.position;
      b.axis = light.direction;
      b.cos_spread = light.spotCosOuter;  // nothing leaves past the outer cone
      b.cos_reach = 1.0f;
      b.power = luminance(light.intensity);
      break;
    default:
      return b;  // at infinity: not in the tree
  }
  if (!std::isfinite(b.power) || b.power < 0.0f ||
      !std::isfinite(b.lo.x + b.lo.y + b.lo.z + b.hi.x + b.hi.y + b.hi.z))
    b.power = 0.0f;
  // Hostile emitters: capped so that the sums of up to 2^32 of them stay finite in the nodes.
  b.power = std::min(b.power, 1e25f);
  return b;
}

std::vector<abi::LightTreeNode> build_light_tree(std::vector<LightBounds> bounds,
                                                 std::vector<abi::Light>& lights) {
  for (abi::Light& light : lights) light.treeLeaf = abi::kInvalidIndex;
  std::erase_if(bounds, [](const LightBounds& b) { return !(b.power > 0.0f); });
  // 2 L - 1 nodes, each index below the flags of `child`.
  if (bounds.size() > abi::kLightTreeIndexMask / 2u || lights.size() > abi::kLightTreeIndexMask)
    throw std::runtime_error("too many lights for the light tree");
  return Builder(bounds, lights).build();
}

LightTreeNodeCone light_tree_node_cone(const abi::LightTreeNode& node) {
  const glm::vec2 cosines = shader::light_tree_cosines(node.cone, node.child);
  return {cosines.x, cosines.y, shader::light_tree_front(node.cone, node.child),
          (node.child & abi::kLightTreeTwoSided) != 0u};
}

}  // namespace hipr
