#include "bench/reference_cache.h"

#include <algorithm>

#include "core/hash.h"
#include "core/log.h"
#include "core/timer.h"
#include "image/error_metrics.h"
#include "image/image_io.h"
#include "vk/context.h"
#include "vk/embedded_shaders.h"
#include "vk/shader_compiler.h"

namespace hipr::bench {
namespace fs = std::filesystem;

namespace {

// Any fixed nonzero constant works: it only has to move the reference off the runs' sample streams.
constexpr uint32_t kReferenceSeedOffset = 0x68e31da5u;

}  // namespace

void converge(Renderer& renderer, uint32_t spp) {
  renderer.reset();
  for (uint32_t done = 0; done < spp; done += 16)
    renderer.add_samples_full_frame(std::min(16u, spp - done));
}

std::string reference_key(const vk::Context& ctx, const Scene& scene, const std::string& state,
                          const RenderSettings& settings, uint32_t spp) {
  Hasher hasher;
  // The shader sources are hashed below; a change of host code that alters pixels (scene
  // packing, light or BSDF tables) must bump this version, or stale references are reused.
  hasher.add("hipr-reference-v2").add(scene.content_hash).add(state);
  // Devices (and traversals) agree only to a tolerance: each keeps its own references.
  hasher.add(ctx.device_name()).add(ctx.traversal_name());
  if (scene.environment) {
    hasher.add(&scene.environment->intensity, sizeof(float));
    hasher.add(&scene.environment->rotation, sizeof(float));
  }
  const uint32_t numbers[] = {settings.width,
                              settings.height,
                              settings.seed,
                              settings.max_depth,
                              uint32_t(settings.light_sampling),
                              uint32_t(settings.sampler),
                              uint32_t(settings.light_selection),
                              uint32_t(settings.guiding),
                              settings.guide_training_spp,
                              spp};
  hasher.add(numbers, sizeof numbers);
  for (const vk::EmbeddedShaderFile& file : vk::embedded_shader_files())
    hasher.add(file.path).add(file.text);
  return hasher.hex();
}

fs::path default_reference_cache() {
  const fs::path shaders = vk::shader_cache_dir();
  return shaders.empty() ? fs::path() : shaders.parent_path() / "references";
}

Reference converged_reference(const vk::Context& ctx, const Scene& scene, const std::string& key,
                              const RenderSettings& settings, uint32_t spp,
                              const fs::path& cache_dir) {
  const fs::path file = cache_dir.empty() ? fs::path() : cache_dir / (key + ".exr");
  std::error_code ec;
  if (!file.empty() && fs::is_regular_file(file, ec)) {
    try {
      ImageRGB image = read_image(file);
      if (image.width == settings.width && image.height == settings.height)
        return {std::move(image), true, 0.0};
    } catch (const std::exception&) {
      // A damaged cache entry is rendered again and replaced.
    }
    log::warn("reference cache entry " + file.string() + " is unreadable; rendering it again");
  }
  RenderSettings reference_settings = settings;
  reference_settings.seed = settings.seed ^ kReferenceSeedOffset;
  Renderer renderer(ctx, scene, reference_settings);
  const Timer timer;
  converge(renderer, spp);
  Reference reference{renderer.image(), false, timer.seconds()};
  if (!file.empty()) {
    fs::create_directories(cache_dir, ec);
    try {
      write_image(file, reference.image,
                  {{"hipr:spp", std::to_string(spp)}, {"hipr:reference_key", key}});
    } catch (const std::exception& e) {
      log::warn(std::string("could not cache the reference: ") + e.what());
    }
  }
  return reference;
}

std::vector<uint32_t> reference_changed_tiles(const ImageRGB& before, const ImageRGB& after,
                                              uint32_t tile_size) {
  const std::vector<double> sums = relmse_tile_sums(before, after, tile_size);
  const uint32_t tiles_x = (after.width + tile_size - 1) / tile_size;
  std::vector<uint32_t> changed;
  for (uint32_t t = 0; t < sums.size(); ++t) {
    const uint32_t x0 = (t % tiles_x) * tile_size, y0 = (t / tiles_x) * tile_size;
    const uint32_t pixels = (std::min(x0 + tile_size, after.width) - x0) *
                            (std::min(y0 + tile_size, after.height) - y0);
    if (sums[t] > kChangedTileRelmse * 3.0 * pixels) changed.push_back(t);
  }
  return changed;
}

}  // namespace hipr::bench
