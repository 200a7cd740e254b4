#include "test_support.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>

#include "hipr/hipr_stages.h"

namespace hipr::test {
namespace fs = std::filesystem;

fs::path asset(const std::string& name) { return fs::path(HIPR_ASSETS_DIR) / name; }
fs::path shared_scene(const std::string& name) { return fs::path(HIPR_SHARED_SCENES_DIR) / name; }
bool shared_scenes_available() { return fs::is_directory(HIPR_SHARED_SCENES_DIR); }

namespace {

std::vector<fs::path>& created_temp_dirs() {
  static std::vector<fs::path> dirs;
  return dirs;
}

}  // namespace

fs::path temp_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("hipr-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  created_temp_dirs().push_back(dir);
  return dir;
}

bool gltf_validator_required() {
  const char* required = std::getenv("HIPR_REQUIRE_GLTF_VALIDATOR");
  return required && std::string(required) == "1";
}

fs::path camera_less_cornell_box(const fs::path& dir) {
  nlohmann::json gltf;
  std::ifstream(asset("cornell_box.gltf")) >> gltf;
  gltf.erase("cameras");
  for (auto& node : gltf["nodes"]) node.erase("camera");
  fs::copy_file(asset("cornell_box.bin"), dir / "cornell_box.bin",
                fs::copy_options::overwrite_existing);
  const fs::path path = dir / "cornell_no_camera.gltf";
  std::ofstream(path) << gltf.dump(2);
  return path;
}

namespace {

std::unique_ptr<vk::Context>& context_slot() {
  static std::unique_ptr<vk::Context> ctx;
  return ctx;
}

// Checks validation errors and removes temporary folders once all tests of the binary ran.
class ValidationEnvironment : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ignored;
    for (const fs::path& dir : created_temp_dirs()) fs::remove_all(dir, ignored);
    if (auto& ctx = context_slot()) {
      EXPECT_EQ(ctx->validation_errors(), 0u) << "the Vulkan validation layer reported errors";
      ctx.reset();
    }
  }
};

[[maybe_unused]] ::testing::Environment* const g_validation =
    ::testing::AddGlobalTestEnvironment(new ValidationEnvironment);

}  // namespace

const vk::Context& context() {
  auto& ctx = context_slot();
  if (!ctx) {
    vk::ContextOptions options;
    options.validation = true;
    ctx = std::make_unique<vk::Context>(options);
  }
  return *ctx;
}

RenderSettings render_settings(uint32_t width, uint32_t height, uint32_t tile_size,
                               uint32_t max_depth, uint32_t seed) {
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.tile_size = tile_size;
  s.max_depth = max_depth;
  s.seed = seed;
  return s;
}

ChangeSet edit_scene(Scene& scene, const Edit& edit) {
  const Scene before = diff_snapshot(scene);
  apply_edit(scene, edit);
  return diff_scenes(before, scene);
}

void expect_update_matches_fresh(Renderer& renderer, Scene& scene, const Edit& edit, uint32_t spp) {
  const auto fresh_render = [&](const Scene& s) {
    Renderer fresh(context(), s, renderer.settings());
    fresh.add_samples_full_frame(spp);
    return fresh.image();
  };
  const ImageRGB before = fresh_render(scene);
  const ChangeSet changes = edit_scene(scene, edit);
  EXPECT_FALSE(changes.empty()) << describe(edit);
  renderer.update_scene(scene, changes);
  renderer.reset();
  renderer.add_samples_full_frame(spp);
  const ImageRGB fresh = fresh_render(scene);
  EXPECT_EQ(renderer.image().rgb, fresh.rgb) << describe(edit);
  EXPECT_NE(before.rgb, fresh.rgb) << describe(edit) << " changed nothing visible";
}

void discover_all(Renderer& renderer, uint32_t samples_per_pixel) {
  HiprStageRunner& stages = hipr_stages(renderer);
  stages.build_schedule();
  stages.stage2_discover(0, renderer.tile_count(), samples_per_pixel);
}

CommandResult run_hipr(const std::string& arguments) {
  return run_command(std::string("'") + HIPR_BINARY + "' " + arguments);
}

fs::path hipr_binary() { return HIPR_BINARY; }

CommandResult run_command(const std::string& command_line) {
  const std::string command = command_line + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

double mean(const ImageRGB& image, int channel) {
  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < image.rgb.size(); ++i) {
    if (channel >= 0 && int(i % 3) != channel) continue;
    sum += image.rgb[i];
    ++count;
  }
  return count ? sum / double(count) : 0.0;
}

bool all_finite(const ImageRGB& image) {
  for (float v : image.rgb)
    if (!std::isfinite(v)) return false;
  return true;
}

ImageRGB full_frame_display(const Scene& scene, const RenderSettings& settings, uint32_t spp) {
  Renderer renderer(context(), scene, settings);
  renderer.add_samples_full_frame(spp);
  renderer.resolve_display_all(DisplayRule::Immediate);
  return renderer.displayed_image();
}

