// HiPR discovery at every scale: the same room built at 1e-4, 1 and 1e5 (far off the origin),
// the same edit (a block moved next to a mirror and a bright wall), stages 1 and 2 on the GPU.
// Discovery is made of relative quantities (pinhole projection, a depth tolerance relative to
// the G-buffer depth, throughput), so active tiles, discovered tiles and tile weights must agree
// across scales, and the depth test must reject the same hidden vertices everywhere: those on
// the floor behind a thick occluder and on its far faces.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "hipr/edits.h"
#include "hipr/hipr_stages.h"
#include "hipr/renderer.h"
#include "hipr/scene_diff.h"
#include "render/render_readback.h"
#include "shaders/shared/abi.h"
#include "test_support.h"

namespace hipr {
namespace {

constexpr float kScales[] = {1e-4f, 1.0f, 1e5f};

// Unit-scale layout (camera at (-1, 1, 4) looking down -Z):
//   floor y = 0, mirror back wall z = -3, bright right wall x = 1.8, emissive ceiling patch;
//   the block, moved from x in [0.4, 1.1], z in [-2.0, -1.3] toward the mirror and the wall;
//   a thick occluder box in front, x in [-1.8, -0.5], y in [0.5, 1.6], z in [1.6, 2.2]: the
//   camera sees only its front face (it is within the box's x and y ranges), and the floor
//   runs on behind it, hidden.
const glm::vec3 kCamera(-1.0f, 1.0f, 4.0f);
const glm::vec3 kOccluderLo(-1.8f, 0.5f, 1.6f), kOccluderHi(-0.5f, 1.6f, 2.2f);
const glm::vec3 kMove(0.3f, 0.0f, -0.5f);

void add_quad(MeshPrimitive& p, glm::vec3 o, glm::vec3 u, glm::vec3 v) {
  const glm::vec3 n = glm::normalize(glm::cross(u, v));
  const uint32_t base = uint32_t(p.positions.size());
  for (const glm::vec3& corner : {o, o + u, o + u + v, o + v}) {
    p.positions.push_back(corner);
    p.normals.push_back(n);
    p.tangents.emplace_back(glm::normalize(u), 1.0f);
    p.uvs.emplace_back(0.0f);
  }
  p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

void add_box(MeshPrimitive& p, glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 d = hi - lo;
  const glm::vec3 x(d.x, 0, 0), y(0, d.y, 0), z(0, 0, d.z);
  add_quad(p, lo, z, x);      // -y
  add_quad(p, lo + y, x, z);  // +y
  add_quad(p, lo, y, z);      // -x
  add_quad(p, lo + x, z, y);  // +x
  add_quad(p, lo, x, y);      // -z
  add_quad(p, lo + z, y, x);  // +z
}

Material diffuse(const char* name, glm::vec3 color) {
  Material m{name, default_material_params()};
  m.params.base_color = color;
  m.params.specular_weight = 0.0f;
  return m;
}

// The room at `scale`, its origin moved to scale x (3, -2, 1).
Scene room(float scale) {
  Scene scene;
  Material mirror{"mirror", default_material_params()};
  mirror.params.base_color = glm::vec3(0.95f);
  mirror.params.base_metalness = 1.0f;
  mirror.params.specular_roughness = 0.0f;
  Material light = diffuse("light", glm::vec3(0.0f));
  light.params.emission_color = glm::vec3(1.0f);
  light.params.emission_luminance = 20.0f;
  scene.materials = {diffuse("floor", glm::vec3(0.7f)),
                     mirror,
                     diffuse("bright", glm::vec3(0.9f)),
                     light,
                     diffuse("block", glm::vec3(0.8f, 0.3f, 0.1f)),
                     diffuse("occluder", glm::vec3(0.5f))};
  const auto mesh = [&](const char* name, uint32_t material, auto build) {
    MeshPrimitive p;
    p.material = material;
    build(p);
    scene.meshes.push_back({name, {p}});
    Node node;
    node.name = name;
    node.mesh = int(scene.meshes.size() - 1);
    scene.nodes.push_back(node);
  };
  mesh("floor", 0, [](MeshPrimitive& p) { add_quad(p, {-3, 0, -3}, {0, 0, 4.2f}, {4.8f, 0, 0}); });
  mesh("mirror", 1, [](MeshPrimitive& p) { add_quad(p, {-3, 0, -3}, {4.8f, 0, 0}, {0, 3, 0}); });
  mesh("bright_wall", 2, [](MeshPrimitive& p) {
    add_quad(p, {1.8f, 0, -3}, {0, 3, 0}, {0, 0, 4.2f});
  });
  mesh("light", 3, [](MeshPrimitive& p) { add_quad(p, {-1, 3, -2}, {2, 0, 0}, {0, 0, 1.5f}); });
  mesh("block", 4, [](MeshPrimitive& p) { add_box(p, {0.4f, 0, -2.0f}, {1.1f, 0.7f, -1.3f}); });
  mesh("occluder", 5, [](MeshPrimitive& p) { add_box(p, kOccluderLo, kOccluderHi); });
  Node camera;
  camera.name = "camera";
  camera.camera = 0;
  camera.local = glm::translate(glm::mat4(1.0f), kCamera);
  scene.nodes.push_back(camera);
  scene.cameras.push_back(Camera{"camera", glm::mat4(1.0f), 0.8f, 0.01f});

  const glm::mat4 world = glm::scale(
      glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, -2.0f, 1.0f) * scale), glm::vec3(scale));
  for (uint32_t n = 0; n < scene.nodes.size(); ++n) {
    scene.nodes[n].local = world * scene.nodes[n].local;
    scene.root_nodes.push_back(n);
    scene.children.emplace_back();
  }
  return scene;
}

RenderSettings settings() { return test::render_settings(64, 48, 4, 8, 21); }

struct Discovery {
  std::vector<uint32_t> flags;
  std::vector<double> weights;
  std::vector<uint32_t> instances;  // G-buffer after the edit
};

// Stages 1 and 2 after moving the block, as hipr_stages_test does it.
Discovery discover(float scale, const RenderSettings& s = settings()) {
  const Scene before = room(scale);
  Scene after = before;
  apply_edit(after, TransformEdit{"block", kMove * scale, std::nullopt});
  Renderer renderer(test::context(), before, s);
  renderer.add_samples_full_frame(1);
  hipr_stages(renderer).stage1_visibility({});
  renderer.update_scene(after, diff_scenes(before, after));
  renderer.mark_all_owed();
  hipr_stages(renderer).stage1_visibility(diff_scenes(before, after));
  test::discover_all(renderer, 4);
  EXPECT_EQ(renderer.counters().non_finite_samples, 0u) << "scale " << scale;
  return {read_tile_flags(renderer), read_tile_weights(renderer), renderer.gbuffer_instances()};
}

// Tiles at least one tile away from the border of the occluder's front face on screen: every
// path vertex that projects there lies on the hidden floor or on the occluder's far faces.
std::vector<bool> occluder_interior_tiles(const RenderSettings& s) {
  const float tan_y = std::tan(0.4f), tan_x = tan_y * float(s.width) / float(s.height);
  const float depth = kCamera.z - kOccluderHi.z;
  const auto px = [&](float x) {
    return ((x - kCamera.x) / depth / tan_x + 1.0f) * 0.5f * float(s.width);
  };
  const auto py = [&](float y) {
    return (1.0f - (y - kCamera.y) / depth / tan_y) * 0.5f * float(s.height);
  };
  const uint32_t tiles_x = (s.width + s.tile_size - 1) / s.tile_size;
  const uint32_t tiles_y = (s.height + s.tile_size - 1) / s.tile_size;
  std::vector<bool> interior(size_t(tiles_x) * tiles_y, false);
  for (uint32_t ty = 0; ty < tiles_y; ++ty)
    for (uint32_t tx = 0; tx < tiles_x; ++tx) {
      const float t = float(s.tile_size);
      interior[ty * tiles_x + tx] =
          float(tx) * t >= px(kOccluderLo.x) + t && float(tx + 1) * t <= px(kOccluderHi.x) - t &&
          float(ty) * t >= py(kOccluderHi.y) + t && float(ty + 1) * t <= py(kOccluderLo.y) - t;
    }
  return interior;
}

TEST(DiscoveryAtEveryScale, SameTilesAndWeightsAndTheSameRejections) {
  const RenderSettings s = settings();
  const std::vector<bool> interior = occluder_interior_tiles(s);
  ASSERT_GE(std::count(interior.begin(), interior.end(), true), 4)
      << "the occluder must cover whole tiles";
  const Discovery unit = discover(1.0f);
  size_t active = 0, discovered = 0;
  double total = 0.0;
  for (size_t t = 0; t < unit.flags.size(); ++t) {
    active += (unit.flags[t] & abi::kTileActive) ? 1 : 0;
    discovered += (unit.flags[t] & abi::kTileDiscovered) ? 1 : 0;
    total += unit.weights[t];
  }
  ASSERT_GT(active, 0u);
  ASSERT_GT(discovered, active) << "the move must be discovered beyond the block's own tiles";
  ASSERT_GT(total, 0.0);

  for (float scale : kScales) {
    const Discovery d = scale == 1.0f ? unit : discover(scale);
    size_t pixels_differ = 0;
    for (size_t i = 0; i < d.instances.size(); ++i)
      pixels_differ += d.instances[i] != unit.instances[i] ? 1 : 0;
    EXPECT_LE(pixels_differ, d.instances.size() / 200) << "G-buffer at scale " << scale;
    size_t flags_differ = 0;
    double weight_difference = 0.0;
    for (size_t t = 0; t < d.flags.size(); ++t) {
      EXPECT_EQ(d.flags[t] & abi::kTileActive, unit.flags[t] & abi::kTileActive)
          << "tile " << t << ", scale " << scale;
      flags_differ +=
          (d.flags[t] & abi::kTileDiscovered) != (unit.flags[t] & abi::kTileDiscovered) ? 1 : 0;
      weight_difference += std::abs(d.weights[t] - unit.weights[t]);
      // The depth test rejects every vertex behind the occluder's front face.
      if (interior[t]) {
        EXPECT_EQ(d.flags[t] & abi::kTileDiscovered, 0u)
            << "occluder tile " << t << ", scale " << scale;
        EXPECT_EQ(d.weights[t], 0.0) << "occluder tile " << t << ", scale " << scale;
      }
    }
    EXPECT_LE(flags_differ, discovered / 20) << "discovered tiles at scale " << scale;
    EXPECT_LE(weight_difference, 0.02 * total) << "tile weights at scale " << scale;
  }
}

TEST(DiscoveryAtEveryScale, WithoutTheDepthTestHiddenVerticesDiscoverTheOccluder) {
  // The control: accepting any depth, the vertices the test above sees rejected do reach the
  // occluder's tiles, at every scale.
  RenderSettings s = settings();
  s.hipr.depth_epsilon = 1e3f;
  const std::vector<bool> interior = occluder_interior_tiles(s);
  for (float scale : kScales) {
    const Discovery d = discover(scale, s);
    size_t found = 0;
    for (size_t t = 0; t < d.flags.size(); ++t)
      found += interior[t] && (d.flags[t] & abi::kTileDiscovered) ? 1 : 0;
    EXPECT_GT(found, 0u) << "scale " << scale;
  }
}

}  // namespace
}  // namespace hipr
