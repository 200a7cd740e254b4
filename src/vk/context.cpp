#include "vk/context.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/error.h"
#include "core/log.h"
#include "vk/check.h"
#include "vk/staging.h"

namespace hipr::vk {
namespace {

std::atomic<uint64_t> g_submissions{0};  // queue_submissions()

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// What ray queries need; the software traversal needs none of it.
const char* const kRayQueryExtensions[] = {
    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
    VK_KHR_RAY_QUERY_EXTENSION_NAME,
    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME,
};

Traversal requested_traversal(Traversal option) {
  if (option != Traversal::Automatic) return option;
  const char* env = std::getenv("HIPR_TRAVERSAL");
  if (!env || !*env) return Traversal::Automatic;
  const std::string value = env;
  if (value == "ray-query") return Traversal::RayQuery;
  if (value == "software") return Traversal::Software;
  throw InputError("HIPR_TRAVERSAL must be ray-query or software");
}

bool requested_staged_memory(bool option) {
  const char* env = std::getenv("HIPR_DEVICE_MEMORY");
  if (option || !env || !*env) return option;
  const std::string value = env;
  if (value == "staged") return true;
  if (value == "auto") return false;
  throw InputError("HIPR_DEVICE_MEMORY must be staged or auto");
}

bool has_extension(const std::vector<VkExtensionProperties>& list, const char* name) {
  return std::any_of(list.begin(), list.end(), [&](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, name) == 0;
  });
}

std::vector<VkExtensionProperties> device_extensions(VkPhysicalDevice device) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> list(count);
  VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, list.data()));
  return list;
}

// Everything the kernels use, checked before the device is chosen.
struct FeatureChain {
  VkPhysicalDeviceRayQueryFeaturesKHR rayQuery{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR accel{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR, &rayQuery};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                       &accel};
  VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12};

  FeatureChain() = default;
  FeatureChain(const FeatureChain&) = delete;

  // What every kernel needs, whichever the traversal.
  bool supports_kernels() const {
    return v12.bufferDeviceAddress && v12.scalarBlockLayout && v12.shaderBufferInt64Atomics &&
           core.features.shaderInt64;
  }
  bool supports_ray_queries() const { return rayQuery.rayQuery && accel.accelerationStructure; }
};

// The queue family to use: compute, preferably with graphics (the viewer draws its UI on the
// same queue); with a surface, it must have graphics and present to the surface. -1: none.
int pick_queue_family(VkPhysicalDevice device, VkSurfaceKHR surface) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  int chosen = -1;
  for (uint32_t i = 0; i < count; ++i) {
    const VkQueueFlags flags = families[i].queueFlags;
    if (!(flags & VK_QUEUE_COMPUTE_BIT)) continue;
    if (surface) {
      VkBool32 present = VK_FALSE;
      VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(device, i, surface, &present));
      if (!present || !(flags & VK_QUEUE_GRAPHICS_BIT)) continue;
    }
    if (chosen < 0 || (flags & VK_QUEUE_GRAPHICS_BIT)) chosen = int(i);
    if (flags & VK_QUEUE_GRAPHICS_BIT) break;
  }
  return chosen;
}

int device_rank(const VkPhysicalDeviceProperties& props) {
  switch (props.deviceType) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 1;
    default:
      return 0;
  }
}

}  // namespace

Context::Context(const ContextOptions& options) {
  try {
    m_staged_device_memory = requested_staged_memory(options.staged_device_memory);
    create_instance(options);
    if (options.create_surface) {
      m_surface = options.create_surface(m_instance);
      if (!m_surface) throw InternalError("the window system made no Vulkan surface");
    }
    pick_physical_device(options, requested_traversal(options.traversal));
    create_device();
  } catch (...) {
    release();  // the destructor does not run for a constructor that throws
    throw;
  }
}

Context::~Context() { release(); }

StagingBuffers& Context::staging() const {
  if (!m_staging) m_staging = std::make_unique<StagingBuffers>();
  return *m_staging;
}

