#pragma once
// Companion outputs: further outputs of the pass that wrote an input, read without a recipe
// connection, and outputs that a pass may leave unwritten when nothing consumes them. The
// G-buffer's `surface` (gbuffer_raster.h) is the use: every GL producer that reads `hits` reads
// the surface beside it, and the G-buffer writes it only for a frame that has such a reader.
#include <string>

#include "engine/graph/pass.h"

namespace diptych {

// Reads the output `output` of the pass that wrote `of` (during setup): kNoResource when `of` is
// kNoResource or that pass writes no such output; an InputError when its format differs. With
// `glOnly`, the read holds only while the reader runs on GL: compile drops it from a pass placed
// on the CPU (placement.h, dropGlOnlyReads), so it never costs a readback.
inline ResourceId readCompanion(PassBuilder& builder, ResourceId of, const std::string& output,
                                Format expected, bool glOnly) {
  return builder.readCompanion(of, output, expected, glOnly);
}

// Whether a live pass reads `id` or the frame outputs it (during execute); true outside the
// frame graph's executor.
inline bool consumed(const PassContext& context, ResourceId id) {
  return context.consumed(id);
}

}  // namespace diptych
