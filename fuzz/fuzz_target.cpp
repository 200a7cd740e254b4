// One libFuzzer target per input kind (HIPR_FUZZ_TARGET: 0 glTF, 1 edit script, 2 environment
// image, 3 an image `compare` reads); see fuzz_inputs.h and tools/fuzz.sh.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/log.h"
#include "fuzz_inputs.h"

namespace {

const std::filesystem::path& scratch() {
  static const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("hipr-fuzz-" + std::to_string(getpid()));
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  hipr::log::set_quiet(true);  // no progress lines (tools/fuzz.sh also closes the targets' stderr)
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
#if HIPR_FUZZ_TARGET == 0
  hipr::fuzz::load_gltf_bytes(data, size, scratch());
#elif HIPR_FUZZ_TARGET == 1
  hipr::fuzz::apply_edit_script_bytes(data, size, HIPR_ASSETS_DIR);
#elif HIPR_FUZZ_TARGET == 2
  hipr::fuzz::load_environment_bytes(data, size, scratch());
#else
  hipr::fuzz::read_image_bytes(data, size, scratch());
#endif
  return 0;
}
