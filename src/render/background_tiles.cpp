#include "render/background_tiles.h"

#include <algorithm>
#include <cmath>

#include "scene/default_camera.h"

namespace hipr {
namespace {

// Relative padding of world bounds: far above the float rounding of the GPU's transforms and hits.
constexpr double kBoundsPadding = 1e-5;
// Triangles per leaf of a mesh's box tree: at least this many, and leaves at most that many
// (huge meshes have triangles far below a pixel; their tree stays small and quick to build).
constexpr size_t kLeafTriangles = 8;
constexpr size_t kMaxLeaves = 8192;

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::dvec3 corner(const glm::dvec3& lo, const glm::dvec3& hi, int i) {
  return {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
}

// The camera as the kernel gets it (make_frame_params in renderer.cpp): the ray through pixel
// coordinates (px, py) has direction F + sx R + sy U, with sx = (2 px / width - 1) tan_x and
// sy = (1 - 2 py / height) tan_y. Camera coordinates (x, y, z) of a point P solve
// P - origin = x R + y U + z F, so the ray's points have z = t > 0, x = sx z, y = sy z.
struct View {
  glm::dvec3 origin;
  glm::dmat3 to_camera;
  double tan_x, tan_y;
  double width, height;
};

// Where in the image (pixel coordinates) rays can reach a world box.
struct Footprint {
  enum Kind { Nowhere, Rectangle, Everywhere } kind = Nowhere;
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

Footprint footprint(const View& view, const glm::dvec3& lo, const glm::dvec3& hi) {
  glm::dvec3 q[8], q_lo(HUGE_VAL), q_hi(-HUGE_VAL);
  double reach = 0.0;
  for (int i = 0; i < 8; ++i) {
    q[i] = view.to_camera * (corner(lo, hi, i) - view.origin);
    q_lo = glm::min(q_lo, q[i]);
    q_hi = glm::max(q_hi, q[i]);
    reach = std::max(reach, glm::length(q[i]));
  }
  if (!finite(q_lo) || !finite(q_hi)) return {Footprint::Everywhere};
  if (q_hi.z <= 0.0) return {};  // wholly behind the camera: rays only go forward
  // Between the camera and a plane just ahead of it the view is a tiny pyramid; a box reaching
  // into its bounds may be hit in any direction.
  const double near = 1e-4 * reach;
  const double fx = 1.01 * view.tan_x, fy = 1.01 * view.tan_y;  // the whole image, with a margin
  if (q_lo.z < near && q_lo.x <= near * fx && q_hi.x >= -near * fx && q_lo.y <= near * fy &&
      q_hi.y >= -near * fy)
    return {Footprint::Everywhere};
  // Beyond the plane the box projects inside the rectangle of its corners there and of the
  // points where its edges cross the plane; nearer, it is outside the view (just checked).
  double sx0 = HUGE_VAL, sx1 = -HUGE_VAL, sy0 = HUGE_VAL, sy1 = -HUGE_VAL;
  const auto project = [&](const glm::dvec3& c) {
    sx0 = std::min(sx0, c.x / c.z);
    sx1 = std::max(sx1, c.x / c.z);
    sy0 = std::min(sy0, c.y / c.z);
    sy1 = std::max(sy1, c.y / c.z);
  };
  for (int i = 0; i < 8; ++i) {
    if (q[i].z >= near) project(q[i]);
    for (int axis = 1; axis < 8; axis <<= 1) {  // each edge once, from its lower corner
      if (i & axis) continue;
      const glm::dvec3& a = q[i];
      const glm::dvec3& b = q[i | axis];
      if ((a.z - near) * (b.z - near) < 0.0) project(a + (b - a) * ((near - a.z) / (b.z - a.z)));
    }
  }
  if (!(sx0 <= sx1)) return {};
  return {Footprint::Rectangle, (sx0 / view.tan_x + 1.0) * 0.5 * view.width,
          (sx1 / view.tan_x + 1.0) * 0.5 * view.width, (1.0 - sy1 / view.tan_y) * 0.5 * view.height,
          (1.0 - sy0 / view.tan_y) * 0.5 * view.height};
}

// The world box of an object box under `world`, padded by kBoundsPadding x `magnitude`.
std::pair<glm::dvec3, glm::dvec3> world_box(const glm::dmat4& world, const glm::dvec3& lo,
                                            const glm::dvec3& hi, double magnitude) {
  glm::dvec3 w_lo(HUGE_VAL), w_hi(-HUGE_VAL);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 w(world * glm::dvec4(corner(lo, hi, i), 1.0));
    w_lo = glm::min(w_lo, w);
    w_hi = glm::max(w_hi, w);
  }
  return {w_lo - glm::dvec3(kBoundsPadding * magnitude),
          w_hi + glm::dvec3(kBoundsPadding * magnitude)};
}

}  // namespace

uint32_t BackgroundTiles::build_tree(std::vector<Node>& nodes, size_t leaf_size,
                                     std::vector<Triangle>::iterator first,
                                     std::vector<Triangle>::iterator last) {
  const uint32_t index = uint32_t(nodes.size());
  nodes.emplace_back();
  if (size_t(last - first) <= leaf_size) {
    Box box{glm::vec3(HUGE_VALF), glm::vec3(-HUGE_VALF)};
    for (auto it = first; it != last; ++it)
      box = {glm::min(box.first, it->box.first), glm::max(box.second, it->box.second)};
    nodes[index].box = box;
    return index;
  }
  // Median split along the longest axis of the centres.
  glm::vec3 c_lo(HUGE_VALF), c_hi(-HUGE_VALF);
  for (auto it = first; it != last; ++it) {
    c_lo = glm::min(c_lo, it->centre);
    c_hi = glm::max(c_hi, it->centre);
  }
  const glm::vec3 spread = c_hi - c_lo;
  const int axis =
      spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
  const auto middle = first + (last - first) / 2;
  std::nth_element(first, middle, last, [axis](const Triangle& a, const Triangle& b) {
    return a.centre[axis] < b.centre[axis];
  });
  const uint32_t left = build_tree(nodes, leaf_size, first, middle);
  const uint32_t right = build_tree(nodes, leaf_size, middle, last);
  nodes[index].box = {glm::min(nodes[left].box.first, nodes[right].box.first),
                      glm::max(nodes[left].box.second, nodes[right].box.second)};
  nodes[index].left = left;
  nodes[index].right = right;
  nodes[index].leaf = false;
  return index;
}

BackgroundTiles::BackgroundTiles(const Scene& scene) { update_meshes(scene); }

void BackgroundTiles::update_meshes(const Scene& scene) {
  const size_t built = m_meshes.size();  // meshes [0, built) have trees, of m_revisions
  m_meshes.resize(scene.meshes.size());
  m_revisions.resize(scene.meshes.size(), 0);
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    if (m < built && m_revisions[m] == scene.meshes[m].revision) continue;
    m_meshes[m] = build_mesh_tree(scene.meshes[m]);
    m_revisions[m] = scene.meshes[m].revision;
  }
}

BackgroundTiles::MeshTree BackgroundTiles::build_mesh_tree(const Mesh& mesh) {
  MeshTree tree;
  std::vector<Triangle> triangles;
  for (const MeshPrimitive& p : mesh.primitives)
    for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
      Triangle triangle{{glm::vec3(HUGE_VALF), glm::vec3(-HUGE_VALF)}, glm::vec3(0.0f)};
      for (size_t k = 0; k < 3; ++k) {
        if (p.indices[t + k] >= p.positions.size()) continue;  // the loader rejects these
        const glm::vec3& v = p.positions[p.indices[t + k]];
        tree.unbounded = tree.unbounded || !finite(glm::dvec3(v));
        triangle.box = {glm::min(triangle.box.first, v), glm::max(triangle.box.second, v)};
      }
      triangle.centre = 0.5f * (triangle.box.first + triangle.box.second);
      if (triangle.box.first.x <= triangle.box.second.x) triangles.push_back(triangle);
    }
  if (!triangles.empty() && !tree.unbounded) {
    const size_t leaf_size = std::max(kLeafTriangles, triangles.size() / kMaxLeaves);
    build_tree(tree.nodes, leaf_size, triangles.begin(), triangles.end());
  }
  return tree;
}

