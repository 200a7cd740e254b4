#pragma once
// The device hipr renders on: the Vulkan instance, the GPU (or lavapipe's CPU device) and its
// queue. A program that uses the library opens one and hands it to every Renderer.
#include <memory>
#include <string>

namespace hipr {

struct DeviceOptions {
  std::string name;         // a part of the device's name; empty: the best that can render
  bool validation = false;  // Vulkan's validation layers, their errors counted
};

class Device {
 public:
  virtual ~Device() = default;
  virtual const std::string& device_name() const = 0;
  // How kernels trace rays on it: "ray-query" (the driver's acceleration structures) or
  // "software" (hipr's own BVH, on devices without ray queries).
  virtual const char* traversal_name() const = 0;
};

// The best device for hipr (or the one `options.name` names); throws InputError where there is
// none that can render.
std::unique_ptr<Device> open_device(const DeviceOptions& options = {});

}  // namespace hipr
