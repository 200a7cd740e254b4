#pragma once
// Error of a displayed image against a converged reference, for `hipr bench`: relMSE on linear
// radiance and LDR-FLIP on the tone-mapped image (docs/method.md#measuring-run-time-against-error).
#include <cstdint>
#include <vector>

#include "image/image_io.h"

namespace hipr {

// The relMSE of docs/method.md: mean over pixels and RGB channels of (x-y)^2 / (y^2 + 0.01),
// divided by 2. x = test, y = reference, linear radiance. Throws InternalError when sizes differ
// (or an image's rgb does not hold width * height * 3 values). An empty image has no error (0). A
// NaN or infinite value makes the result non-finite, so a broken render never looks converged.
double relmse(const ImageRGB& test, const ImageRGB& reference);

// relmse() over the pixels whose `mask` entry is non-zero (row-major, one per pixel): the error
// of a region (a focus, docs/method.md#focus). 0 when the mask selects no pixel; InternalError
// when the sizes differ.
double relmse_masked(const ImageRGB& test, const ImageRGB& reference,
                     const std::vector<uint8_t>& mask);

// The same per-pixel terms, (x-y)^2 / (y^2 + 0.01) / 2 summed over RGB, summed over each
// tile x tile block (row-major tile ids, tiles_x = ceil(width / tile)); partial tiles at the
// edges included. The sum over all tiles divided by 3 * width * height is relmse(). Used to rank
// tiles by true error (the "oracle" policy). Throws InternalError for tile == 0.
std::vector<double> relmse_tile_sums(const ImageRGB& test, const ImageRGB& reference,
                                     uint32_t tile);

struct FlipOptions {
  float pixels_per_degree = 67.0f;  // the FLIP paper's default viewing setup
  // The display transform before FLIP, as tonemap_srgb8 applies it (exposure, tone mapper).
  float exposure_ev = 0.0f;
  ToneMapper tone_mapper = ToneMapper::Clamp;
};

// The two halves of LDR-FLIP per pixel (row-major), each in [0,1]: the compressed colour
// difference ec and the feature (edge and point) difference ef. The error is ec^(1 - ef).
struct FlipComponents {
  std::vector<float> color;
  std::vector<float> feature;
};

// LDR-FLIP (Andersson et al. 2020, "FLIP: A Difference Evaluator for Alternating Images") of two
// linear-radiance images after the project's display transform (exposure, tone mapper; FLIP then
// works on those display values as sRGB-encoded images, as the paper's LDR-FLIP expects).
// Returns the per-pixel error map in [0,1] (row-major). Throws InternalError when sizes differ
// and InputError when pixels_per_degree is below 1 or exposure_ev is not finite.
std::vector<float> flip_error_map(const ImageRGB& test, const ImageRGB& reference,
                                  const FlipOptions& options = {});
// Mean of flip_error_map (0 for an empty image).
double flip_mean(const ImageRGB& test, const ImageRGB& reference, const FlipOptions& options = {});
// Both halves separately, for tests and for showing where the error comes from.
FlipComponents flip_components(const ImageRGB& test, const ImageRGB& reference,
                               const FlipOptions& options = {});

}  // namespace hipr
