#pragma once
// How the display follows the accumulation after an edit (docs/method.md, "The display after an
// edit"): Immediate shows every re-rendered pixel at once; Switch keeps a tile's stale radiance
// until its fresh estimate is expected to be closer to the truth; Blend shows the mix of the two
// with the least expected error; Difference is Blend where a pixel's stale estimate is corrected
// by the difference of its new samples from the old scene's samples with the same random numbers
// (the default of the HiPR policy; Blend where the film keeps no samples). All show the fresh
// estimate alone once it has caught up in samples, so every rule ends on the same image.
#include <string>

namespace hipr {

enum class DisplayRule { Immediate = 0, Switch = 1, Blend = 2, Difference = 3 };

DisplayRule parse_display_rule(const std::string& name);  // throws InputError
std::string display_rule_name(DisplayRule rule);

}  // namespace hipr
