#include "scene/gltf_accessor.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"

namespace mirage::gltf {

namespace {

const char* typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    case TINYGLTF_TYPE_MAT2:
      return "MAT2";
    case TINYGLTF_TYPE_MAT3:
      return "MAT3";
    case TINYGLTF_TYPE_MAT4:
      return "MAT4";
    default:
      return "unknown";
  }
}

int typeOf(int components) {
  static constexpr int kTypes[] = {TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC2, TINYGLTF_TYPE_VEC3,
                                   TINYGLTF_TYPE_VEC4};
  return kTypes[components - 1];
}

size_t componentSize(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

// An accessor's bytes, all checked to lie inside its buffer.
struct Span {
  const unsigned char* data = nullptr;
  size_t stride = 0;
  size_t count = 0;
  int component_type = 0;
};

Span locate(const tinygltf::Model& model, int index, int components, uint64_t max_count,
            const Use& use) {
  const std::string& f = use.file;
  accessorCount(model, index, use);
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  if (a.sparse.isSparse)
    throwInput("{}: {}: accessor {} is sparse, which mirage does not read", f, use.what, index);
  if (a.type != typeOf(components))
    throwInput("{}: {}: accessor {} has type {}; expected {}", f, use.what, index, typeName(a.type),
               typeName(typeOf(components)));
  size_t csize = componentSize(a.componentType);
  if (csize == 0)
    throwInput("{}: {}: accessor {} has the unknown componentType {}", f, use.what, index,
               a.componentType);
  if (a.count > max_count)
    throwInput("{}: {}: accessor {} has {} elements; at most {} are allowed (LoadLimits)", f,
               use.what, index, a.count, max_count);
  if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size())
    throwInput("{}: {}: accessor {} has no valid bufferView ({}; the file has {})", f, use.what,
               index, a.bufferView, model.bufferViews.size());
  const tinygltf::BufferView& v = model.bufferViews[size_t(a.bufferView)];
  if (v.buffer < 0 || size_t(v.buffer) >= model.buffers.size())
    throwInput("{}: {}: bufferView {} refers to buffer {}, but the file has {}", f, use.what,
               a.bufferView, v.buffer, model.buffers.size());
  const std::vector<unsigned char>& buffer = model.buffers[size_t(v.buffer)].data;
  if (v.byteOffset > buffer.size() || v.byteLength > buffer.size() - v.byteOffset)
    throwInput("{}: {}: bufferView {} (bytes {}..{}) lies outside buffer {} of {} bytes", f,
               use.what, a.bufferView, v.byteOffset, uint64_t(v.byteOffset) + v.byteLength,
               v.buffer, buffer.size());
  size_t element = csize * size_t(components);
  size_t stride = v.byteStride ? v.byteStride : element;
  if (stride < element)
    throwInput("{}: {}: bufferView {} has byteStride {}, less than the {} bytes of one element", f,
               use.what, a.bufferView, stride, element);
  Span s{nullptr, stride, a.count, a.componentType};
  if (a.count == 0) return s;
  // The last element must end inside the view: offset + stride * (count - 1) + element <= length,
  // written so that nothing overflows.
  uint64_t length = v.byteLength;
  bool fits = a.byteOffset <= length && element <= length - a.byteOffset &&
              uint64_t(a.count - 1) <= (length - a.byteOffset - element) / stride;
  if (!fits)
    throwInput(
        "{}: {}: accessor {} ({} elements of {} bytes, stride {}, offset {}) does not fit "
        "in bufferView {} of {} bytes",
        f, use.what, index, a.count, element, stride, a.byteOffset, a.bufferView, length);
  s.data = buffer.data() + v.byteOffset + a.byteOffset;
  return s;
}

template <typename T>
T load(const unsigned char* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

}  // namespace

uint64_t accessorCount(const tinygltf::Model& model, int index, const Use& use) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    throwInput("{}: {}: accessor {} does not exist (the file has {})", use.file, use.what, index,
               model.accessors.size());
  return model.accessors[size_t(index)].count;
}

std::vector<float> readFloats(const tinygltf::Model& model, int index, int components,
                              bool normalized_ok, uint64_t max_count, const Use& use) {
  accessorCount(model, index, use);
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  const int ct = a.componentType;
  bool normalized_int = a.normalized && componentSize(ct) > 0 && componentSize(ct) < 4;
  if (ct != TINYGLTF_COMPONENT_TYPE_FLOAT && !(normalized_ok && normalized_int))
    throwInput("{}: {}: accessor {} has componentType {}; expected FLOAT (5126){}", use.file,
               use.what, index, ct, normalized_ok ? " or a normalized byte/short" : "");
  Span s = locate(model, index, components, max_count, use);
  std::vector<float> out(s.count * size_t(components));
  size_t csize = componentSize(ct);
  for (size_t i = 0; i < s.count; ++i) {
    const unsigned char* e = s.data + i * s.stride;
    for (size_t c = 0; c < size_t(components); ++c) {
      const unsigned char* p = e + c * csize;
      float v = 0.0f;
      switch (ct) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
          v = load<float>(p);
          break;
        // The normalisations of the glTF 2.0 specification (3.11, "Animations" table).
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          v = float(load<uint8_t>(p)) / 255.0f;
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
          v = float(load<uint16_t>(p)) / 65535.0f;
          break;
        case TINYGLTF_COMPONENT_TYPE_BYTE:
          v = std::max(float(load<int8_t>(p)) / 127.0f, -1.0f);
          break;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
          v = std::max(float(load<int16_t>(p)) / 32767.0f, -1.0f);
          break;
        default:
          break;
      }
      out[i * size_t(components) + c] = v;
    }
  }
  return out;
}

std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index, uint64_t max_count,
                                  const Use& use) {
  accessorCount(model, index, use);
  int ct = model.accessors[size_t(index)].componentType;
  if (ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      ct != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throwInput(
        "{}: {}: accessor {} has componentType {}; indices must be UNSIGNED_BYTE (5121), "
        "UNSIGNED_SHORT (5123) or UNSIGNED_INT (5125)",
        use.file, use.what, index, ct);
  Span s = locate(model, index, 1, max_count, use);
  std::vector<uint32_t> out(s.count);
  switch (s.component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      for (size_t i = 0; i < s.count; ++i) out[i] = load<uint8_t>(s.data + i * s.stride);
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      for (size_t i = 0; i < s.count; ++i) out[i] = load<uint16_t>(s.data + i * s.stride);
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      for (size_t i = 0; i < s.count; ++i) out[i] = load<uint32_t>(s.data + i * s.stride);
      break;
    default:
      break;  // refused above
  }
  return out;
}

}  // namespace mirage::gltf
