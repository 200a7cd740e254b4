#include "scene/gltf_meshopt.h"

#include <meshoptimizer.h>

#include "core/error.h"

namespace hipr::gltf {
namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";

// The extension's object on a bufferView, read into plain numbers (negative: missing or wrong).
struct Stream {
  int buffer = -1;
  size_t byte_offset = 0;
  size_t byte_length = 0;
  size_t byte_stride = 0;
  size_t count = 0;
  std::string mode;
  std::string filter = "NONE";
};

Stream read_stream(const tinygltf::Value& ext, const std::string& what) {
  const auto fail = [&](const std::string& why) { throw InputError(what + ": " + why); };
  const auto number = [&](const char* key, bool required) -> size_t {
    if (!ext.Has(key)) {
      if (required) fail(std::string(kExtension) + " has no '" + key + "'");
      return 0;
    }
    const tinygltf::Value& v = ext.Get(key);
    if (!v.IsNumber() && !v.IsInt())
      fail(std::string(kExtension) + " '" + key + "' is not a number");
    const double d = v.GetNumberAsDouble();
    if (!(d >= 0.0 && d < 9.0e15) || d != double(size_t(d)))
      fail(std::string(kExtension) + " '" + key + "' is not a valid size");
    return size_t(d);
  };
  const auto text = [&](const char* key, const char* fallback) -> std::string {
    if (!ext.Has(key)) return fallback;
    const tinygltf::Value& v = ext.Get(key);
    if (!v.IsString()) fail(std::string(kExtension) + " '" + key + "' is not a string");
    return v.Get<std::string>();
  };
  if (!ext.IsObject()) fail(std::string(kExtension) + " is not an object");
  Stream s;
  const size_t buffer = number("buffer", true);
  s.buffer = buffer > size_t(INT32_MAX) ? -1 : int(buffer);
  s.byte_offset = number("byteOffset", false);
  s.byte_length = number("byteLength", true);
  s.byte_stride = number("byteStride", true);
  s.count = number("count", true);
  s.mode = text("mode", "");
  s.filter = text("filter", "NONE");
  return s;
}

enum class Filter { kNone, kOctahedral, kQuaternion, kExponential };

// The filter, after checking it suits the stream (strides checked for the mode already).
Filter checked_filter(const Stream& s, const std::string& what) {
  const auto fail = [&](const std::string& why) { throw InputError(what + ": " + why); };
  if (s.filter == "NONE") return Filter::kNone;
  if (s.mode != "ATTRIBUTES") fail("filter " + s.filter + " on " + s.mode + " data");
  if (s.filter == "OCTAHEDRAL") {
    if (s.byte_stride != 4 && s.byte_stride != 8)
      fail("OCTAHEDRAL filter needs a stride of 4 or 8, not " + std::to_string(s.byte_stride));
    return Filter::kOctahedral;
  }
  if (s.filter == "QUATERNION") {
    if (s.byte_stride != 8)
      fail("QUATERNION filter needs a stride of 8, not " + std::to_string(s.byte_stride));
    return Filter::kQuaternion;
  }
  if (s.filter == "EXPONENTIAL") return Filter::kExponential;  // any multiple of 4
  fail("unknown " + std::string(kExtension) + " filter '" + s.filter + "'");
  return Filter::kNone;
}

void decode_view(tinygltf::Model& model, size_t index, const Stream& s, const std::string& what) {
  const auto fail = [&](const std::string& why) { throw InputError(what + ": " + why); };
  if (s.buffer < 0 || size_t(s.buffer) >= model.buffers.size())
    fail("compressed data in missing buffer " + std::to_string(s.buffer));
  const std::vector<unsigned char>& source = model.buffers[size_t(s.buffer)].data;
  if (s.byte_offset > source.size() || s.byte_length > source.size() - s.byte_offset)
    fail("compressed data runs past the end of buffer " + std::to_string(s.buffer));

  const tinygltf::BufferView& view = model.bufferViews[index];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    fail("references a missing buffer");
  std::vector<unsigned char>& target = model.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > target.size() || view.byteLength > target.size() - view.byteOffset)
    fail("runs past the end of its buffer");
  if (view.buffer == s.buffer && view.byteOffset < s.byte_offset + s.byte_length &&
      s.byte_offset < view.byteOffset + view.byteLength)
    fail("decodes over its own compressed data");
  if (s.mode == "ATTRIBUTES") {
    if (s.byte_stride == 0 || s.byte_stride % 4 != 0 || s.byte_stride > 256)
      fail("ATTRIBUTES stride " + std::to_string(s.byte_stride) +
           " is not a multiple of 4 up to 256");
  } else if (s.mode == "TRIANGLES" || s.mode == "INDICES") {
    if (s.byte_stride != 2 && s.byte_stride != 4)
      fail(s.mode + " stride " + std::to_string(s.byte_stride) + " is not 2 or 4");
    if (s.mode == "TRIANGLES" && s.count % 3 != 0)
      fail("TRIANGLES count " + std::to_string(s.count) + " is not a multiple of 3");
  } else {
    fail("unknown " + std::string(kExtension) + " mode '" + s.mode + "'");
  }
  const Filter filter = checked_filter(s, what);
  if (s.count > view.byteLength / s.byte_stride)
    fail("decodes " + std::to_string(s.count) + " elements of " + std::to_string(s.byte_stride) +
         " bytes, more than its byteLength " + std::to_string(view.byteLength));

  unsigned char* out = target.data() + view.byteOffset;
  const unsigned char* in = source.data() + s.byte_offset;
  const int status =
      s.mode == "ATTRIBUTES"
          ? meshopt_decodeVertexBuffer(out, s.count, s.byte_stride, in, s.byte_length)
      : s.mode == "TRIANGLES"
          ? meshopt_decodeIndexBuffer(out, s.count, s.byte_stride, in, s.byte_length)
          : meshopt_decodeIndexSequence(out, s.count, s.byte_stride, in, s.byte_length);
  if (status != 0)
    fail("meshopt stream does not decode (meshoptimizer error " + std::to_string(status) + ")");

  switch (filter) {
    case Filter::kOctahedral:
      meshopt_decodeFilterOct(out, s.count, s.byte_stride);
      break;
    case Filter::kQuaternion:
      meshopt_decodeFilterQuat(out, s.count, s.byte_stride);
      break;
    case Filter::kExponential:
      meshopt_decodeFilterExp(out, s.count, s.byte_stride);
      break;
    case Filter::kNone:
      break;
  }
}

}  // namespace

void decode_meshopt_views(tinygltf::Model& model, const std::vector<FallbackBuffer>& fallbacks,
                          const std::string& name) {
  for (const FallbackBuffer& fallback : fallbacks) {
    if (fallback.index >= model.buffers.size()) continue;  // cannot happen: same document
    model.buffers[fallback.index].data.assign(fallback.byte_length, 0);
    model.buffers[fallback.index].uri.clear();
  }
  for (size_t i = 0; i < model.bufferViews.size(); ++i) {
    const auto it = model.bufferViews[i].extensions.find(kExtension);
    if (it == model.bufferViews[i].extensions.end()) continue;
    const std::string what = name + ": bufferView " + std::to_string(i);
    decode_view(model, i, read_stream(it->second, what), what);
  }
}

}  // namespace hipr::gltf
