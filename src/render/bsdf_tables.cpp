#include "render/bsdf_tables.h"

#include <iterator>

#include "shaders/bsdf/ggx_energy_table.glsl"

namespace hipr {

// The layout is the generated header's k*Offset macros; the asserts keep this order in step.
static_assert(kGgxEnergyOffset == 0);
static_assert(kGgxEnergyAverageOffset == std::size(kGgxEnergy));
static_assert(kFuzzEnergyOffset == kGgxEnergyAverageOffset + std::size(kGgxEnergyAverage));
static_assert(kBsdfTablesSize == kFuzzEnergyOffset + std::size(kFuzzEnergy));

std::vector<float> bsdf_table_data() {
  std::vector<float> data(std::begin(kGgxEnergy), std::end(kGgxEnergy));
  data.insert(data.end(), std::begin(kGgxEnergyAverage), std::end(kGgxEnergyAverage));
  data.insert(data.end(), std::begin(kFuzzEnergy), std::end(kFuzzEnergy));
  return data;
}

}  // namespace hipr
