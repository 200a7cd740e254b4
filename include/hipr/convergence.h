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

  bool operator==(const ConvergenceTarget&) const = default;
};

struct ConvergenceSettingInfo {
  const char* name;  // the viewer panel's label
  const char* flag;
  const char* help;
  double min, max;  // the range the flag accepts and the panel offers
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
}

}  // namespace hipr
