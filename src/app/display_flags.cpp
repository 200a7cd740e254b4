#include "app/display_flags.h"

#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "image/auto_exposure.h"

namespace hipr::app {

std::optional<float> parse_exposure(const std::string& text) {
  if (text == "auto") return std::nullopt;
  float value = 0.0f;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%f%c", &value, &tail) != 1 || !std::isfinite(value))
    throw InputError("exposure must be a finite number of stops or 'auto', got '" + text + "'");
  return value;
}

void add_display_flags(CLI::App& cmd, DisplayFlags& flags, const std::string& applies_to) {
  char current[32];
  if (flags.exposure_ev) std::snprintf(current, sizeof current, "%g", double(*flags.exposure_ev));
  cmd.add_option_function<std::string>(
         "--exposure",
         [&flags](const std::string& text) {
           try {
             flags.exposure_ev = parse_exposure(text);
           } catch (const InputError& e) {
             throw CLI::ValidationError("--exposure", e.what());
           }
         },
         "Exposure in stops, or auto (the frame's 90th-percentile luminance at 80% of white), "
         "for " +
             applies_to)
      ->default_str(flags.exposure_ev ? current : "auto");
  cmd.add_option_function<std::string>(
         "--tonemap",
         [&flags](const std::string& text) {
           try {
             flags.tone_mapper = parse_tone_mapper(text);
           } catch (const InputError& e) {
             throw CLI::ValidationError("--tonemap", e.what());
           }
         },
         "Tone mapper after the exposure: clamp, pbr-neutral (Khronos PBR Neutral), agx or "
         "aces, for " +
             applies_to)
      ->default_str(tone_mapper_name(flags.tone_mapper));
}

DisplayTransform display_transform(const DisplayFlags& flags, const ImageRGB& metered) {
  return {flags.exposure_ev ? *flags.exposure_ev : metered_exposure_ev(metered.rgb),
          flags.tone_mapper};
}

}  // namespace hipr::app
