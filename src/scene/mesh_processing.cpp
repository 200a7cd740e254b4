#include "scene/mesh_processing.h"

#include <cmath>

#include "core/error.h"

namespace hipr {
namespace {

bool usable(const glm::vec3& v) {
  const float len2 = glm::dot(v, v);
  return std::isfinite(len2) && len2 > 1e-20f;
}

// Any unit vector perpendicular to n (n must be unit length).
glm::vec3 perpendicular(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(axis, n));
}

glm::vec3 face_normal(const MeshPrimitive& p, size_t tri) {
  const glm::vec3& a = p.positions[p.indices[3 * tri]];
  const glm::vec3& b = p.positions[p.indices[3 * tri + 1]];
  const glm::vec3& c = p.positions[p.indices[3 * tri + 2]];
  return glm::cross(b - a, c - a);  // counter-clockwise front face, length = 2 * area
}

void make_flat(MeshPrimitive& p) {
  MeshPrimitive flat;
  flat.material = p.material;
  flat.variant_materials = p.variant_materials;
  flat.default_material = p.default_material;
  const size_t triangles = p.indices.size() / 3;
  for (size_t t = 0; t < triangles; ++t) {
    glm::vec3 n = face_normal(p, t);
    n = usable(n) ? glm::normalize(n) : glm::vec3(0, 1, 0);
    for (int k = 0; k < 3; ++k) {
      const uint32_t i = p.indices[3 * t + size_t(k)];
      flat.positions.push_back(p.positions[i]);
      flat.normals.push_back(n);
      flat.uvs.push_back(p.uvs.empty() ? glm::vec2(0) : p.uvs[i]);
      flat.uvs1.push_back(p.uvs1.empty() ? glm::vec2(0) : p.uvs1[i]);
      if (!p.tangents.empty()) flat.tangents.push_back(p.tangents[i]);
      flat.indices.push_back(uint32_t(3 * t + size_t(k)));
    }
  }
  p = std::move(flat);
}

// Per-vertex tangents from UV derivatives (Lengyel's method), Gram-Schmidt against the normal.
void generate_tangents(MeshPrimitive& p) {
  std::vector<glm::vec3> tan(p.positions.size(), glm::vec3(0));
  std::vector<glm::vec3> bitan(p.positions.size(), glm::vec3(0));
  for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
    const uint32_t i0 = p.indices[t], i1 = p.indices[t + 1], i2 = p.indices[t + 2];
    const glm::vec3 e1 = p.positions[i1] - p.positions[i0];
    const glm::vec3 e2 = p.positions[i2] - p.positions[i0];
    const glm::vec2 d1 = p.uvs[i1] - p.uvs[i0];
    const glm::vec2 d2 = p.uvs[i2] - p.uvs[i0];
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!std::isfinite(det) || std::abs(det) < 1e-20f) continue;
    const float r = 1.0f / det;
    const glm::vec3 sdir = (e1 * d2.y - e2 * d1.y) * r;
    const glm::vec3 tdir = (e2 * d1.x - e1 * d2.x) * r;
    for (uint32_t i : {i0, i1, i2}) {
      tan[i] += sdir;
      bitan[i] += tdir;
    }
  }
  p.tangents.resize(p.positions.size());
  for (size_t i = 0; i < p.positions.size(); ++i) {
    const glm::vec3& n = p.normals[i];
    glm::vec3 t = tan[i] - n * glm::dot(n, tan[i]);
    t = usable(t) ? glm::normalize(t) : perpendicular(n);
    // glTF: bitangent = cross(normal, tangent.xyz) * w
    const float w = glm::dot(glm::cross(n, t), bitan[i]) < 0.0f ? -1.0f : 1.0f;
    p.tangents[i] = glm::vec4(t, w);
  }
}

}  // namespace

std::vector<uint32_t> triangulate(const std::vector<uint32_t>& indices, int mode) {
  std::vector<uint32_t> out;
  for (size_t i = 2; i < indices.size(); ++i) {
    if (mode == 5) {  // strip: alternate winding so every triangle keeps the front face
      if (i % 2 == 0)
        out.insert(out.end(), {indices[i - 2], indices[i - 1], indices[i]});
      else
        out.insert(out.end(), {indices[i - 1], indices[i - 2], indices[i]});
    } else {  // fan
      out.insert(out.end(), {indices[0], indices[i - 1], indices[i]});
    }
  }
  return out;
}

void complete_primitive(MeshPrimitive& p, const std::string& what) {
  const size_t vertices = p.positions.size();
  p.indices.resize(p.indices.size() / 3 * 3);
  for (uint32_t i : p.indices) {
    if (i >= vertices)
      throw InputError(what + ": index " + std::to_string(i) + " >= vertex count " +
                       std::to_string(vertices));
  }
  if (!p.uvs.empty() && p.uvs.size() != vertices)
    throw InputError(what + ": TEXCOORD_0 count differs from POSITION");
  if (!p.uvs1.empty() && p.uvs1.size() != vertices)
    throw InputError(what + ": TEXCOORD_1 count differs from POSITION");
  if (!p.normals.empty() && p.normals.size() != vertices)
    throw InputError(what + ": NORMAL count differs from POSITION");
  if (!p.tangents.empty() && p.tangents.size() != vertices)
    throw InputError(what + ": TANGENT count differs from POSITION");

  if (p.normals.empty()) make_flat(p);
  if (p.uvs.empty()) p.uvs.assign(p.positions.size(), glm::vec2(0));
  if (p.uvs1.empty()) p.uvs1.assign(p.positions.size(), glm::vec2(0));

  // Unusable normals (zero, NaN) fall back to the face normal of a triangle using the vertex.
  std::vector<glm::vec3> fallback(p.positions.size(), glm::vec3(0));
  for (size_t t = 0; t < p.indices.size() / 3; ++t) {
    const glm::vec3 n = face_normal(p, t);
    for (int k = 0; k < 3; ++k)
      fallback[p.indices[3 * t + size_t(k)]] += usable(n) ? n : glm::vec3(0);
  }
  for (size_t i = 0; i < p.normals.size(); ++i) {
    glm::vec3& n = p.normals[i];
    if (usable(n))
      n = glm::normalize(n);
    else
      n = usable(fallback[i]) ? glm::normalize(fallback[i]) : glm::vec3(0, 1, 0);
  }

  bool tangents_ok = !p.tangents.empty();
  for (const glm::vec4& t : p.tangents) tangents_ok = tangents_ok && usable(glm::vec3(t));
  if (!tangents_ok) {
    p.tangents.clear();
    generate_tangents(p);
  } else {
    for (size_t i = 0; i < p.tangents.size(); ++i) {
      const glm::vec3 t = glm::normalize(glm::vec3(p.tangents[i]));
      p.tangents[i] = glm::vec4(t, p.tangents[i].w < 0.0f ? -1.0f : 1.0f);
    }
  }
}

}  // namespace hipr
