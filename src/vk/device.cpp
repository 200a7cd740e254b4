// The public Device is a vk::Context: the only device hipr has.
#include "hipr/device.h"

#include "vk/context.h"

namespace hipr {

std::unique_ptr<Device> open_device(const DeviceOptions& options) {
  vk::ContextOptions context;
  context.preferred_device = options.name;
  context.validation = options.validation;
  return std::make_unique<vk::Context>(context);
}

}  // namespace hipr
