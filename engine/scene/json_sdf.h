#pragma once
// The "sdf" object of the JSON scene format (docs/scene-format.md, docs/geometry.md): a tree of
// signed-distance primitives and CSG operations, sphere-traced by the ray tracers and
// polygonised (surface nets) for the rasterizer.
#include <string>

#include "engine/scene/json_reader.h"
#include "engine/scene/scene.h"

namespace diptych {

// Reads "shape", "tolerance", "max_steps", "relaxation", "resolution" from an object of type
// "sdf"; returns the polygonised mesh with Mesh::sdf set. Errors name the JSON path.
Mesh readSdfObject(jsonread::JsonObject& o);

}  // namespace diptych
