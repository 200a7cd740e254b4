// Which traversal the kernels trace rays with, chosen per device by the host
// (vk::Context::software_traversal, passed as HIPR_SOFTWARE_TRAVERSAL to every kernel):
// 0: ray queries over the driver's acceleration structures; 1: hipr's own BVH in storage
// buffers (bvh_traversal.glsl), for devices without VK_KHR_ray_query (NVIDIA's data-centre
// GPUs, for one). Kernels that trace include this before any declaration: it enables
// GL_EXT_ray_query only where the device has it.
#ifndef HIPR_TRAVERSAL_GLSL
#define HIPR_TRAVERSAL_GLSL

#ifndef HIPR_SOFTWARE_TRAVERSAL
#define HIPR_SOFTWARE_TRAVERSAL 0
#endif
#if !HIPR_SOFTWARE_TRAVERSAL
#extension GL_EXT_ray_query : require
#endif

#endif