ImageRGB render_finite(const Scene& scene, const RenderSettings& settings, uint32_t spp) {
  Renderer renderer(context(), scene, settings);
  renderer.add_samples_full_frame(spp);
  EXPECT_EQ(renderer.counters().non_finite_samples, 0u);
  ImageRGB image = renderer.image();
  EXPECT_TRUE(all_finite(image));
  return image;
}

}  // namespace hipr::test

namespace hipr::test {

Scene make_furnace_scene(float radius, glm::vec3 center, float albedo, float env) {
  Scene scene;
  MeshPrimitive sphere;
  constexpr int kRings = 48, kSegments = 96;
  for (int r = 0; r <= kRings; ++r) {
    const float theta = float(M_PI) * float(r) / kRings;
    for (int s = 0; s <= kSegments; ++s) {
      const float phi = 2.0f * float(M_PI) * float(s) / kSegments;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
      sphere.positions.push_back(n);
      sphere.normals.push_back(n);
      sphere.tangents.push_back(glm::vec4(-std::sin(phi), 0.0f, std::cos(phi), 1.0f));
      sphere.uvs.push_back(glm::vec2(float(s) / kSegments, float(r) / kRings));
    }
  }
  for (int r = 0; r < kRings; ++r)
    for (int s = 0; s < kSegments; ++s) {
      const uint32_t a = uint32_t(r * (kSegments + 1) + s), b = a + kSegments + 1;
      sphere.indices.insert(sphere.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  Material white;
  white.name = "white";
  white.params = default_material_params();
  white.params.base_color = glm::vec3(albedo);
  white.params.specular_weight = 0.0f;
  scene.materials.push_back(white);
  scene.meshes.push_back({"sphere", {sphere}});

  Node node;
  node.name = "sphere";
  node.mesh = 0;
  node.local =
      glm::translate(glm::mat4(1.0f), center) * glm::scale(glm::mat4(1.0f), glm::vec3(radius));
  Node camera_node;
  camera_node.name = "camera";
  camera_node.camera = 0;
  camera_node.local =
      glm::translate(glm::mat4(1.0f), center + glm::vec3(0.0f, 0.0f, 4.0f * radius));
  scene.nodes = {node, camera_node};
  scene.children = {{}, {}};
  scene.root_nodes = {0, 1};
  Camera camera;
  camera.yfov = 0.6f;
  scene.cameras.push_back(camera);

  scene.environment = uniform_environment(env);
  return scene;
}

Environment uniform_environment(float radiance) {
  Environment environment;
  environment.width = 8;
  environment.height = 4;
  environment.texels.assign(32, glm::vec3(radiance));
  return environment;
}

std::vector<uint32_t> grid_triangles(uint32_t n, uint32_t shuffle_seed) {
  std::vector<std::array<uint32_t, 3>> triangles;
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) {
      const uint32_t a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  if (shuffle_seed != 0) {
    std::mt19937 rng(shuffle_seed);
    std::shuffle(triangles.begin(), triangles.end(), rng);
  }
  std::vector<uint32_t> indices;
  for (const auto& t : triangles) indices.insert(indices.end(), t.begin(), t.end());
  return indices;
}

}  // namespace hipr::test

namespace hipr::test {

std::vector<double> block_means(const ImageRGB& image, uint32_t b) {
  std::vector<double> out;
  for (uint32_t by = 0; by + b <= image.height; by += b)
    for (uint32_t bx = 0; bx + b <= image.width; bx += b) {
      double sum = 0.0;
      for (uint32_t y = by; y < by + b; ++y)
        for (uint32_t x = bx; x < bx + b; ++x)
          for (size_t c = 0; c < 3; ++c) sum += image.rgb[(size_t(y) * image.width + x) * 3 + c];
      out.push_back(sum / double(3 * b * b));
    }
  return out;
}

ImageRGB average(const ImageRGB& a, const ImageRGB& b) {
  ImageRGB out = a;
  for (size_t i = 0; i < out.rgb.size(); ++i) out.rgb[i] = 0.5f * (a.rgb[i] + b.rgb[i]);
  return out;
}

double error_to_noise_ratio(const std::vector<ImageRGB>& renders, const ImageRGB& reference) {
  const size_t k = renders.size();
  std::vector<std::vector<double>> blocks;
  for (const ImageRGB& image : renders) blocks.push_back(block_means(image, 4));
  const auto br = block_means(reference, 4);
  double noise2 = 0.0, error2 = 0.0;
  for (size_t i = 0; i < br.size(); ++i) {
    double mean = 0.0;
    for (const auto& b : blocks) mean += b[i] / double(k);
    double spread = 0.0;
    for (const auto& b : blocks) spread += (b[i] - mean) * (b[i] - mean);
    noise2 += spread / double(k - 1) / double(k);  // sample variance / k: the mean's variance
    error2 += (mean - br[i]) * (mean - br[i]);
  }
  return noise2 > 0.0 ? std::sqrt(error2 / noise2) : (error2 > 0.0 ? 1e9 : 0.0);
}

double error_to_noise_ratio(const ImageRGB& a, const ImageRGB& b, const ImageRGB& reference) {
  return error_to_noise_ratio(std::vector<ImageRGB>{a, b}, reference);
}

}  // namespace hipr::test
