#!/usr/bin/env bash
# Regenerates the per-pass table of docs/benchmarks-history.md: runs `diptych render` RUNS times
# (default 3) for each sample scene and size, each run reporting the median of 10 frames after
# 3 warm-up frames, and prints the median over the runs of each node's CPU and GPU ms, and of
# rt_shadows rays/s, as Markdown. Then runs Embree's triangle_geometry tutorial for comparison.
# Usage: tests/bench/collect_figures.sh [BUILD_DIR] [RUNS]   (from the repository root)
set -euo pipefail
build=${1:-build/release}
runs=${2:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | xargs)"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for scene in whitted cornell; do
  for size in 640x480 1920x1080; do
    for ((r = 0; r < runs; ++r)); do
      "$build/diptych" render "samples/scenes/$scene.json" --size "$size" --frames 10 --warmup 3 \
        --out "$tmp/$scene-$size.png" --timings "$tmp/$scene-$size-$r.json" >/dev/null
    done
    python3 - "$scene" "$size" "$tmp"/"$scene-$size"-*.json <<'EOF'
import json, statistics, sys
scene, size, files = sys.argv[1], sys.argv[2], sys.argv[3:]
runs = [json.load(open(f)) for f in files]
rows = {}
for run in runs:
    for node in run["schedule"]:
        t = node.get("timing", {})
        row = rows.setdefault(node["name"], {"cpu": [], "gpu": [], "rays": []})
        cpu = t.get("cpu_ms", {}).get("median")
        row["cpu"].append(cpu)
        gpu = t.get("gpu_ms")
        if isinstance(gpu, dict): gpu = gpu.get("median")
        if gpu is not None: row["gpu"].append(gpu)
        rays = t.get("counters", {}).get("rays")
        if rays: row["rays"].append(rays / (cpu * 1e-3))
print(f"\n### {scene} {size} (median of {len(runs)} runs x median of 10 frames)\n")
print("| node | cpu ms | gpu ms | Mrays/s |")
print("|---|---:|---:|---:|")
total = 0.0
for name, row in rows.items():
    cpu = statistics.median(row["cpu"]); total += cpu
    gpu = f"{statistics.median(row['gpu']):.3f}" if row["gpu"] else "-"
    mr = f"{statistics.median(row['rays']) / 1e6:.2f}" if row["rays"] else "-"
    print(f"| {name} | {cpu:.2f} | {gpu} | {mr} |")
print(f"| total (sum of medians) | {total:.2f} | | |")
EOF
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"

echo
echo "Embree triangle_geometry tutorial (2 skipped + 16 measured frames, default shader):"
for size in "640 480" "1920 1080"; do
  for ((r = 0; r < runs; ++r)); do
    # shellcheck disable=SC2086
    triangle_geometry --size $size --benchmark 2 16 2>&1 |
      awk -v s="$size" '/BENCHMARK_RENDER_AVG |BENCHMARK_RENDER_MRAYPS_AVG / {printf "%s %s=%s ", s, $1, $2} END {print ""}'
  done
done
