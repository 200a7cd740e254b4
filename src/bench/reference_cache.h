#pragma once
// Converged references of edited scene states, cached on disk: a reference costs hundreds of
// full-frame passes, and a benchmark is rerun far more often than its scene or edits change.
#include <filesystem>
#include <string>
#include <vector>

#include "hipr/renderer.h"
#include "hipr/scene.h"
#include "image/image_io.h"

namespace hipr::vk {
class Context;
}

namespace hipr::bench {

// Everything that decides a reference's pixels: the scene as loaded (content hash, environment
// settings), the edits applied so far (`state` = their canonical text), the render settings
// that change the image, the sample count, the renderer's own shader sources and the device
// with its traversal.
std::string reference_key(const vk::Context& ctx, const Scene& scene, const std::string& state,
                          const RenderSettings& settings, uint32_t spp);

// $HIPR_CACHE_DIR/references (or beside the shader cache); empty when there is no cache folder.
std::filesystem::path default_reference_cache();

struct Reference {
  ImageRGB image;
  bool from_cache = false;
  double render_seconds = 0.0;  // 0 when read from the cache
};

// Restarts the renderer's image and renders `spp` samples per pixel, in submissions of at most
// 16 (each stays short: no device watchdog, and lavapipe's threads stay shared).
void converge(Renderer& renderer, uint32_t spp);

// The reference of `scene` at `spp` samples per pixel, rendered with a seed unrelated to
// `settings.seed` (its noise must not correlate with the runs it judges). Read from
// `cache_dir`/KEY.exr when present, else rendered and stored there (when cache_dir is set).
Reference converged_reference(const vk::Context& ctx, const Scene& scene, const std::string& key,
                              const RenderSettings& settings, uint32_t spp,
                              const std::filesystem::path& cache_dir);

// A tile whose two references differ by more than this mean relMSE (per pixel and channel, as
// relmse()) changed: about 10 % RMS, several times what two 1024-spp references of one scene
// differ by from noise alone (about 0.001 on cornell_sphere, whose 64-spp images are at 0.009).
inline constexpr double kChangedTileRelmse = 0.005;

// The tiles (ids, ascending) where the references before and after an edit differ by more than
// kChangedTileRelmse: what the edit really changed, to judge stage 1's active set against.
std::vector<uint32_t> reference_changed_tiles(const ImageRGB& before, const ImageRGB& after,
                                              uint32_t tile_size);

}  // namespace hipr::bench