void Context::release() {
  if (m_device) {
    vkDeviceWaitIdle(m_device);
    m_staging.reset();  // its buffers before the device
    if (m_fence) vkDestroyFence(m_device, m_fence, nullptr);
    if (m_command_pool) vkDestroyCommandPool(m_device, m_command_pool, nullptr);
    vkDestroyDevice(m_device, nullptr);
    m_device = VK_NULL_HANDLE;
  }
  if (m_surface) {
    vkDestroySurfaceKHR(m_instance, m_surface, nullptr);
    m_surface = VK_NULL_HANDLE;
  }
  if (m_messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(m_instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(m_instance, m_messenger, nullptr);
    m_messenger = VK_NULL_HANDLE;
  }
  if (m_instance) {
    vkDestroyInstance(m_instance, nullptr);
    m_instance = VK_NULL_HANDLE;
  }
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::on_validation_message(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<Context*>(user);
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    self->m_validation_errors.fetch_add(1);
    std::fprintf(stderr, "hipr: validation error: %s\n", data->pMessage);
  } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    std::fprintf(stderr, "hipr: validation warning: %s\n", data->pMessage);
  }
  return VK_FALSE;
}

void Context::create_instance(const ContextOptions& options) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "hipr";
  app.pEngineName = "hipr";
  app.apiVersion = VK_API_VERSION_1_2;

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  for (const std::string& name : options.instance_extensions) extensions.push_back(name.c_str());
  VkDebugUtilsMessengerCreateInfoEXT messenger{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  if (options.validation) {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> available(count);
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, available.data()));
    const bool found = std::any_of(
        available.begin(), available.end(),
        [](const VkLayerProperties& l) { return std::strcmp(l.layerName, kValidationLayer) == 0; });
    if (!found)
      throw InternalError(
          "validation requested but VK_LAYER_KHRONOS_validation is not installed "
          "(package vulkan-validationlayers)");
    layers.push_back(kValidationLayer);
    if (std::none_of(extensions.begin(), extensions.end(), [](const char* e) {
          return std::strcmp(e, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) == 0;
        }))
      extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = &Context::on_validation_message;
    messenger.pUserData = this;
  }

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledLayerCount = uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  if (options.validation) info.pNext = &messenger;  // also catches instance creation problems
  const VkResult result = vkCreateInstance(&info, nullptr, &m_instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_INITIALIZATION_FAILED)
    throw InternalError(
        "no Vulkan driver found (install mesa-vulkan-drivers: tools/setup-deps.sh)");
  VK_CHECK(result);

  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(m_instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw InternalError("VK_EXT_debug_utils is not available");
    VK_CHECK(create(m_instance, &messenger, nullptr, &m_messenger));
  }
}

void Context::pick_physical_device(const ContextOptions& options, Traversal traversal) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(m_instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(m_instance, &count, devices.data()));

  int best_rank = -1;
  std::string rejected, unnamed;
  for (VkPhysicalDevice device : devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(device, &props);
    const std::string name = props.deviceName;
    if (!options.preferred_device.empty() &&
        name.find(options.preferred_device) == std::string::npos) {
      unnamed += (unnamed.empty() ? "" : ", ") + name;
      continue;
    }
    const auto extensions = device_extensions(device);
    FeatureChain features;
    vkGetPhysicalDeviceFeatures2(device, &features.core);
    const bool ray_queries =
        std::all_of(std::begin(kRayQueryExtensions), std::end(kRayQueryExtensions),
                    [&](const char* ext) { return has_extension(extensions, ext); }) &&
        features.supports_ray_queries();
    const bool usable =
        props.apiVersion >= VK_API_VERSION_1_2 && features.supports_kernels() &&
        (!m_surface || has_extension(extensions, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) &&
        (ray_queries || traversal != Traversal::RayQuery) &&
        pick_queue_family(device, m_surface) >= 0;
    if (!usable) {
      rejected += (rejected.empty() ? "" : ", ") + name;
      continue;
    }
    // The kind of device first (a GPU without ray queries beats a CPU with them), then ray queries.
    const int rank = 2 * device_rank(props) + (ray_queries ? 1 : 0);
    if (rank > best_rank) {
      best_rank = rank;
      m_physical = device;
      m_device_name = name;
      m_is_cpu = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
      m_software_traversal = traversal == Traversal::Software || !ray_queries;
      m_has_ray_queries = ray_queries;
    }
  }
  if (!m_physical && rejected.empty() && !options.preferred_device.empty())
    throw InternalError("no Vulkan device's name contains '" + options.preferred_device +
                        "' (found: " + (unnamed.empty() ? std::string("none") : unnamed) + ")");
  if (!m_physical) {
    std::string message =
        traversal == Traversal::RayQuery
            ? "no Vulkan device supports acceleration structures + ray queries"
            : "no Vulkan 1.2 device has buffer device addresses, scalar layouts and 64-bit atomics";
    if (m_surface) message += " and presents to the window";
    if (!options.preferred_device.empty())
      message += " matching '" + options.preferred_device + "'";
    if (!rejected.empty()) message += " (rejected: " + rejected + ")";
    message += "; install Mesa >= 23 lavapipe from bookworm-backports (tools/setup-deps.sh)";
    throw InternalError(message);
  }

  VkPhysicalDeviceAccelerationStructurePropertiesKHR accel_props{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                     m_software_traversal ? nullptr : &accel_props};
  vkGetPhysicalDeviceProperties2(m_physical, &props2);
  m_min_storage_alignment = uint32_t(props2.properties.limits.minStorageBufferOffsetAlignment);
  m_max_storage_range = props2.properties.limits.maxStorageBufferRange;
  if (options.storage_range_limit)
    m_max_storage_range = std::min(m_max_storage_range, options.storage_range_limit);
  if (!m_software_traversal)
    m_min_scratch_alignment = accel_props.minAccelerationStructureScratchOffsetAlignment;
  const auto& groups = props2.properties.limits.maxComputeWorkGroupCount;
  m_max_dispatch[0] =
      options.dispatch_width_limit ? std::min(options.dispatch_width_limit, groups[0]) : groups[0];
  m_max_dispatch[1] = groups[1];
}

