#include "fuzz_inputs.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "core/error.h"
#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "image/builtin_environments.h"
#include "image/environment_loader.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/bvh_builder.h"
#include "render/light_groups.h"
#include "render/light_tables.h"
#include "scene/default_camera.h"

namespace hipr::fuzz {
namespace {

std::filesystem::path write_alone(const uint8_t* data, size_t size,
                                  const std::filesystem::path& folder, const std::string& name) {
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::filesystem::path path = folder / name;
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

bool starts_with(const uint8_t* data, size_t size, const char* magic, size_t length) {
  return size >= length && std::memcmp(data, magic, length) == 0;
}

// A broken invariant is a finding: the fuzzer (and the regression test) stop at it.
void require(bool condition) {
  if (!condition) __builtin_trap();
}

void require_tree(const Bvh& bvh, size_t items) {
  std::vector<bool> seen(items, false);
  for (const uint32_t item : bvh.order) {
    require(item < items && !seen[item]);
    seen[item] = true;
  }
  require(bvh.order.size() == items && !bvh.nodes.empty());
}

// What GpuScene derives from a scene on the host (src/render/gpu_scene.cpp, software_bvh.cpp),
// at no device: a BVH per mesh over its triangles and one over the instances' world boxes (the
// software traversal's), the light tables with their CDF, the camera. Each kernel indexes by
// what these hold, so each must be whole and finite.
void derive_gpu_scene(const Scene& scene) {
  std::vector<Box> mesh_boxes;
  for (const Mesh& mesh : scene.meshes) {
    std::vector<Box> triangles;
    Box whole;
    for (const MeshPrimitive& primitive : mesh.primitives)
      for (size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
        Box triangle;
        for (size_t k = 0; k < 3; ++k) {
          require(primitive.indices[i + k] < primitive.positions.size());
          triangle.grow(primitive.positions[primitive.indices[i + k]]);
        }
        triangles.push_back(triangle);
        whole.grow(triangle);
      }
    require_tree(build_bvh(triangles), triangles.size());
    mesh_boxes.push_back(whole);
  }
  const std::vector<Instance> instances = scene.instances();
  std::vector<uint32_t> record_base;
  uint32_t records = 0;
  std::vector<Box> instance_boxes;
  for (const Instance& instance : instances) {
    record_base.push_back(records);
    records += uint32_t(scene.meshes[instance.mesh].primitives.size());
    if (!instance.visible) continue;
    const Box& local = mesh_boxes[instance.mesh];
    Box world;
    for (int corner = 0; corner < 8; ++corner)
      world.grow(
          glm::vec3(instance.world * glm::vec4((corner & 1) ? local.hi.x : local.lo.x,
                                               (corner & 2) ? local.hi.y : local.lo.y,
                                               (corner & 4) ? local.hi.z : local.lo.z, 1.0f)));
    instance_boxes.push_back(world);
  }
  require_tree(build_bvh(instance_boxes), instance_boxes.size());
  const auto [lo, hi] = scene.bounds();
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
  require(std::isfinite(radius));
  const float environment_mean =
      scene.environment ? environment_mean_luminance(*scene.environment) : 0.0f;
  const LightTables tables = build_light_tables(scene, instances, record_base, records, radius,
                                                environment_mean, assign_light_groups(scene, 8));
  // Two CDFs (over every light; over the lights the tree does not hold), each from 0 to 1.
  const size_t n = tables.lights.size() + 1;
  require(tables.cdf.size() == 2 * n && tables.tree_cdf_offset() == n);
  for (size_t c = 0; c < 2; ++c)
    for (size_t i = 1; i < n; ++i)
      require(std::isfinite(tables.cdf[c * n + i]) &&
              tables.cdf[c * n + i] >= tables.cdf[c * n + i - 1]);
  require(tables.tree_probability >= 0.0f && tables.tree_probability <= 1.0f);
  // The light tree: every leaf names a light that names it back, children within the tree.
  for (size_t node = 0; node < tables.tree.size(); ++node) {
    const abi::LightTreeNode& t = tables.tree[node];
    require(std::isfinite(t.power) && t.power > 0.0f && t.radius2 >= 0.0f);
    const uint32_t index = t.child & abi::kLightTreeIndexMask;  // without the node's flags
    if (t.child & abi::kLightTreeLeaf) {
      require(index < tables.lights.size() && tables.lights[index].treeLeaf == node);
    } else {
      require(index > node && size_t(index) + 1 < tables.tree.size());
    }
  }
  const Camera camera = resolve_camera(scene);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) require(std::isfinite(camera.camera_to_world[c][r]));
}

void apply_all(Scene scene, const std::vector<Edit>& edits) {
  for (const Edit& edit : edits) {
    if (const auto* e = std::get_if<EnvironmentEdit>(&edit))
      if (e->source && !is_environment_name(*e->source)) continue;
    try {
      const Scene before = scene;
      const Edit inverse = inverse_edit(scene, edit);
      apply_edit(scene, edit);
      (void)diff_scenes(before, scene);
      apply_edit(scene, inverse);
      (void)diff_scenes(before, scene);
      apply_edit(scene, edit);  // the next edit starts from this one
      derive_gpu_scene(scene);
    } catch (const InputError&) {
    }
  }
}

}  // namespace

void load_gltf_bytes(const uint8_t* data, size_t size, const std::filesystem::path& folder) {
  const bool glb = starts_with(data, size, "glTF", 4);
  const std::filesystem::path path =
      write_alone(data, size, folder, glb ? "scene.glb" : "scene.gltf");
  try {
    const Scene scene = load_scene(path, {.environment = kNoEnvironment});
    derive_gpu_scene(scene);
  } catch (const InputError&) {
  }
}

void apply_edit_script_bytes(const uint8_t* data, size_t size,
                             const std::filesystem::path& assets) {
  static const Scene cornell =
      load_scene(assets / "cornell_box.gltf", {.environment = kNoEnvironment});
  static const Scene furnace =
      load_scene(assets / "furnace_sphere.gltf", {.environment = "studio"});
  std::vector<Edit> edits;
  try {
    edits = parse_edit_script(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const InputError&) {
    return;
  }
  apply_all(cornell, edits);
  apply_all(furnace, edits);
}

void load_environment_bytes(const uint8_t* data, size_t size, const std::filesystem::path& folder) {
  const bool exr = starts_with(data, size, "\x76\x2f\x31\x01", 4);
  const std::filesystem::path path = write_alone(data, size, folder, exr ? "map.exr" : "map.hdr");
  try {
    (void)load_environment(path);
  } catch (const InputError&) {
  }
}

void read_image_bytes(const uint8_t* data, size_t size, const std::filesystem::path& folder) {
  // The name says PNG; the content picks the reader (image_reader.h).
  const std::filesystem::path path = write_alone(data, size, folder, "image.png");
  ImageRGB image;
  try {
    image = read_image(path);
  } catch (const InputError&) {
    return;
  }
  require(image.width > 0 && image.height > 0 &&
          image.rgb.size() == size_t(image.width) * image.height * 3);
  // FLIP filters every pixel: larger images would slow the fuzzer without reaching new code.
  if (image.rgb.size() > 3 * 4096) return;
  ImageRGB off = image;
  off.rgb[0] = off.rgb[0] + 0.5f;
  for (const CompareMetric metric :
       {CompareMetric::Flip, CompareMetric::RelMse, CompareMetric::Rmse, CompareMetric::Max})
    for (const ImageRGB* other : {&image, &off}) {
      const ImageComparison same = compare_images(image, *other, metric, 0.0, 99.0);
      const ImageComparison whole = compare_images(image, *other, metric, 0.0);
      require(same.pixel_error.size() == size_t(image.width) * image.height);
      require(!std::isnan(whole.value) && !std::isnan(same.value));
      // A finite image is the same as itself.
      if (other == &image && whole.nonfinite_pixels == 0) require(whole.value == 0.0);
    }
}

}  // namespace hipr::fuzz
