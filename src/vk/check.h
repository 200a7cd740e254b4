#pragma once
// VK_CHECK: every Vulkan call that returns a VkResult goes through it. A failure throws
// InternalError naming the result, the call site and the expression.
#include <vulkan/vulkan.h>

namespace hipr::vk {

const char* result_name(VkResult result);
[[noreturn]] void throw_vk_error(VkResult result, const char* expression, const char* file,
                                 int line);

}  // namespace hipr::vk

#define VK_CHECK(expression)                                                         \
  do {                                                                               \
    const VkResult vk_check_result_ = (expression);                                  \
    if (vk_check_result_ != VK_SUCCESS)                                              \
      ::hipr::vk::throw_vk_error(vk_check_result_, #expression, __FILE__, __LINE__); \
  } while (0)
