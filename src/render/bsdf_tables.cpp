#include "render/bsdf_tables.h"

#include <iterator>

#include "shaders/bsdf/ggx_energy_table.glsl"

namespace hipr {

std::vector<float> bsdf_table_data() {
  return std::vector<float>(std::begin(kBsdfTables), std::end(kBsdfTables));
}

}  // namespace hipr
