#pragma once
// The oracle: after an edit, tiles in descending order of the true error of what they show
// against the converged render of the edited scene. The best any tile order could do, so a
// bound to measure HiPR's order against (hipr bench); no interactive tool has the reference.
#include <memory>

#include "hipr/image.h"
#include "hipr/scheduling_policy.h"

namespace hipr::bench {

class OraclePolicy final : public SchedulingPolicy {
 public:
  // `reference`: the converged render of the edited scene, read at each edit; the caller keeps
  // it alive and, across several edits, current.
  explicit OraclePolicy(const ImageRGB& reference) : m_reference(reference) {}

  Policy id() const override { return Policy::Oracle; }
  // The oracle keeps a G-buffer too (the display rule reads which surface each pixel shows), so
  // it differs from HiPR in its order alone.
  void start(ProgressiveRenderer& renderer) override { renderer.refresh_gbuffer(); }
  uint32_t plan(ProgressiveRenderer& renderer, const ChangeSet& changes) override;

 private:
  const ImageRGB& m_reference;
};

// The policy of that name for hipr bench: the library's, or the oracle with `reference` (kept
// alive by the caller).
std::unique_ptr<SchedulingPolicy> make_bench_policy(Policy policy, const ImageRGB& reference);

}  // namespace hipr::bench
