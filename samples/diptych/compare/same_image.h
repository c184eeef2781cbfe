#pragma once
// Variants whose frames differ but whose images do not (docs/compare.md, "Same image"). On
// whitted the three environment-map parameterisations return the same pixels, because the
// environment is one colour, and sorted and unsorted blending do too, because there is one
// transparent object: the techniques differ, the scene cannot tell them apart. Timed separately
// (their frames are not the same: same_frame.h), such variants used to show identical error
// columns with nothing said; compare now names the earlier variant whose image it is, how far
// apart the two are, and why where it can tell.
#include <limits>
#include <string>

#include "engine/core/image.h"
#include "engine/scene/scene.h"
#include "samples/diptych/compare/same_frame.h"

namespace diptych::cli {

// Two images are the same image when no sample differs by more than this, relative to the larger
// magnitude of the two (or to 1e-6 for samples nearer 0): float rounding of the same value
// through two paths (1e-7 on whitted's sky, taken from a cube face or from a sphere map) passes;
// an 8-bit display step (4e-3) or half-float rounding (5e-4) is 40-400 times larger.
constexpr double kSameImageTolerance = 1e-5;

// The largest per-sample difference of a and b relative to max(|a|, |b|, 1e-6); infinity when
// their sizes differ or one is NaN where the other is not. It stops at the first sample past
// `stopAbove` and returns that sample's difference (compare tries every earlier variant).
double largestRelativeDifference(const Image& a, const Image& b,
                                 double stopAbove = std::numeric_limits<double>::infinity());

// Why a variant's image is an earlier one's: the live passes the two frames set differently
// ("reflection: env_sphere, not env_cube"), then, where the scene explains it, the reason: an
// environment of one colour for the environment-map producers, at most one transparent mesh for
// the blending producers; otherwise that the scene does not tell the producers apart.
std::string sameImageReason(const FrameIdentity& mine, const FrameIdentity& earlier,
                            const Scene& scene);

}  // namespace diptych::cli
