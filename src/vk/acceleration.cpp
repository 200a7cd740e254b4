#include "vk/acceleration.h"

#include <cstring>
#include <utility>

#include "core/error.h"
#include "vk/check.h"

namespace hipr::vk {

AccelerationStructure::~AccelerationStructure() { release(); }

AccelerationStructure::AccelerationStructure(AccelerationStructure&& other) noexcept {
  *this = std::move(other);
}

AccelerationStructure& AccelerationStructure::operator=(AccelerationStructure&& other) noexcept {
  if (this != &other) {
    release();
    m_ctx = other.m_ctx;
    m_storage = std::move(other.m_storage);
    m_size = std::exchange(other.m_size, 0);
    m_handle = std::exchange(other.m_handle, VK_NULL_HANDLE);
    m_address = std::exchange(other.m_address, 0);
  }
  return *this;
}

void AccelerationStructure::release() {
  if (m_ctx && m_handle)
    m_ctx->fn().destroyAccelerationStructure(m_ctx->device(), m_handle, nullptr);
  m_handle = VK_NULL_HANDLE;
}

// Builds into `target`, whose storage and handle are kept when they hold the new structure, with
// `scratch`, made anew only when short.
void build_acceleration_structure(const Context& ctx, VkAccelerationStructureTypeKHR type,
                                  const std::vector<VkAccelerationStructureGeometryKHR>& geometries,
                                  const std::vector<uint32_t>& primitive_counts,
                                  AccelerationStructure& target, Buffer& scratch) {
  // `geometries` stays alive until the build has executed: lavapipe reads it at record time.
  VkAccelerationStructureBuildGeometryInfoKHR build{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  build.type = type;
  build.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  build.geometryCount = uint32_t(geometries.size());
  build.pGeometries = geometries.data();

  VkAccelerationStructureBuildSizesInfoKHR sizes{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  ctx.fn().getAccelerationStructureBuildSizes(ctx.device(),
                                              VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                              &build, primitive_counts.data(), &sizes);

  if (!target.m_handle || target.m_size < sizes.accelerationStructureSize) {
    target.release();
    target.m_ctx = &ctx;
    target.m_storage = Buffer(ctx, sizes.accelerationStructureSize,
                              VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR);
    target.m_size = sizes.accelerationStructureSize;
    VkAccelerationStructureCreateInfoKHR create{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
    create.buffer = target.m_storage.handle();
    create.size = sizes.accelerationStructureSize;
    create.type = type;
    VK_CHECK(
        ctx.fn().createAccelerationStructure(ctx.device(), &create, nullptr, &target.m_handle));
    VkAccelerationStructureDeviceAddressInfoKHR address{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
    address.accelerationStructure = target.m_handle;
    target.m_address = ctx.fn().getAccelerationStructureDeviceAddress(ctx.device(), &address);
  }

  const VkDeviceSize alignment = ctx.min_scratch_alignment();
  if (!scratch || scratch.size() < sizes.buildScratchSize + alignment)
    scratch = Buffer(ctx, sizes.buildScratchSize + alignment, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  build.dstAccelerationStructure = target.m_handle;
  build.scratchData.deviceAddress = (scratch.address() + alignment - 1) / alignment * alignment;

  std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges(primitive_counts.size());
  for (size_t i = 0; i < ranges.size(); ++i) ranges[i] = {primitive_counts[i], 0, 0, 0};
  const VkAccelerationStructureBuildRangeInfoKHR* range_pointer = ranges.data();
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    ctx.fn().cmdBuildAccelerationStructures(cmd, 1, &build, &range_pointer);
  });
}

AccelerationStructure build_blas(const Context& ctx,
                                 const std::vector<TriangleGeometry>& geometries) {
  std::vector<VkAccelerationStructureGeometryKHR> vk_geometries;
  std::vector<uint32_t> counts;
  for (const TriangleGeometry& g : geometries) {
    VkAccelerationStructureGeometryKHR geometry{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
    // Non-opaque geometry stops ray queries at candidates, where the shader's alpha test
    // decides (shaders/common/cutout.glsl).
    geometry.flags = g.opaque ? VK_GEOMETRY_OPAQUE_BIT_KHR : 0;
    auto& tri = geometry.geometry.triangles;
    tri.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
    tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
    tri.vertexData.deviceAddress = g.positions;
    tri.vertexStride = 3 * sizeof(float);
    tri.maxVertex = g.vertex_count == 0 ? 0 : g.vertex_count - 1;
    tri.indexType = VK_INDEX_TYPE_UINT32;
    tri.indexData.deviceAddress = g.indices;
    vk_geometries.push_back(geometry);
    counts.push_back(g.triangle_count);
  }
  AccelerationStructure blas;
  Buffer scratch;
  build_acceleration_structure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, vk_geometries,
                               counts, blas, scratch);
  return blas;
}

void build_tlas(const Context& ctx, const std::vector<TlasInstance>& instances, Tlas& tlas) {
  std::vector<VkAccelerationStructureInstanceKHR> records(instances.size());
  for (size_t i = 0; i < instances.size(); ++i) {
    const TlasInstance& in = instances[i];
    VkAccelerationStructureInstanceKHR& out = records[i];
    std::memcpy(out.transform.matrix, in.object_to_world.data(), sizeof(out.transform.matrix));
    if (in.custom_index >= (1u << 24))
      throw InputError("scene has too many primitives for one TLAS");
    out.instanceCustomIndex = in.custom_index;
    out.mask = in.visible ? 0xff : 0x00;
    out.instanceShaderBindingTableRecordOffset = 0;
    // Vulkan's default front face is clockwise in its ray space; glTF fronts are counter-clockwise.
    out.flags =
        in.front_face_ccw ? VK_GEOMETRY_INSTANCE_TRIANGLE_FRONT_COUNTERCLOCKWISE_BIT_KHR : 0;
    out.accelerationStructureReference = in.blas;
  }
  write_storage_buffer(ctx, tlas.instances, records,
                       VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR);

  std::vector<VkAccelerationStructureGeometryKHR> geometry(1);
  geometry[0] = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry[0].geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry[0].geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geometry[0].geometry.instances.arrayOfPointers = VK_FALSE;
  geometry[0].geometry.instances.data.deviceAddress = tlas.instances.address();
  build_acceleration_structure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, geometry,
                               {uint32_t(instances.size())}, tlas.structure, tlas.scratch);
}

}  // namespace hipr::vk
