#pragma once
// The display flags of every command that shows or writes 8-bit pictures (render, replay and
// bench for their PNGs, compare for FLIP, view for the window): `--exposure EV|auto` and
// `--tonemap clamp|pbr-neutral|agx|aces`. EXR output is linear radiance and ignores both.
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "hipr/image.h"
#include "image/tonemap.h"

namespace hipr::app {

struct DisplayFlags {
  std::optional<float> exposure_ev = 0.0f;  // nullopt: metered (image/auto_exposure.h)
  ToneMapper tone_mapper = ToneMapper::Clamp;
};

// Adds both flags, their defaults taken from `flags`; `applies_to` ends their help ("PNG
// output"). A bad value (not a finite number nor "auto", an unknown mapper) is a parse error.
void add_display_flags(CLI::App& cmd, DisplayFlags& flags, const std::string& applies_to);

// The transform for pictures of `metered`: the exposure given, or the one metered from it.
DisplayTransform display_transform(const DisplayFlags& flags, const ImageRGB& metered);

// "2.5" or "auto" -> the exposure (nullopt for auto); throws InputError otherwise.
std::optional<float> parse_exposure(const std::string& text);

}  // namespace hipr::app
