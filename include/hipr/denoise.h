#pragma once
// The display denoiser's settings, declared once (for_each_denoise_setting): the commands' flags
// (src/app/denoise_flags.cpp) and the viewer's panel are bound from this declaration.
// The denoiser filters a copy of what the display shows; the accumulation, its images and the
// convergence contract never see it (docs/method.md, "The denoised display").
#include <cstdint>

namespace hipr {

struct DenoiseSettings {
  bool enabled = false;
  // Scales how far the filter reaches across luminance differences, in units of the pixel's
  // own noise (1: SVGF's four standard deviations; 0: nothing moves).
  float strength = 1.0f;
  uint32_t passes = 5;  // a-trous passes: the footprint is 4 x 2^passes - 3 pixels wide
  // The filter knows what the display shows (samples behind each value, stale or fresh, which
  // surface): false is the ablation that knows only the accumulation.
  bool display_state = true;
  // The share of the last frame shown that the next keeps, per sample the pixel gained (SVGF's
  // temporal filter of its output, denoise_temporal.comp): a converging view stops shimmering.
  // Never kept across a change; 0: every frame shows its own filter alone.
  float history = 0.8f;

  bool operator==(const DenoiseSettings&) const = default;
};

// A still image: the filter of the samples alone, nothing of earlier frames (what a render
// writes, what a view shows once it has converged).
inline DenoiseSettings without_history(DenoiseSettings settings) {
  settings.history = 0.0f;
  return settings;
}

inline constexpr uint32_t kMaxDenoisePasses = 8;
inline constexpr float kMaxDenoiseHistory = 0.95f;

// One run of the filter as the device timed it (GPU timestamps between its kernels): what a
// viewer's frame pays for it, without the host's submission and wait. The guides are traced
// only after an edit or a camera move (0 otherwise); `prepare` is the keys' kernel and the
// variance's together.
struct DenoiseGpuSeconds {
  double guides = 0.0, prepare = 0.0, atrous = 0.0, blend = 0.0, temporal = 0.0;
  double total() const { return guides + prepare + atrous + blend + temporal; }
};

struct DenoiseSettingInfo {
  const char* name;  // the field, and the viewer panel's label
  const char* flag;  // the commands' flag; a bool's flag turns it on, or off with "--no-"
  const char* help;
  float min = 0.0f, max = 0.0f;  // numbers: the range the flag accepts and the panel offers
};

// Calls `visit(info, field)` for every setting, in the order help and panel list them.
template <typename Settings, typename Visitor>
void for_each_denoise_setting(Settings& s, Visitor&& visit) {
  visit(
      DenoiseSettingInfo{"denoise", "--denoise",
                         "Show (or write) the display denoised: an edge-avoiding filter guided by "
                         "each pixel's noise, surface and scene state; the accumulation is "
                         "never filtered"},
      s.enabled);
  visit(DenoiseSettingInfo{"strength", "--denoise-strength",
                           "How far the denoiser reaches across luminance differences, in units "
                           "of each pixel's own noise (0: off)",
                           0.0f, 4.0f},
        s.strength);
  visit(DenoiseSettingInfo{"passes", "--denoise-passes",
                           "A-trous passes of the denoiser (footprint 4 x 2^passes - 3 pixels)",
                           1.0f, float(kMaxDenoisePasses)},
        s.passes);
  visit(DenoiseSettingInfo{"use display state", "--denoise-plain",
                           "Ablation: the denoiser ignores what hipr's display knows (samples "
                           "behind each value, stale or fresh) and reads the accumulation only"},
        s.display_state);
  visit(DenoiseSettingInfo{"history", "--denoise-history",
                           "Share of the last frame shown that the denoised display keeps per new "
                           "sample, within the pixel's noise (0: none); never kept across a change",
                           0.0f, kMaxDenoiseHistory},
        s.history);
}

}  // namespace hipr
