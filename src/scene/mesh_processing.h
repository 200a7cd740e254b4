#pragma once
// Fills in what a mesh primitive lacks so every primitive the renderer sees is complete:
// triangle lists, flat normals when none are given, tangents from UVs, finite unit vectors.
#include "hipr/scene.h"

namespace hipr {

// Converts a strip (mode 5) or fan (mode 6) index list into a triangle list.
std::vector<uint32_t> triangulate(const std::vector<uint32_t>& indices, int mode);

// Given positions + indices (+ optional normals/uvs/tangents), produces a complete primitive:
// without normals the triangles are unwelded and get flat normals (as glTF requires);
// tangents come from UV derivatives when absent. Throws InputError on out-of-range indices.
void complete_primitive(MeshPrimitive& primitive, const std::string& what);

}  // namespace hipr
