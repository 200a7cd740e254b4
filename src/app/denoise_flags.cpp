#include "app/denoise_flags.h"

namespace hipr::app {
namespace {

struct FlagBinder {
  CLI::App& cmd;

  // A flag flips the default: --denoise turns the denoiser on (--no-denoise off, where it is
  // on by default: the viewer), --denoise-plain its knowledge off.
  void operator()(const DenoiseSettingInfo& info, bool& value) const {
    const bool flipped = !value;
    const std::string flag = info.flag;
    if (flag == "--denoise" && value) {
      cmd.add_flag_function(
          "--no-denoise", [&value](int64_t) { value = false; },
          "Show the display as rendered: no denoiser (N toggles it)");
      return;
    }
    cmd.add_flag_function(
        flag, [&value, flipped](int64_t) { value = flipped; }, info.help);
  }
  void operator()(const DenoiseSettingInfo& info, float& value) const {
    cmd.add_option(info.flag, value, info.help)
        ->capture_default_str()
        ->check(CLI::Range(info.min, info.max));
  }
  void operator()(const DenoiseSettingInfo& info, uint32_t& value) const {
    cmd.add_option(info.flag, value, info.help)
        ->capture_default_str()
        ->check(CLI::Range(uint32_t(info.min), uint32_t(info.max)));
  }
};

}  // namespace

void add_denoise_flags(CLI::App& cmd, DenoiseSettings& settings) {
  for_each_denoise_setting(settings, FlagBinder{cmd});
}

}  // namespace hipr::app
