#include "scene/gltf_draco.h"

#include <draco/compression/decode.h>

#include <cstring>
#include <map>

#include "core/error.h"
#include "scene/gltf_accessors.h"

namespace hipr::gltf {
namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

// Appends `bytes` to the model as a bufferView of a new buffer; returns the view's index.
int append_view(tinygltf::Model& model, std::vector<unsigned char> bytes) {
  tinygltf::Buffer buffer;
  buffer.data = std::move(bytes);
  tinygltf::BufferView view;
  view.buffer = int(model.buffers.size());
  view.byteOffset = 0;
  view.byteLength = buffer.data.size();
  model.buffers.push_back(std::move(buffer));
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size() - 1);
}

// Points accessor `index` at decoded data (a whole bufferView, tightly packed).
void point_accessor(tinygltf::Model& model, int index, int view, int component_type, size_t count) {
  tinygltf::Accessor& accessor = model.accessors[size_t(index)];
  accessor.bufferView = view;
  accessor.byteOffset = 0;
  accessor.componentType = component_type;
  accessor.normalized = false;
  accessor.count = count;
  accessor.sparse.isSparse = false;
  accessor.sparse.count = 0;
}

int accessor_index(const tinygltf::Model& model, int index, const std::string& what) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    throw InputError(what + ": references missing accessor " + std::to_string(index));
  return index;
}

class PrimitiveDecoder {
 public:
  PrimitiveDecoder(tinygltf::Model& model, const std::string& what)
      : m_model(model), m_what(what) {}

  void decode(tinygltf::Primitive& primitive, const tinygltf::Value& ext) {
    if (!ext.IsObject() || !ext.Has("bufferView") || !ext.Get("bufferView").IsInt() ||
        !ext.Has("attributes") || !ext.Get("attributes").IsObject())
      fail(std::string(kExtension) + " needs a bufferView and an attributes object");
    const int view_index = ext.Get("bufferView").Get<int>();
    if (view_index < 0 || size_t(view_index) >= m_model.bufferViews.size())
      fail("Draco data in missing bufferView " + std::to_string(view_index));
    const tinygltf::BufferView& view = m_model.bufferViews[size_t(view_index)];
    if (view.buffer < 0 || size_t(view.buffer) >= m_model.buffers.size())
      fail("Draco bufferView references a missing buffer");
    const std::vector<unsigned char>& data = m_model.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
      fail("Draco bufferView runs past the end of its buffer");

    draco::DecoderBuffer stream;
    stream.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&stream);
    if (!decoded.ok())
      fail("Draco stream does not decode (" + decoded.status().error_msg_string() + ")");
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    const size_t points = mesh->num_points();
    const size_t faces = mesh->num_faces();
    if (points > kMaxSceneElements || faces > kMaxSceneElements / 3)
      fail("Draco mesh of " + std::to_string(points) + " points and " + std::to_string(faces) +
           " triangles is beyond hipr's limits");

    if (primitive.indices >= 0) {
      std::vector<unsigned char> bytes(faces * 3 * 4);
      for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
          const uint32_t v = mesh->face(f)[k].value();
          if (v >= points) fail("Draco triangle references a point past the mesh's end");
          std::memcpy(bytes.data() + (size_t(f.value()) * 3 + size_t(k)) * 4, &v, 4);
        }
      point_accessor(m_model, accessor_index(m_model, primitive.indices, m_what),
                     append_view(m_model, std::move(bytes)), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                     faces * 3);
    } else if (faces * 3 != points) {
      fail("Draco mesh without glTF indices must have three points per triangle");
    }

    for (const auto& [semantic, id] : ext.Get("attributes").Get<tinygltf::Value::Object>()) {
      if (!id.IsInt() || id.Get<int>() < 0)
        fail("Draco attribute " + semantic + " has no valid id");
      const auto it = primitive.attributes.find(semantic);
      if (it == primitive.attributes.end())
        fail("Draco attribute " + semantic + " is not one of the primitive's attributes");
      decode_attribute(*mesh, uint32_t(id.Get<int>()), semantic,
                       accessor_index(m_model, it->second, m_what));
    }
  }

 private:
  [[noreturn]] void fail(const std::string& why) const { throw InputError(m_what + ": " + why); }

  void decode_attribute(const draco::Mesh& mesh, uint32_t id, const std::string& semantic,
                        int accessor) {
    const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(id);
    if (!attribute)
      fail("Draco stream has no attribute " + std::to_string(id) + " for " + semantic);
    const int components = component_count(m_model.accessors[size_t(accessor)].type);
    if (components == 0 || components > 4) fail(semantic + " accessor is not a scalar or vector");
    std::vector<unsigned char> bytes(size_t(mesh.num_points()) * size_t(components) * 4);
    float value[4];
    for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
      std::fill(value, value + 4, 0.0f);
      // Normalized integers come back in [0, 1] or [-1, 1]; quantized positions dequantized.
      if (!attribute->ConvertValue<float>(attribute->mapped_index(p), int8_t(components), value))
        fail("Draco attribute " + semantic + " cannot be read as floats");
      std::memcpy(bytes.data() + size_t(p.value()) * size_t(components) * 4, value,
                  size_t(components) * 4);
    }
    point_accessor(m_model, accessor, append_view(m_model, std::move(bytes)),
                   TINYGLTF_COMPONENT_TYPE_FLOAT, mesh.num_points());
  }

  tinygltf::Model& m_model;
  std::string m_what;
};

}  // namespace

void decode_draco_primitives(tinygltf::Model& model, const std::vector<DracoIndices>& indices,
                             const std::string& name) {
  for (const DracoIndices& set_aside : indices)
    if (set_aside.mesh < model.meshes.size() &&
        set_aside.primitive < model.meshes[set_aside.mesh].primitives.size())
      model.meshes[set_aside.mesh].primitives[set_aside.primitive].indices = set_aside.accessor;
  for (size_t mi = 0; mi < model.meshes.size(); ++mi)
    for (size_t pi = 0; pi < model.meshes[mi].primitives.size(); ++pi) {
      tinygltf::Primitive& primitive = model.meshes[mi].primitives[pi];
      const auto it = primitive.extensions.find(kExtension);
      if (it == primitive.extensions.end()) continue;
      const std::string what =
          name + ": mesh " + std::to_string(mi) + " primitive " + std::to_string(pi);
      PrimitiveDecoder(model, what).decode(primitive, it->second);
    }
}

}  // namespace hipr::gltf
