#pragma once
// Fuzz builds (tests/fuzz/CMakeLists.txt defines DIPTYCH_FUZZ_WORK_LIMITS) scale the limits on
// the work one input may ask for (SDF distance evaluations, triangles, image values) by 1/1024,
// so that every input runs in milliseconds under ASan and the fuzzer explores instead of
// waiting on a legal but expensive input (a 256^3 SDF grid took over 60 s there). The checks are
// the same code; only their thresholds are lower (docs/robustness.md).
namespace diptych {
#ifdef DIPTYCH_FUZZ_WORK_LIMITS
inline constexpr double kWorkLimitScale = 1.0 / 1024;
#else
inline constexpr double kWorkLimitScale = 1.0;
#endif
}  // namespace diptych
