#pragma once
// Variants that compile to the same frame (docs/compare.md, "Same frame, measured once"). A
// slot whose producers the scene culls (texture_filtering on a scene without colour textures)
// leaves every one of its variants the very frame of the variant without it; timing each again
// would only show load noise as if it were the technique's cost. compare times such a variant
// once, under its first name, and reports the others as "same_frame_as" it, with the reason.
#include <string>

#include <nlohmann/json.hpp>

#include "engine/graph/frame_graph.h"
#include "engine/graph/recipe.h"
#include "engine/graph/registry.h"

namespace diptych::cli {

struct FrameIdentity {
  // Canonical JSON of what the frame computes: the scene state it runs on (`sceneState`), every
  // live pass (name, type, domain, parameters with their defaults filled in, reads and writes
  // with their formats and sizes, inputs left out, placement, adaptive choice), the schedule
  // (transfers and default fills with their resource, size and fill value) and the outputs.
  // Culled passes are left out: they run nothing. Equal signatures: the same frame.
  nlohmann::json signature;
  // Every pass, culled or not: name -> {type, params, culled, reason} (for the reason below).
  nlohmann::json passes;
  // The surface detail the variant asked for ("" for as authored): "bump" on a bump-mapped
  // scene, or any mode on a scene without bump maps, leaves the scene as it is.
  std::string askedDetail;
};

FrameIdentity frameIdentity(const CompiledGraph& graph, const Recipe& recipe,
                            const PassRegistry& registry, const nlohmann::json& sceneState,
                            const std::string& askedDetail);

// Why two frames with equal signatures are the same: the passes their recipes set differently
// (type or parameters), all culled, as "texture_filtering culled: scene has no textured
// materials", and "surface_detail bump: the scene as authored" where only the asked detail
// differs; "the same compiled graph" where the variants differ in nothing else.
std::string sameFrameReason(const FrameIdentity& mine, const FrameIdentity& earlier);

}  // namespace diptych::cli
