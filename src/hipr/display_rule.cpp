#include "hipr/display_rule.h"

#include "core/error.h"

namespace hipr {

DisplayRule parse_display_rule(const std::string& name) {
  for (DisplayRule rule :
       {DisplayRule::Immediate, DisplayRule::Switch, DisplayRule::Blend, DisplayRule::Difference})
    if (display_rule_name(rule) == name) return rule;
  throw InputError("unknown display rule '" + name + "' (immediate, switch, blend, difference)");
}

std::string display_rule_name(DisplayRule rule) {
  switch (rule) {
    case DisplayRule::Immediate:
      return "immediate";
    case DisplayRule::Switch:
      return "switch";
    case DisplayRule::Blend:
      return "blend";
    case DisplayRule::Difference:
      return "difference";
  }
  return "?";
}

}  // namespace hipr
