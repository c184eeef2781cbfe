#pragma once
// Generic, bounds-checked reading of glTF accessors (glTF 2.0 spec, section 3.6 "Binary Data
// Storage"): any component type, normalized integers, byteStride and sparse substitution. Every
// failure is an InputError that names the accessor and the place that referenced it.
#include "engine/scene/gltf/tinygltf.h"

#include <cstdint>
#include <string>
#include <vector>

namespace diptych::gltf {

// Where an accessor is being read from, for error messages: file plus e.g.
// "meshes[2].primitives[0].attributes.POSITION".
struct AccessorSite {
  const std::string& file;
  std::string place;
};

// Reads accessor `index` as `components` floats per element (row-major, element after element).
// Normalized integer components are mapped to [0,1] or [-1,1] as the spec's section 3.11 says;
// non-normalized integers are converted to float unchanged (KHR_mesh_quantization style).
// Rejects a type whose component count differs from `components`, and non-finite values.
std::vector<float> readFloatAccessor(const tinygltf::Model& model, int index, int components,
                                     const AccessorSite& site);

// Reads a SCALAR unsigned index accessor (UNSIGNED_BYTE/SHORT/INT) as 32-bit indices.
std::vector<std::uint32_t> readIndexAccessor(const tinygltf::Model& model, int index,
                                             const AccessorSite& site);

}  // namespace diptych::gltf
