// Set 0 of meter_exposure.comp (ExposureMeter) and the histogram it fills: the viewer's automatic
// exposure reads 4 KB back instead of the whole display.
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_EXPOSURE_H
#define HIPR_BINDINGS_EXPOSURE_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kMeterDisplay = 0u;    // DisplayTexel per pixel, read (`shown`)
HIPR_CONST uint kMeterHistogram = 1u;  // uint per bin: the lit pixels of each luminance bin

// The bins: log2 of the luminance from kMeterLowestStop, kMeterBinsPerStop a stop (1/16 of a
// stop is finer than the viewer's metering follows), over 64 stops; luminances beyond either end
// count in the end bins.
HIPR_CONST uint kMeterBins = 1024u;
HIPR_CONST uint kMeterBinsPerStop = 16u;
HIPR_CONST int kMeterLowestStop = -40;
// Pixels a workgroup counts in its own shared histogram before adding it to the device's (128:
// what every Vulkan device allows).
HIPR_CONST uint kMeterWorkgroupSize = 128u;

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
