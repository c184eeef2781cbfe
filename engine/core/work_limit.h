#pragma once
// Fuzz builds (tests/fuzz/CMakeLists.txt defines DIPTYCH_FUZZ_WORK_LIMITS) scale the limits on
// the work one input may ask for (SDF distance evaluations, triangles, image values) by 1/1024,
// so that every input runs in milliseconds under ASan and the fuzzer explores instead of
// waiting on a legal but expensive input (a 256^3 SDF grid took over 60 s there). The checks are
// the same code; only their thresholds are lower (docs/robustness.md).
namespace diptych {
#ifdef DIPTYCH_FUZZ_WORK_LIMITS
inline constexpr double kWorkLimitScale = 1.0 / 1024;
// Two limits get a further 1/16, where perf showed one fuzz input still costing tens of ms:
// SDF polygonisation (every node at every grid point, then six more per vertex for normals; 90%
// of fuzz_scene_json's time at 1/1024) and image values (large buffers are mapped and zeroed
// per input under ASan; most of fuzz_image's time). 90k evaluations is resolution 44 for one
// node; 16k values a 64x64 RGBA image.
inline constexpr double kSdfWorkLimitScale = kWorkLimitScale / 16;
inline constexpr double kImageWorkLimitScale = kWorkLimitScale / 16;
#else
inline constexpr double kWorkLimitScale = 1.0;
inline constexpr double kSdfWorkLimitScale = 1.0;
inline constexpr double kImageWorkLimitScale = 1.0;
#endif
}  // namespace diptych
