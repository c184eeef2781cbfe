#pragma once
// Lighting for scenes that bring none (docs/materials.md, "Default lighting"). Many glTF sample
// models (DamagedHelmet, ...) have no KHR_lights_punctual light and no environment; rendered as
// they are, only emission shows. The program (not the loaders: tests and library users see the
// file as it is) adds a documented default, or what the user gives with --env / --light.
#include <optional>
#include <string>

#include "engine/scene/scene.h"

namespace diptych {

// What the user asked for on the command line. Empty strings: not given.
struct LightingOptions {
  std::string environmentFile;  // --env FILE (.hdr, .exr, any image): equirect environment
  std::string lightJson;        // --light '{"type":"directional",...}' (scene-format light)
};

// True when the scene has no light and its environment is black: nothing but emission shows.
bool sceneIsUnlit(const Scene& scene);

// One line for a scene loaded from a glTF file (Scene::sourcePath .gltf/.glb) that brings its
// own lights but no environment: it is
// left as it is (applyLighting), so its background, mirror reflections and transmission show
// black, and a file made for a viewer with image-based light (IridescenceSuzanne's one 2-lux
// light) renders dark; the line names --env. Nothing for JSON scenes, whose authors chose their
// environment, or where the environment is not black.
std::optional<std::string> darkEnvironmentHint(const Scene& scene);

// The procedural sky: an equirect image (width x width/2) with a zenith-to-horizon gradient
// above the horizon and a dim ground below (radiance values in docs/materials.md).
Environment proceduralSky(int width = 256);

// The default sun: a directional light from above, behind the camera's left shoulder, so that
// what the camera sees is lit from the front; it casts shadows. `camera` is the frame's camera.
Light defaultSun(const Camera& camera);

// Applies the options and, when the scene is still unlit, the default (procedural sky + sun).
// --env replaces the environment and --light adds a light whatever the scene has (the user
// asked); a scene with its own lights or environment is otherwise never changed. Returns one
// line saying what was added, or nothing when the scene was left as it is. Throws InputError
// naming --env / --light on bad input.
std::optional<std::string> applyLighting(Scene& scene, const Camera& camera,
                                         const LightingOptions& options);

}  // namespace diptych
