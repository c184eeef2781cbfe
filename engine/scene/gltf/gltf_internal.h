#pragma once
// Pieces of the glTF loader shared between its files (not part of the engine's public API).
#include "engine/scene/gltf/tinygltf.h"

#include <string>
#include <vector>

#include "engine/scene/scene.h"

namespace diptych::gltf {

// What the image-loader callback produced for each glTF image, by image index: the decoded
// pixels, or why decoding failed (reported only if a material uses the image).
struct DecodedImages {
  std::vector<Image> images;
  std::vector<std::string> errors;
};

// Fills scene.materials (one per glTF material, same index) and the textures they use.
void convertMaterials(const tinygltf::Model& model, const DecodedImages& decoded,
                      const std::string& file, Scene& scene);

// Converts each glTF mesh primitive into one Mesh; result[m] lists the Mesh indices made from
// glTF mesh m (non-triangle primitives are skipped with a warning).
std::vector<std::vector<int>> convertMeshes(const tinygltf::Model& model, const std::string& file,
                                            Scene& scene);

// KHR_materials_volume's thicknessFactor is in the mesh's own units (glTF spec): scales each
// volume material's thickness into world units by the cube root of |det| of its instances'
// transform (the mean axis scale; exact for uniform scales). A material placed at several scales
// is split: one copy of the material and of each mesh using it per further scale.
void scaleVolumeThickness(Scene& scene);

}  // namespace diptych::gltf
