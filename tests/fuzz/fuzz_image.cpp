// libFuzzer harness: the image inputs of `diptych diff` (readLinearImage through OpenImageIO,
// then the metrics on small images). The first byte picks the file extension, which is how
// OpenImageIO chooses the reader to try first.
#include <OpenImageIO/imageio.h>
#include <tbb/global_control.h>

#include "engine/metrics/metrics.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  OIIO::attribute("threads", 1);
  // Only the reader the extension names: trying every other reader on each failing input cut
  // the rate to a few executions per second (the first byte already covers every format).
  OIIO::attribute("try_all_readers", 0);
  OIIO::attribute("exr_threads", 0);  // OpenEXR's own pool: no worker threads either
  // The metrics run on TBB; on a busy machine each hand-off to a worker thread waits for a time
  // slice (0.3 s per input measured), so everything stays on the fuzzing thread.
  static tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const kExtensions[] = {".png", ".exr", ".hdr", ".jpg",
                                            ".tga", ".bmp", ".ppm", ".tif"};
  if (size < 1) return 0;
  const auto path = diptych::fuzz::writeScratch(std::string("image") + kExtensions[data[0] % 8],
                                                data + 1, size - 1);
  diptych::fuzz::expectCleanOutcome([&] {
    const diptych::Image image = diptych::readLinearImage(path);
    // The metrics cost grows with the pixels times FLIP's filter taps (sized by the viewing
    // distance, not by the image), and HDR-FLIP repeats it for up to 64 exposures: at 16x16
    // that was 60% of the harness's time (perf). 4x4 images reach the same code, edges included.
    if (std::size_t(image.width) * image.height <= 4 * 4) {
      diptych::Image other = image;
      for (float& v : other.pixels) v = v * 0.5f + 0.25f;
      diptych::computeMetrics(other, image);
    }
  });
  return 0;
}
