#pragma once
// Automatic exposure (the viewer's metering, `--exposure auto`): one exposure for a frame of
// linear radiance, so that a white floor under the studio (about 1 nit), under the daylight sky
// (thousands) and beside a candle all open well exposed.
//
// Highlight-weighted metering: the frame's 90th-percentile luminance (Rec. 709 weights, over
// finite pixels brighter than 0) is shown at 80% of display white. An average meter (the mean
// at middle grey) makes a white floor filling the frame grey and lets a dark room's few lit
// surfaces clip; anchoring near the top keeps the brightest tenth of the surfaces, which is
// what a viewer judges exposure by, just under white, while the top 10% (emitters, speculars)
// may roll off in the tone mapper.
#include <cstdint>
#include <vector>

namespace hipr {

constexpr float kMeteredPercentile = 0.90f;
constexpr float kMeteredDisplayValue = 0.80f;
constexpr float kMinExposureEv = -20.0f, kMaxExposureEv = 20.0f;

// The exposure in stops (in [kMinExposureEv, kMaxExposureEv]) for interleaved linear RGB; 0 for
// a frame without a lit pixel.
float metered_exposure_ev(const std::vector<float>& rgb);

// The same rule over a histogram of the lit pixels' luminances by log2 (render/exposure_meter.h
// makes it on the device): counts[i] pixels have log2(luminance) in
// [lowest_stop + i / bins_per_stop, lowest_stop + (i + 1) / bins_per_stop); the metered luminance
// is the middle of the percentile's bin (within half a bin of metered_exposure_ev's).
struct LuminanceHistogram {
  std::vector<uint32_t> counts;
  float lowest_stop = 0.0f;
  float bins_per_stop = 1.0f;
};
float histogram_exposure_ev(const LuminanceHistogram& histogram);

}  // namespace hipr
