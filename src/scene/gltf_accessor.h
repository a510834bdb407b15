// Reading glTF accessors safely: every index, type, stride and byte range is checked against the
// buffers before a byte is read, so a malformed file gives an InputError, never a read out of
// bounds. Sparse accessors and accessors without a buffer view are refused.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/gltf_model.h"

namespace mirage::gltf {

// Names the file and the accessor's use for messages: "mesh 'hull' primitive 0 NORMAL".
struct Use {
  const std::string& file;
  std::string what;
};

// Reads accessor `index` as `components` floats per element (type SCALAR/VEC2/VEC3/VEC4). FLOAT
// always; normalized integer types too when `normalized_ok` (texture coordinates). At most
// `max_count` elements.
std::vector<float> readFloats(const tinygltf::Model& model, int index, int components,
                              bool normalized_ok, uint64_t max_count, const Use& use);

// Reads an index accessor (SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT).
std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index, uint64_t max_count,
                                  const Use& use);

// The number of elements of accessor `index` (checked to exist).
uint64_t accessorCount(const tinygltf::Model& model, int index, const Use& use);

}  // namespace mirage::gltf
