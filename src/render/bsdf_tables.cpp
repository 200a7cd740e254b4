#include "render/bsdf_tables.h"

#include <iterator>

#include "shaders/bsdf/ggx_energy_table.glsl"

namespace hipr {

std::vector<float> bsdf_table_data() {
  std::vector<float> data(std::begin(kGgxEnergy), std::end(kGgxEnergy));
  data.insert(data.end(), std::begin(kGgxEnergyAverage), std::end(kGgxEnergyAverage));
  return data;
}

}  // namespace hipr
