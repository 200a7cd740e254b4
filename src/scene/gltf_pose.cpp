#include "scene/gltf_pose.h"

#include <cmath>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/log.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_node_transform.h"

namespace hipr::gltf {
namespace {

bool finite(const glm::mat4& m) {
  for (int i = 0; i < 16; ++i)
    if (!std::isfinite(glm::value_ptr(m)[i])) return false;
  return true;
}

int attribute(const std::map<std::string, int>& attributes, const std::string& name) {
  const auto it = attributes.find(name);
  return it == attributes.end() ? -1 : it->second;
}

}  // namespace

MeshPoses::MeshPoses(const tinygltf::Model& model, const std::string& name)
    : m_model(model), m_name(name), m_poses(model.meshes.size()) {
  const size_t count = model.nodes.size();
  m_parents.assign(count, -1);
  m_locals.assign(count, glm::mat4(1.0f));
  for (size_t i = 0; i < count; ++i) {
    const tinygltf::Node& node = model.nodes[i];
    if (node.matrix.empty() || node.matrix.size() == 16)
      m_locals[i] = local_transform(node.matrix, node.translation, node.rotation, node.scale);
    if (!finite(m_locals[i])) m_locals[i] = glm::mat4(1.0f);  // refused later, with its name
    for (int child : node.children)
      if (child >= 0 && size_t(child) < count && m_parents[size_t(child)] < 0 && child != int(i))
        m_parents[size_t(child)] = int(i);
  }
  for (size_t m = 0; m < model.meshes.size(); ++m)
    for (const double w : model.meshes[m].weights) m_poses[m].weights.push_back(float(w));
  std::vector<bool> posed(model.meshes.size(), false);
  for (size_t i = 0; i < count; ++i) {
    const tinygltf::Node& node = model.nodes[i];
    if (node.mesh < 0 || size_t(node.mesh) >= model.meshes.size()) continue;
    if (node.skin < 0 && node.weights.empty()) continue;
    Pose& pose = m_poses[size_t(node.mesh)];
    const std::string what = name + ": node " + std::to_string(i);
    if (node.skin >= 0 && size_t(node.skin) >= model.skins.size())
      throw InputError(what + " references missing skin " + std::to_string(node.skin));
    if (posed[size_t(node.mesh)]) {
      log::warn(what + " shows mesh " + std::to_string(node.mesh) +
                " in another pose than an earlier node; hipr shows the earlier one's");
      continue;
    }
    posed[size_t(node.mesh)] = true;
    if (!node.weights.empty()) {
      pose.weights.clear();
      for (const double w : node.weights) pose.weights.push_back(float(w));
    }
    pose.skin = node.skin;
    pose.node = int(i);
  }
}

glm::mat4 MeshPoses::world(int node) const {
  glm::mat4 m(1.0f);
  // A cycle (refused later with a clear message) must not hang here: at most `count` steps.
  for (size_t steps = 0; node >= 0 && steps <= m_locals.size(); ++steps) {
    m = m_locals[size_t(node)] * m;
    node = m_parents[size_t(node)];
  }
  return m;
}

void MeshPoses::apply(size_t mesh, const tinygltf::Primitive& source, MeshPrimitive& p,
                      const std::string& what) const {
  if (mesh >= m_poses.size()) return;
  const Pose& pose = m_poses[mesh];
  if (!source.targets.empty()) morph(pose, source, p, what);
  if (pose.skin >= 0) skin(pose, source, p, what);
}

void MeshPoses::morph(const Pose& pose, const tinygltf::Primitive& source, MeshPrimitive& p,
                      const std::string& what) const {
  for (size_t t = 0; t < source.targets.size(); ++t) {
    const float w = t < pose.weights.size() ? pose.weights[t] : 0.0f;
    if (w == 0.0f || !std::isfinite(w)) continue;
    const std::string target = what + " morph target " + std::to_string(t);
    const auto add = [&](const char* name, auto& vertices, int components) {
      const int accessor = attribute(source.targets[t], name);
      if (accessor < 0 || vertices.empty()) return;
      const std::vector<float> delta =
          read_floats(m_model, accessor, components, target + " " + name);
      if (delta.size() != vertices.size() * size_t(components))
        throw InputError(target + " " + name + " has another count than the primitive's");
      for (size_t v = 0; v < vertices.size(); ++v)
        for (int c = 0; c < components; ++c)
          vertices[v][c] += w * delta[v * size_t(components) + size_t(c)];
    };
    add("POSITION", p.positions, 3);
    add("NORMAL", p.normals, 3);
    // A tangent target moves xyz; its handedness (w) stays.
    const int tangent = attribute(source.targets[t], "TANGENT");
    if (tangent >= 0 && !p.tangents.empty()) {
      const std::vector<float> delta = read_floats(m_model, tangent, 3, target + " TANGENT");
      if (delta.size() != p.tangents.size() * 3)
        throw InputError(target + " TANGENT has another count than the primitive's");
      for (size_t v = 0; v < p.tangents.size(); ++v)
        for (int c = 0; c < 3; ++c) p.tangents[v][c] += w * delta[v * 3 + size_t(c)];
    }
  }
}

void MeshPoses::skin(const Pose& pose, const tinygltf::Primitive& source, MeshPrimitive& p,
                     const std::string& what) const {
  const tinygltf::Skin& skin = m_model.skins[size_t(pose.skin)];
  const std::string where = what + " (skin " + std::to_string(pose.skin) + ")";
  const size_t joints = skin.joints.size();
  std::vector<float> inverse_binds;
  if (skin.inverseBindMatrices >= 0) {
    inverse_binds =
        read_floats(m_model, skin.inverseBindMatrices, 16, where + " inverseBindMatrices");
    if (inverse_binds.size() < joints * 16)
      throw InputError(where + ": fewer inverseBindMatrices than joints");
  }
  // Each joint's matrix, taken into the frame of the node showing the mesh (whose own
  // transform glTF ignores for skinned meshes: the instance applies it, so it is undone here).
  const glm::mat4 to_node = glm::inverse(world(pose.node));
  std::vector<glm::mat4> matrices(joints, glm::mat4(1.0f));
  for (size_t j = 0; j < joints; ++j) {
    const int joint = skin.joints[j];
    if (joint < 0 || size_t(joint) >= m_model.nodes.size())
      throw InputError(where + " references missing joint node " + std::to_string(joint));
    const glm::mat4 bind =
        inverse_binds.empty() ? glm::mat4(1.0f) : glm::make_mat4(&inverse_binds[j * 16]);
    matrices[j] = to_node * world(joint) * bind;
    if (!finite(matrices[j]))
      throw InputError(where + ": joint " + std::to_string(j) + " is degenerate");
  }

  const size_t vertices = p.positions.size();
  std::vector<glm::mat4> blended(vertices, glm::mat4(0.0f));
  std::vector<float> total(vertices, 0.0f);
  for (int set = 0;; ++set) {
    const int joint_accessor = attribute(source.attributes, "JOINTS_" + std::to_string(set));
    const int weight_accessor = attribute(source.attributes, "WEIGHTS_" + std::to_string(set));
    if (joint_accessor < 0 || weight_accessor < 0) break;
    const std::vector<float> ids =
        read_floats(m_model, joint_accessor, 4, where + " JOINTS_" + std::to_string(set));
    const std::vector<float> weights =
        read_floats(m_model, weight_accessor, 4, where + " WEIGHTS_" + std::to_string(set));
    if (ids.size() != vertices * 4 || weights.size() != vertices * 4)
      throw InputError(where + ": JOINTS/WEIGHTS count differs from POSITION");
    for (size_t v = 0; v < vertices; ++v)
      for (int k = 0; k < 4; ++k) {
        const float w = weights[v * 4 + size_t(k)];
        if (w == 0.0f) continue;
        const float id = ids[v * 4 + size_t(k)];
        if (!(id >= 0.0f && id < float(joints)))
          throw InputError(where + ": a vertex names joint " + std::to_string(int(id)) + " of " +
                           std::to_string(joints));
        blended[v] += w * matrices[size_t(id)];
        total[v] += w;
      }
  }
  for (size_t v = 0; v < vertices; ++v) {
    // Weights should sum to one; a vertex with none stays where the node puts it.
    const glm::mat4 m = total[v] > 0.0f ? blended[v] / total[v] : glm::mat4(1.0f);
    p.positions[v] = glm::vec3(m * glm::vec4(p.positions[v], 1.0f));
    const glm::mat3 linear(m);
    if (!p.normals.empty()) p.normals[v] = glm::transpose(glm::inverse(linear)) * p.normals[v];
    if (!p.tangents.empty())
      p.tangents[v] = glm::vec4(linear * glm::vec3(p.tangents[v]), p.tangents[v].w);
  }
}

}  // namespace hipr::gltf
