#pragma once
// Marks every floating-point add, subtract, multiply, divide and vector/matrix product of a
// SPIR-V module NoContraction, as GLSL's `precise` would: the driver may no longer fuse a
// multiply and an add into one FMA where it sees fit. Where it fuses depends on the code around
// the arithmetic, so without this two variants of one kernel (the specialised and the uber
// kernel, or one compiled after an edit brought in a feature) round the same expression
// differently on a GPU's compiler (NVIDIA's does; lavapipe's LLVM did not), and a converged
// image would no longer match the full-frame render bit for bit.
#include <cstdint>
#include <vector>

namespace hipr::vk {

// Returns how many instructions it decorated. Throws InternalError on a malformed module.
uint32_t forbid_contraction(std::vector<uint32_t>& spirv);

}  // namespace hipr::vk