std::vector<uint32_t> BackgroundTiles::mask(const Scene& scene, uint32_t width, uint32_t height,
                                            uint32_t tile_size) const {
  const uint32_t tiles_x = (width + tile_size - 1) / tile_size;
  const uint32_t tiles_y = (height + tile_size - 1) / tile_size;
  std::vector<uint32_t> mask(size_t(tiles_x) * tiles_y, 1u);
  const auto nothing_is_background = [&] {
    std::fill(mask.begin(), mask.end(), 0u);
    return mask;
  };

  const Camera camera = resolve_camera(scene);
  View view;
  view.origin = glm::dvec3(glm::vec3(camera.camera_to_world[3]));
  const glm::dmat3 frame(glm::dvec3(glm::normalize(glm::vec3(camera.camera_to_world[0]))),
                         glm::dvec3(glm::normalize(glm::vec3(camera.camera_to_world[1]))),
                         glm::dvec3(-glm::normalize(glm::vec3(camera.camera_to_world[2]))));
  view.tan_y = std::tan(0.5f * camera.yfov);
  view.tan_x = view.tan_y * double(float(width) / float(height));
  view.width = width;
  view.height = height;
  const double det = glm::determinant(frame);
  if (!std::isfinite(det) || std::abs(det) < 1e-6 || !finite(view.origin) || !(view.tan_x > 0.0) ||
      !(view.tan_y > 0.0) || !std::isfinite(view.tan_x) || !std::isfinite(view.tan_y))
    return nothing_is_background();
  view.to_camera = glm::inverse(frame);

  // Tile range of the pixels whose rays cover part of a footprint, one pixel wider on every side.
  struct TileRange {
    int64_t x0, x1, y0, y1;  // inclusive; empty when x0 > x1 or y0 > y1
  };
  const auto tiles_of = [&](const Footprint& f) {
    const auto pixels = [](double lo, double hi, uint32_t size) {
      const double first = std::floor(std::clamp(lo, -2.0, double(size) + 2.0)) - 1.0;
      const double last = std::floor(std::clamp(hi, -2.0, double(size) + 2.0)) + 1.0;
      return std::pair<int64_t, int64_t>(std::max<int64_t>(int64_t(first), 0),
                                         std::min<int64_t>(int64_t(last), int64_t(size) - 1));
    };
    const auto [px0, px1] = pixels(f.x0, f.x1, width);
    const auto [py0, py1] = pixels(f.y0, f.y1, height);
    const int64_t t = tile_size;
    if (px0 > px1 || py0 > py1) return TileRange{0, -1, 0, -1};
    return TileRange{px0 / t, px1 / t, py0 / t, py1 / t};
  };
  const auto any_background = [&](const TileRange& r) {
    for (int64_t ty = r.y0; ty <= r.y1; ++ty)
      for (int64_t tx = r.x0; tx <= r.x1; ++tx)
        if (mask[size_t(ty) * tiles_x + size_t(tx)]) return true;
    return false;
  };
  const auto cover = [&](const TileRange& r) {
    for (int64_t ty = r.y0; ty <= r.y1; ++ty)
      for (int64_t tx = r.x0; tx <= r.x1; ++tx) mask[size_t(ty) * tiles_x + size_t(tx)] = 0u;
  };

  for (const Instance& instance : scene.instances()) {
    if (!instance.visible) continue;
    if (instance.mesh >= m_meshes.size())
      return nothing_is_background();  // not bounded yet: anywhere
    const MeshTree& tree = m_meshes[instance.mesh];
    if (tree.unbounded) return nothing_is_background();
    if (tree.nodes.empty()) continue;
    const glm::dmat4 world(instance.world);
    const auto [lo, hi] = world_box(world, glm::dvec3(tree.nodes[0].box.first),
                                    glm::dvec3(tree.nodes[0].box.second), 0.0);
    if (!finite(lo) || !finite(hi)) return nothing_is_background();
    const double magnitude = std::max({glm::length(hi - lo), glm::length(lo - view.origin),
                                       glm::length(hi - view.origin), glm::length(view.origin)});
    // Depth-first down the tree, only where a box covers tiles still marked background.
    std::vector<uint32_t> stack = {0};
    while (!stack.empty()) {
      const Node& node = tree.nodes[stack.back()];
      stack.pop_back();
      const auto [b_lo, b_hi] =
          world_box(world, glm::dvec3(node.box.first), glm::dvec3(node.box.second), magnitude);
      const Footprint f = footprint(view, b_lo, b_hi);
      if (f.kind == Footprint::Everywhere) return nothing_is_background();
      if (f.kind == Footprint::Nowhere) continue;
      const TileRange range = tiles_of(f);
      if (!any_background(range)) continue;  // nothing left to decide there
      if (node.leaf) {
        cover(range);
      } else {
        stack.push_back(node.left);
        stack.push_back(node.right);
      }
    }
  }
  return mask;
}

}  // namespace hipr
