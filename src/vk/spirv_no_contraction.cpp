#include "vk/spirv_no_contraction.h"

#include <algorithm>
#include <unordered_set>

#include "core/error.h"

namespace hipr::vk {
namespace {

// Opcodes and the one decoration this pass needs (SPIR-V 1.5 specification, section 3).
constexpr uint32_t kOpDecorate = 71;
constexpr uint32_t kDecorationNoContraction = 42;
constexpr uint32_t kHeaderWords = 5;
constexpr uint32_t kMagic = 0x07230203u;

bool is_contractible(uint32_t opcode) {
  switch (opcode) {
    case 129:  // OpFAdd
    case 131:  // OpFSub
    case 133:  // OpFMul
    case 136:  // OpFDiv
    case 142:  // OpVectorTimesScalar
    case 143:  // OpMatrixTimesScalar
    case 144:  // OpVectorTimesMatrix
    case 145:  // OpMatrixTimesVector
    case 146:  // OpMatrixTimesMatrix
    case 148:  // OpDot
      return true;
    default:
      return false;
  }
}

bool is_annotation(uint32_t opcode) {
  return opcode == 71 || opcode == 72 || opcode == 73 || opcode == 74 || opcode == 75 ||
         opcode == 332 || opcode == 5632 || opcode == 5633;
}

}  // namespace

uint32_t forbid_contraction(std::vector<uint32_t>& spirv) {
  if (spirv.size() < kHeaderWords || spirv[0] != kMagic) throw InternalError("not a SPIR-V module");
  std::unordered_set<uint32_t> decorated;  // glslang's own NoContraction (precise) targets
  std::vector<uint32_t> targets;
  size_t after_annotations = 0;  // word index just past the last annotation
  for (size_t at = kHeaderWords; at < spirv.size();) {
    const uint32_t opcode = spirv[at] & 0xffffu;
    const uint32_t words = spirv[at] >> 16;
    if (words == 0 || at + words > spirv.size())
      throw InternalError("malformed SPIR-V instruction");
    if (is_annotation(opcode)) after_annotations = at + words;
    if (opcode == kOpDecorate && words >= 3 && spirv[at + 2] == kDecorationNoContraction)
      decorated.insert(spirv[at + 1]);
    if (is_contractible(opcode) && words >= 3)
      targets.push_back(spirv[at + 2]);  // result type, result id, ...
    at += words;
  }
  if (after_annotations == 0) throw InternalError("SPIR-V module without annotations");
  std::vector<uint32_t> decorations;
  for (uint32_t id : targets) {
    if (decorated.count(id)) continue;
    decorations.insert(decorations.end(), {(3u << 16) | kOpDecorate, id, kDecorationNoContraction});
  }
  spirv.insert(spirv.begin() + std::ptrdiff_t(after_annotations), decorations.begin(),
               decorations.end());
  return uint32_t(decorations.size() / 3);
}

}  // namespace hipr::vk
