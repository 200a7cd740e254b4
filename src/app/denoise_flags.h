#pragma once
// The display denoiser's flags, bound from their one declaration (hipr/denoise.h) for every
// command that shows a display (render, replay, bench).
#include <CLI/CLI.hpp>

#include "hipr/denoise.h"

namespace hipr::app {

void add_denoise_flags(CLI::App& cmd, DenoiseSettings& settings);

}  // namespace hipr::app
