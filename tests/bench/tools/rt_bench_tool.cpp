// Helper of tests/bench/rt_vs_embree.sh: puts a Diptych scene where Embree's own tutorials can
// read it, and times Diptych's BVH build the way Embree's buildbench times its own.
//   diptych_rt_bench obj SCENE OUT.obj      world-space triangles (the tessellation of analytic
//       shapes) as Wavefront OBJ, one group per instance; prints the camera and point lights as
//       the tutorials' options (--vp/--vi/--vu/--fov, --pointlight) on stdout.
//   diptych_rt_bench build SCENE [REPS]     builds the Embree scene REPS times (default 5) with
//       instancing of repeated meshes off and on; prints the median build time, Embree's peak
//       allocation during a build (rtcSetDeviceMemoryMonitorFunction) and the geometry's bytes.
//   diptych_rt_bench bandwidth [MB]         memcpy bandwidth of this machine on MB-megabyte
//       buffers (default 256: far past the caches), one thread and all threads (TBB, as the
//       per-pixel passes run); counts bytes read + bytes written, as the passes' figure does.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include "engine/rt/rt_scene.h"
#include "engine/scene/load.h"
#include "engine/scene/world_geometry.h"

using namespace diptych;

namespace {

struct Memory {
  std::atomic<long long> current{0}, peak{0};
};

// Embree reports every allocation (bytes > 0) and release (bytes < 0) of the device.
bool monitor(void* user, ssize_t bytes, bool /*post*/) {
  auto* m = static_cast<Memory*>(user);
  const long long now = m->current.fetch_add(bytes) + bytes;
  long long peak = m->peak.load();
  while (now > peak && !m->peak.compare_exchange_weak(peak, now)) {
  }
  return true;
}

int writeObj(const std::string& scenePath, const std::string& out) {
  const Scene scene = loadScene(scenePath);
  const WorldGeometry world = flattenScene(scene);
  std::ofstream f(out);
  if (!f) throw std::runtime_error(out + ": cannot open for writing");
  f << "# " << scenePath << ": world-space triangles written by diptych_rt_bench\n";
  std::size_t base = 1;
  for (const WorldMesh& m : world.meshes) {
    f << "g instance" << m.instance << "\n";
    for (const vec3& p : m.positions) f << "v " << p.x << ' ' << p.y << ' ' << p.z << "\n";
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3)
      f << "f " << base + m.indices[t] << ' ' << base + m.indices[t + 1] << ' '
        << base + m.indices[t + 2] << "\n";
    base += m.positions.size();
  }
  if (!f) throw std::runtime_error(out + ": write failed");
  const Camera& c = scene.camera;
  std::printf("--vp %g %g %g --vi %g %g %g --vu %g %g %g --fov %g", c.position.x, c.position.y,
              c.position.z, c.target.x, c.target.y, c.target.z, c.up.x, c.up.y, c.up.z,
              double(c.verticalFov) * 180.0 / std::numbers::pi);
  for (const Light& l : scene.lights)
    if (l.type == LightType::Point)
      std::printf(" --pointlight %g %g %g %g %g %g", l.position.x, l.position.y, l.position.z,
                  l.color.x * l.intensity, l.color.y * l.intensity, l.color.z * l.intensity);
  std::printf("\n");
  std::fprintf(stderr, "%s: %zu triangles in %zu instances\n", out.c_str(), world.triangleCount(),
               world.meshes.size());
  return 0;
}

