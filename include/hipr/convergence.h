#pragma once
// When the viewer's image is done and rendering pauses, declared once
// (for_each_convergence_setting): `hipr view`'s flags and its panel are bound from this
// declaration. --spp is always a limit; these stop rendering earlier, but never before every
// pixel shows the scene as it is now (one round over the schedule since the last change).
// Whatever stops it, the image at a given sample count is the one every schedule converges to.
#include <cstdint>

namespace hipr {

struct ConvergenceTarget {
  // Rendering pauses this long after the last change (0: no time limit). A fast device reaches
  // any sample count sooner; a slow one shows what it had.
  double seconds = 0.0;
  // Rendering pauses once the image's expected relMSE against its own limit (FilmNoise, from the
  // pixels' sample variances) is at most this (0: no noise target).
  double relmse = 0.0;
  // Once the noise target is met with the image's estimated relMSE at most kRawIsCleanerRelmse
  // (the default target meets it), the window shows the raw image (false), the full-frame render
  // of its samples bit for bit, or keeps the denoised one (true). Paused by the sample limit, the
  // time target or a looser noise target's estimate, noise may remain: the denoised image stays.
  bool keep_denoised = false;

  bool operator==(const ConvergenceTarget&) const = default;
};

// The image's expected relMSE below which the raw image is closer to the truth than the
// denoised one: the denoiser hides noise while the image converges, but its bias does not fade
// as fast as the noise. Measured (FLIP against 2048-spp references, 128x128; in brackets the raw
// image's relMSE): the Cornell box at 64 spp (1.1e-3) 0.0336 denoised against 0.0353 raw, at 268
// spp (2.5e-4) 0.0233 against 0.0211; SheenChair at 16 spp (3.4e-3) 0.0206 against 0.0228, at 64
// spp (7.8e-4) 0.0138 against 0.0120 (BENCHMARKS.md, "What the viewer shows when the image is
// clean"). The viewer's default noise target is this level too.
inline constexpr double kRawIsCleanerRelmse = 5e-4;

struct ConvergenceSettingInfo {
  const char* name;  // the viewer panel's label
  const char* flag;
  const char* help;
  double min = 0.0, max = 0.0;  // numbers: the range the flag accepts and the panel offers
};

// Calls `visit(info, field)` for every setting, in the order help and panel list them.
template <typename Settings, typename Visitor>
void for_each_convergence_setting(Settings& s, Visitor&& visit) {
  visit(ConvergenceSettingInfo{"seconds", "--converge-seconds",
                               "Pause rendering this many seconds after the last change (0: no "
                               "time limit; --spp still applies)",
                               0.0, 86400.0},
        s.seconds);
  visit(ConvergenceSettingInfo{"noise relMSE", "--converge-relmse",
                               "Pause rendering once the image's expected relMSE against its "
                               "converged limit, estimated from the pixels' sample variances, is "
                               "at most this (0: none; --spp still applies)",
                               0.0, 1.0},
        s.relmse);
  visit(ConvergenceSettingInfo{"keep denoised", "--keep-denoised",
                               "Keep showing the denoised image once the noise target is met with "
                               "an estimated relMSE of 5e-4 or less (by default the window then "
                               "shows the raw image: the full-frame render of its samples, bit "
                               "for bit)"},
        s.keep_denoised);
}

}  // namespace hipr
