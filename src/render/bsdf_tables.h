#pragma once
#include <vector>

namespace hipr {

// The generated BSDF tables as the kernels read them (binding kBindingBsdfTables).
std::vector<float> bsdf_table_data();

}  // namespace hipr