void Context::create_device() {
  const int chosen = pick_queue_family(m_physical, m_surface);
  if (chosen < 0) throw InternalError("device " + m_device_name + " has no compute queue");
  m_queue_family = uint32_t(chosen);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = m_queue_family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  // Enable exactly what the kernels need.
  FeatureChain enabled;
  if (m_software_traversal) {
    enabled.v12.pNext = nullptr;  // no ray-query or acceleration-structure features to enable
  } else {
    enabled.rayQuery.rayQuery = VK_TRUE;
    enabled.accel.accelerationStructure = VK_TRUE;
  }
  enabled.v12.bufferDeviceAddress = VK_TRUE;
  enabled.v12.scalarBlockLayout = VK_TRUE;
  enabled.v12.shaderBufferInt64Atomics = VK_TRUE;
  enabled.core.features.shaderInt64 = VK_TRUE;

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enabled.core};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  std::vector<const char*> extensions;
  if (!m_software_traversal)
    extensions.assign(std::begin(kRayQueryExtensions), std::end(kRayQueryExtensions));
  if (m_surface) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(m_physical, &info, nullptr, &m_device));
  vkGetDeviceQueue(m_device, m_queue_family, 0, &m_queue);

  auto load = [&](auto& pointer, const char* name) {
    pointer = reinterpret_cast<std::remove_reference_t<decltype(pointer)>>(
        vkGetDeviceProcAddr(m_device, name));
    if (!pointer) throw InternalError(std::string("Vulkan function missing: ") + name);
  };
  if (!m_software_traversal) {
    load(m_fn.createAccelerationStructure, "vkCreateAccelerationStructureKHR");
    load(m_fn.destroyAccelerationStructure, "vkDestroyAccelerationStructureKHR");
    load(m_fn.getAccelerationStructureBuildSizes, "vkGetAccelerationStructureBuildSizesKHR");
    load(m_fn.cmdBuildAccelerationStructures, "vkCmdBuildAccelerationStructuresKHR");
    load(m_fn.getAccelerationStructureDeviceAddress, "vkGetAccelerationStructureDeviceAddressKHR");
  }

  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = m_queue_family;
  VK_CHECK(vkCreateCommandPool(m_device, &pool_info, nullptr, &m_command_pool));
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vkCreateFence(m_device, &fence_info, nullptr, &m_fence));
}

void Context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = m_command_pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateCommandBuffers(m_device, &alloc, &cmd));
  struct Free {
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    ~Free() { vkFreeCommandBuffers(device, pool, 1, &cmd); }
  } free_on_exit{m_device, m_command_pool, cmd};

  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  // What the commands wrote becomes visible to host reads of mapped memory (counters, read-backs)
  // once the fence is waited for.
  VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  to_host.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &to_host, 0, nullptr, 0, nullptr);
  VK_CHECK(vkEndCommandBuffer(cmd));

  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VK_CHECK(vkResetFences(m_device, 1, &m_fence));
  VK_CHECK(vkQueueSubmit(m_queue, 1, &submit, m_fence));
  g_submissions.fetch_add(1, std::memory_order_relaxed);
  VK_CHECK(vkWaitForFences(m_device, 1, &m_fence, VK_TRUE, UINT64_MAX));
}

uint64_t queue_submissions() { return g_submissions.load(std::memory_order_relaxed); }

}  // namespace hipr::vk