int timeBuild(const std::string& scenePath, int reps) {
  const Scene scene = loadScene(scenePath);
  const WorldGeometry world = flattenScene(scene);
  std::size_t bytes = 0;  // the flattened geometry: float3 positions and uint3 triangles
  for (const WorldMesh& m : world.meshes)
    bytes += m.positions.size() * sizeof(vec3) + m.indices.size() * sizeof(std::uint32_t);
  std::printf("scene %s: %zu triangles, %zu instances, geometry %.1f MB\n", scenePath.c_str(),
              world.triangleCount(), world.meshes.size(), double(bytes) / 1e6);
  for (const bool instancing : {false, true}) {
    std::vector<double> ms;
    long long peak = 0;
    int prototypes = 0;
    for (int r = 0; r < reps; ++r) {
      RtDevice device;
      Memory memory;
      rtcSetDeviceMemoryMonitorFunction(device.handle(), monitor, &memory);
      RtSceneOptions options;
      options.instancing = instancing;
      const auto t0 = std::chrono::steady_clock::now();
      const RtScene rt(device, world, scene, options);
      const auto t1 = std::chrono::steady_clock::now();
      ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
      peak = std::max(peak, memory.peak.load());
      prototypes = rt.prototypes();
    }
    std::sort(ms.begin(), ms.end());
    std::printf(
        "build instancing=%s: median %.1f ms (min %.1f, %d runs), %d prototypes, "
        "%.2f Mtris/s, Embree peak %.1f MB = %.2fx the geometry\n",
        instancing ? "on" : "off", ms[ms.size() / 2], ms.front(), reps, prototypes,
        double(world.triangleCount()) / (ms[ms.size() / 2] * 1e3), double(peak) / 1e6,
        double(peak) / double(bytes));
  }
  return 0;
}

double processCpuSeconds() {  // all threads of the process (CLOCK_PROCESS_CPUTIME_ID)
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

struct Bandwidth {
  double wall = 0, cpu = 0;  // GB/s of read + written bytes; cpu: per CPU-second x threads
};

// Median of 9 copies of `mb` MB (after one warm-up that faults the pages in), in GB/s of
// read + written bytes. Chunks of 1 MB spread over TBB's threads when `parallel`. The CPU
// figure divides by (process CPU time / threads), the wall time the copy would take with the
// cores to itself: on a loaded machine the wall figure measures the load, not the memory.
Bandwidth copyBandwidth(std::size_t mb, bool parallel) {
  const std::size_t bytes = mb << 20, chunk = std::size_t(1) << 20;
  const double threads = parallel ? double(tbb::info::default_concurrency()) : 1.0;
  std::vector<char> src(bytes, 1), dst(bytes, 0);
  const auto copy = [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c)
      std::memcpy(dst.data() + c * chunk, src.data() + c * chunk, chunk);
  };
  std::vector<double> wall, cpu;
  for (int rep = 0; rep < 10; ++rep) {
    const double c0 = processCpuSeconds();
    const auto t0 = std::chrono::steady_clock::now();
    if (parallel)
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, bytes / chunk),
          [&](const tbb::blocked_range<std::size_t>& r) { copy(r.begin(), r.end()); });
    else
      copy(0, bytes / chunk);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double c = processCpuSeconds() - c0;
    if (rep == 0) continue;
    wall.push_back(2.0 * double(bytes) / s / 1e9);
    cpu.push_back(2.0 * double(bytes) / (c / threads) / 1e9);
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

int timeBandwidth(std::size_t mb) {
  const Bandwidth one = copyBandwidth(mb, false), all = copyBandwidth(mb, true);
  std::printf(
      "memcpy %zu MB (read + write bytes, median of 9): 1 thread %.2f GB/s, all threads "
      "%.2f GB/s; per CPU time: 1 thread %.2f GB/s, all threads %.2f GB/s\n",
      mb, one.wall, all.wall, one.cpu, all.cpu);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "obj" && argc == 4) return writeObj(argv[2], argv[3]);
    if (mode == "build" && (argc == 3 || argc == 4))
      return timeBuild(argv[2], argc == 4 ? std::max(1, std::atoi(argv[3])) : 5);
    if (mode == "bandwidth" && argc <= 3)
      return timeBandwidth(argc == 3 ? std::size_t(std::max(1, std::atoi(argv[2]))) : 256);
    std::fprintf(stderr, "usage: %s obj SCENE OUT.obj | build SCENE [REPS] | bandwidth [MB]\n",
                 argv[0]);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "diptych_rt_bench: %s\n", e.what());
    return 1;
  }
}
