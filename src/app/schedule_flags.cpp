#include "app/schedule_flags.h"

#include "core/error.h"

namespace hipr::app {
namespace {

// Turns a name into its value, reporting an unknown one as the flag's parse error.
template <typename Parse>
auto parsed(const std::string& flag, const std::string& text, Parse&& parse) {
  try {
    return parse(text);
  } catch (const InputError& e) {
    throw CLI::ValidationError(flag, e.what());
  }
}

struct FlagBinder {
  CLI::App& cmd;
  const std::set<std::string>& except;

  bool skipped(const ScheduleSettingInfo& info) const { return except.count(info.name) > 0; }

  void operator()(const ScheduleSettingInfo& info, Policy& policy) const {
    if (skipped(info)) return;
    const std::string flag = info.flag;
    cmd.add_option_function<std::string>(
           flag,
           [&policy, flag](const std::string& text) { policy = parsed(flag, text, parse_policy); },
           info.help)
        ->default_str(policy_name(policy));
  }
  void operator()(const ScheduleSettingInfo& info, std::optional<DisplayRule>& rule) const {
    if (skipped(info)) return;
    const std::string flag = info.flag;
    cmd.add_option_function<std::string>(
        flag,
        [&rule, flag](const std::string& text) { rule = parsed(flag, text, parse_display_rule); },
        info.help);
  }
  void operator()(const ScheduleSettingInfo& info, uint32_t& value) const {
    if (skipped(info)) return;
    CLI::Option* option = cmd.add_option(info.flag, value, info.help);
    if (value != 0)
      option->capture_default_str();  // 0 is "the command's default", said in the help
  }
  void operator()(const ScheduleSettingInfo& info, bool& on) const {
    if (skipped(info)) return;
    cmd.add_flag_function(
        info.flag, [&on](int64_t) { on = false; }, info.help);  // --no-...
  }
};

}  // namespace

void add_schedule_flags(CLI::App& cmd, ScheduleSettings& settings,
                        const std::set<std::string>& except) {
  for_each_schedule_setting(settings, FlagBinder{cmd, except});
}

}  // namespace hipr::app
