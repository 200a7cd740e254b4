#pragma once
#include <vector>

namespace hipr {

// The generated BSDF tables as the kernels read them (GpuScene binds them at
// abi::kSceneBsdfTables).
std::vector<float> bsdf_table_data();

}  // namespace hipr
