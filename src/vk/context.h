#pragma once
// The Vulkan instance + device the renderer runs on, and the one queue it uses. Picks the best
// device that can run the kernels: with ray queries (lavapipe in CI, RTX GPUs) they trace
// through the driver's acceleration structures; without (NVIDIA's data-centre GPUs, for one)
// through hipr's own BVH (software traversal: src/render/software_bvh.h).
#include <vulkan/vulkan.h>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "hipr/device.h"

namespace hipr::vk {

// How the kernels trace rays. Automatic: ray queries where the device has them, else the
// software traversal; the environment variable HIPR_TRAVERSAL (ray-query or software) overrides
// it, so a whole test suite can run either way.
enum class Traversal { Automatic, RayQuery, Software };

struct ContextOptions {
  bool validation = false;       // enable VK_LAYER_KHRONOS_validation and count its errors
  std::string preferred_device;  // substring of the device name; empty = best available
  Traversal traversal = Traversal::Automatic;
  // Presentation (the viewer). The window system's instance extensions, and a function that
  // makes the window's surface once the instance exists (the Context then owns the surface).
  // With a surface, only devices whose queue can present to it qualify, and the device gets
  // VK_KHR_swapchain. Without one (the default) the context is headless, as before.
  std::vector<std::string> instance_extensions;
  std::function<VkSurfaceKHR(VkInstance)> create_surface;
  // Tests: fold 1-D dispatches wider than this many workgroups into rows (see
  // max_dispatch_width) as if the device allowed no more; 0 = the device's own limit.
  uint32_t dispatch_width_limit = 0;
  // Tests: as if one storage buffer could address at most this many bytes (maxStorageBufferRange),
  // to reach the limits of big scenes with small ones; 0 = the device's own limit.
  uint64_t storage_range_limit = 0;
  // Device buffers (MemoryUse::Device) are never mapped, even where their memory is host-visible
  // (lavapipe, integrated GPUs): their uploads and read-backs go through staging copies, as on a
  // discrete GPU. The environment variable HIPR_DEVICE_MEMORY=staged sets it, so that tests and
  // measurements on lavapipe take a discrete GPU's path.
  bool staged_device_memory = false;
};

struct DeviceFunctions {
  PFN_vkCreateAccelerationStructureKHR createAccelerationStructure = nullptr;
  PFN_vkDestroyAccelerationStructureKHR destroyAccelerationStructure = nullptr;
  PFN_vkGetAccelerationStructureBuildSizesKHR getAccelerationStructureBuildSizes = nullptr;
  PFN_vkCmdBuildAccelerationStructuresKHR cmdBuildAccelerationStructures = nullptr;
  PFN_vkGetAccelerationStructureDeviceAddressKHR getAccelerationStructureDeviceAddress = nullptr;
};

class StagingBuffers;  // vk/staging.h

class Context final : public Device {
 public:
  explicit Context(const ContextOptions& options = {});
  ~Context() override;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return m_instance; }
  VkPhysicalDevice physical_device() const { return m_physical; }
  VkDevice device() const { return m_device; }
  VkQueue queue() const { return m_queue; }
  VkSurfaceKHR surface() const { return m_surface; }  // VK_NULL_HANDLE when headless
  uint32_t queue_family() const { return m_queue_family; }
  const DeviceFunctions& fn() const { return m_fn; }
  const std::string& device_name() const override { return m_device_name; }
  bool is_cpu_device() const { return m_is_cpu; }
  // The kernels trace hipr's BVH instead of ray queries (HIPR_SOFTWARE_TRAVERSAL=1 in every
  // kernel; GpuScene builds the BVH instead of acceleration structures).
  bool software_traversal() const { return m_software_traversal; }
  bool staged_device_memory() const { return m_staged_device_memory; }
  // Whether the device could trace with ray queries (whichever traversal was chosen).
  bool has_ray_queries() const { return m_has_ray_queries; }
  const char* traversal_name() const override {
    return m_software_traversal ? "software" : "ray-query";
  }
  uint32_t min_storage_alignment() const { return m_min_storage_alignment; }
  // The most bytes one storage buffer binding may address (maxStorageBufferRange).
  uint64_t max_storage_range() const { return m_max_storage_range; }
  uint32_t min_scratch_alignment() const { return m_min_scratch_alignment; }
  // maxComputeWorkGroupCount[0] and [1]: ComputePipeline::dispatch folds wider dispatches.
  uint32_t max_dispatch_width() const { return m_max_dispatch[0]; }
  uint32_t max_dispatch_height() const { return m_max_dispatch[1]; }

  // Records commands into a one-time command buffer, submits it and waits for completion
  // (counted by queue_submissions()).
  void submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const;
  // The staging buffer of copies to and from unmapped device memory (Buffer::upload/download).
  StagingBuffers& staging() const;

  // Messages of severity ERROR reported by the validation layer since start.
  uint32_t validation_errors() const { return m_validation_errors.load(); }
  bool validation_enabled() const { return m_messenger != VK_NULL_HANDLE; }

 private:
  void create_instance(const ContextOptions& options);
  void pick_physical_device(const ContextOptions& options, Traversal traversal);
  void create_device();
  void release();

  static VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(
      VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
      const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);

  VkInstance m_instance = VK_NULL_HANDLE;
  VkSurfaceKHR m_surface = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT m_messenger = VK_NULL_HANDLE;
  VkPhysicalDevice m_physical = VK_NULL_HANDLE;
  VkDevice m_device = VK_NULL_HANDLE;
  VkQueue m_queue = VK_NULL_HANDLE;
  uint32_t m_queue_family = 0;
  VkCommandPool m_command_pool = VK_NULL_HANDLE;
  VkFence m_fence = VK_NULL_HANDLE;
  mutable std::unique_ptr<StagingBuffers> m_staging;  // made at the first staged copy
  DeviceFunctions m_fn;
  std::string m_device_name;
  bool m_is_cpu = false;
  bool m_software_traversal = false;
  bool m_staged_device_memory = false;
  bool m_has_ray_queries = false;
  uint32_t m_min_storage_alignment = 16;
  uint64_t m_max_storage_range = uint64_t(1) << 27;  // the minimum every device supports
  uint32_t m_max_dispatch[2] = {65535, 65535};       // the minimum every device supports
  uint32_t m_min_scratch_alignment = 128;
  std::atomic<uint32_t> m_validation_errors{0};
};

// Submissions waited for by submit_and_wait since the process started: on a GPU each costs a
// round trip through the driver and an idle queue, so an edit's scene update is judged by how
// many it makes.
uint64_t queue_submissions();

}  // namespace hipr::vk
