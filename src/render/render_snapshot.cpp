#include "render/render_snapshot.h"

#include <cstring>

#include "core/error.h"
#include "render/render_state.h"

namespace hipr {
namespace {

template <typename T>
std::vector<uint8_t> bytes_of(const vk::Buffer& buffer) {
  const std::vector<T> values = buffer.download_all<T>();
  std::vector<uint8_t> bytes(values.size() * sizeof(T));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

}  // namespace

RenderSnapshot snapshot_render(const Renderer& renderer) {
  const RenderState& m = renderer.state();
  std::vector<uint8_t> groups = bytes_of<glm::vec3>(m.film.group_sums);
  const std::vector<uint8_t> stale_groups = bytes_of<glm::vec3>(m.relight.stale_groups);
  groups.insert(groups.end(), stale_groups.begin(), stale_groups.end());
  return {bytes_of<abi::PixelAccum>(m.film.accumulation),
          bytes_of<abi::DisplayTexel>(m.resolve.display), std::move(groups),
          bytes_of<abi::DifferenceRecord>(m.film.difference),
          bytes_of<abi::TileJudgement>(m.resolve.judgements)};
}

void restore_render(Renderer& renderer, const RenderSnapshot& snapshot) {
  RenderState& m = *renderer.render_state();
  const size_t film_groups = m.film.group_sums.size();
  if (snapshot.accumulation.size() != m.film.accumulation.size() ||
      snapshot.display.size() != m.resolve.display.size() ||
      snapshot.light_groups.size() != film_groups + m.relight.stale_groups.size() ||
      snapshot.difference.size() != m.film.difference.size() ||
      snapshot.judgements.size() != m.resolve.judgements.size())
    throw InternalError("a snapshot of another image size");
  m.film.accumulation.upload(snapshot.accumulation.data(), snapshot.accumulation.size());
  m.resolve.display.upload(snapshot.display.data(), snapshot.display.size());
  m.film.group_sums.upload(snapshot.light_groups.data(), film_groups);
  m.relight.stale_groups.upload(snapshot.light_groups.data() + film_groups,
                                m.relight.stale_groups.size());
  m.film.difference.upload(snapshot.difference.data(), snapshot.difference.size());
  m.resolve.judgements.upload(snapshot.judgements.data(), snapshot.judgements.size());
}

}  // namespace hipr
