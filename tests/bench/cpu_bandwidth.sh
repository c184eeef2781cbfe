#!/usr/bin/env bash
# Every per-pixel CPU node of a frame against this machine's memory bandwidth, in ONE run
# (issue 14: "`shade` (CPU) and every per-pixel CPU loop at memory bandwidth or within 2x of it
# for its bytes touched"). docs/benchmarks.md (issue 14); earlier runs in docs/benchmarks-history.md, "CPU passes against memory bandwidth".
#
# Method:
#  - bandwidth: diptych_rt_bench bandwidth (memcpy of 256 MB buffers on all threads, TBB; bytes
#    read + bytes written per second, median of 9), measured before and after the frames, per
#    wall second and per (CPU second / threads), the latter compared with the nodes' CPU time;
#  - bytes touched by a node: the sum of the sizes of the images it reads and writes (from the
#    --timings export: passes[].reads/writes, resources[].bytes); a default fill writes its one
#    image. Scene data (meshes, materials, the BVH) is not counted: for these scenes it is a few
#    kB to MB that stay in cache, and counting it would only raise the nodes' figures;
#  - time: the node's median cpu_ms (wall) over 5 frames after 1 warm-up, and, because other
#    processes stretch wall time on a loaded machine, also its process_cpu_ms median (CPU time
#    of all threads over the node, last frame) divided by nproc: the wall time it would take
#    with the cores to itself;
#  - slowdown = bandwidth / (bytes / time): 1 is a node that runs at memcpy's speed; the goal
#    is <= 2. A node far above it is bound by its arithmetic (or its rays), not by memory.
# Usage: tests/bench/cpu_bandwidth.sh [BUILD_DIR] [SCENE] [RECIPE] [SIZE] [OUT_DIR]
set -euo pipefail

build=${1:-build/release}
scene=${2:-samples/scenes/whitted.json}
recipe=${3:-samples/graphs/hybrid.json}
size=${4:-640x480}
out=${5:-$(mktemp -d)}
mkdir -p "$out"
diptych="$build/diptych"
tool="$build/tests/bench/diptych_rt_bench"
for exe in "$diptych" "$tool"; do
  [ -x "$exe" ] || { echo "$exe not found: build diptych_cli and diptych_rt_bench" >&2; exit 1; }
done

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | xargs)"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
"$tool" bandwidth | tee "$out/bandwidth-before.txt"
"$diptych" render "$scene" --recipe "$recipe" --size "$size" --frames 5 --warmup 1 \
  --timings "$out/timings.json" --out "$out/frame.exr" >"$out/render.log" 2>&1
"$tool" bandwidth | tee "$out/bandwidth-after.txt"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"

python3 - "$out" <<'PY'
import json, re, sys
out = sys.argv[1]
gbs, gbs_cpu = [], []
for name in ("before", "after"):
    text = open(f"{out}/bandwidth-{name}.txt").read()
    gbs.append(float(re.search(r"GB/s, all threads ([0-9.]+) GB/s;", text).group(1)))
    gbs_cpu.append(float(re.search(r"per CPU time:.*all threads ([0-9.]+) GB/s", text).group(1)))
bandwidth = max(gbs)  # the better of the two: the load only ever lowers it
bandwidth_cpu = max(gbs_cpu)
t = json.load(open(f"{out}/timings.json"))
size = {r["name"]: r["bytes"] for r in t["resources"]}
passes = {p["name"]: p for p in t["passes"]}
print(f"\nbandwidth: {bandwidth:.2f} GB/s wall, {bandwidth_cpu:.2f} GB/s per CPU time (memcpy, "
      f"all threads; before/after {gbs[0]:.2f}/{gbs[1]:.2f} and {gbs_cpu[0]:.2f}/{gbs_cpu[1]:.2f})")
import os
cores = os.cpu_count()
print("\n| node | kind | bytes touched (MB) | median ms | GB/s | slowdown vs memcpy |"
      f" CPU ms / {cores} | GB/s (CPU) | slowdown (CPU) |")
print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
for n in t["schedule"]:
    if n.get("domain") != "cpu" or n["kind"] not in ("pass", "default"):
        continue
    if n["kind"] == "pass":
        p = passes[n["name"]]
        touched = sum(size.get(r, 0) for r in p.get("reads", []) + p.get("writes", []))
    else:  # "default:RESOURCE": a fill of one image
        touched = size.get(n["name"].split(":", 1)[1], 0)
    ms = n["timing"]["cpu_ms"]["median"]
    cpu = n["timing"].get("process_cpu_ms", {}).get("median", float("nan")) / cores
    rate = touched / (ms * 1e-3) / 1e9 if ms > 0 else float("inf")
    rate_cpu = touched / (cpu * 1e-3) / 1e9 if cpu > 0 else float("inf")
    print(f"| {n['name']} | {n['kind']} | {touched / 1e6:.1f} | {ms:.2f} | {rate:.2f} | "
          f"{bandwidth / rate:.1f}x | {cpu:.2f} | {rate_cpu:.2f} | {bandwidth_cpu / rate_cpu:.1f}x |")
PY
