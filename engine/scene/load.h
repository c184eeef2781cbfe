#pragma once
// Scene input. Every loader either returns a complete, validated scene or throws InputError
// naming the file and the element ("FILE: meshes[2].primitives[0].indices: ..."); it never
// returns a half-loaded scene. Recoveries (e.g. a recomputed zero normal, a skipped line
// primitive) are listed in Scene::warnings. The JSON format is docs/scene-format.md.
#include <filesystem>

#include "engine/scene/scene.h"

namespace diptych {

// Dispatches on the extension: .gltf/.glb -> glTF 2.0, .json -> Diptych JSON scene. Validates
// the result (validateScene) and frames a camera from the bounds when the scene has none.
Scene loadScene(const std::filesystem::path& path);

// Whether loadScene reads `path` as glTF 2.0: its extension is .gltf or .glb, in any case.
bool isGltfPath(const std::filesystem::path& path);

// The individual loaders, unvalidated: loadScene is what programs should call.
Scene loadGltfUnvalidated(const std::filesystem::path& path);
Scene loadJsonSceneUnvalidated(const std::filesystem::path& path);

// One light written as in a JSON scene's "lights" array ('{"type":"point","position":[0,5,0],
// "intensity":20}'); `where` names the source in errors (e.g. "--light").
Light parseLightJson(const std::string& text, const std::string& where);

// The "camera" object of a JSON file (a scene, or a camera the viewer saved), checked as in a
// scene, moved into a rebased world (position and target - worldOrigin, in double: the file is
// in the scene file's coordinates). near/far are 0 when the file gives neither (callers fit
// them: fitNearFar).
Camera readCameraFile(const std::filesystem::path& path, const glm::dvec3& worldOrigin = {});

}  // namespace diptych
