#pragma once
// Bottom-level (one per mesh, one geometry per primitive) and top-level acceleration structures.
#include <vulkan/vulkan.h>

#include <array>
#include <vector>

#include "vk/buffer.h"
#include "vk/context.h"

namespace hipr::vk {

class AccelerationStructure {
 public:
  AccelerationStructure() = default;
  ~AccelerationStructure();
  AccelerationStructure(AccelerationStructure&& other) noexcept;
  AccelerationStructure& operator=(AccelerationStructure&& other) noexcept;
  AccelerationStructure(const AccelerationStructure&) = delete;
  AccelerationStructure& operator=(const AccelerationStructure&) = delete;

  VkAccelerationStructureKHR handle() const { return m_handle; }
  VkDeviceAddress address() const { return m_address; }

 private:
  friend void build_acceleration_structure(const Context&, VkAccelerationStructureTypeKHR,
                                           const std::vector<VkAccelerationStructureGeometryKHR>&,
                                           const std::vector<uint32_t>&, AccelerationStructure&,
                                           Buffer&);
  void release();

  const Context* m_ctx = nullptr;
  Buffer m_storage;
  VkDeviceSize m_size =
      0;  // what the structure was created for: a build that needs no more reuses it
  VkAccelerationStructureKHR m_handle = VK_NULL_HANDLE;
  VkDeviceAddress m_address = 0;
};

// A triangle geometry inside one BLAS: float3 positions and uint32 indices living in the
// shared vertex/index buffers at the given element offsets.
struct TriangleGeometry {
  VkDeviceAddress positions;  // address of the first vertex (vec3, tightly packed)
  uint32_t vertex_count;
  VkDeviceAddress indices;  // address of the first index (uint32)
  uint32_t triangle_count;
  // Opaque geometry never reaches the shader's candidate loop (no alpha test): the fast path.
  bool opaque = true;
};

AccelerationStructure build_blas(const Context& ctx,
                                 const std::vector<TriangleGeometry>& geometries);

struct TlasInstance {
  std::array<float, 12> object_to_world;  // row-major 3x4
  uint32_t custom_index;                  // 24 bits: first GeometryRecord of this instance
  VkDeviceAddress blas;
  bool front_face_ccw = true;
  bool visible = true;  // hidden instances stay in the TLAS with mask 0: no ray ever hits them
};

// The scene's top-level structure and what its builds need, kept between builds: an edit that moves
// an instance rebuilds it in place (instance records written into mapped memory, the storage and
// scratch reused where large enough), one submission and no allocation.
struct Tlas {
  AccelerationStructure structure;
  Buffer instances, scratch;
};

void build_tlas(const Context& ctx, const std::vector<TlasInstance>& instances, Tlas& tlas);

}  // namespace hipr::vk
