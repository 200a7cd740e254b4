#include "vk/check.h"

#include <string>

#include "core/error.h"

namespace hipr::vk {

const char* result_name(VkResult result) {
  switch (result) {
#define HIPR_RESULT_CASE(name) \
  case name:                   \
    return #name;
    HIPR_RESULT_CASE(VK_SUCCESS)
    HIPR_RESULT_CASE(VK_NOT_READY)
    HIPR_RESULT_CASE(VK_TIMEOUT)
    HIPR_RESULT_CASE(VK_INCOMPLETE)
    HIPR_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    HIPR_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    HIPR_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    HIPR_RESULT_CASE(VK_ERROR_DEVICE_LOST)
    HIPR_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    HIPR_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    HIPR_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    HIPR_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    HIPR_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    HIPR_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    HIPR_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    HIPR_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
    HIPR_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    HIPR_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    HIPR_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR)
    HIPR_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR)
    HIPR_RESULT_CASE(VK_SUBOPTIMAL_KHR)
#undef HIPR_RESULT_CASE
    default:
      return "VK_ERROR_UNKNOWN";
  }
}

void throw_vk_error(VkResult result, const char* expression, const char* file, int line) {
  throw InternalError(std::string("Vulkan error ") + result_name(result) + " (" +
                      std::to_string(int(result)) + ") in " + expression + " at " + file + ":" +
                      std::to_string(line));
}

}  // namespace hipr::vk
