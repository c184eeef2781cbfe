#!/usr/bin/env bash
# Per-producer figures (docs/benchmarks-history.md, "Technique slots"): runs `diptych compare` with the
# default variant set on whitted and cornell at 640x480 and 1920x1080 and prints, per variant,
# the total frame time and the time of the pass that produces the swapped slot, with rays/s for
# ray producers. Method: each variant is compiled once, warmed up, then timed over N frames;
# every figure is a median (see docs/compare.md). Usage: producer_figures.sh [FRAMES] [BUILD_DIR]
set -euo pipefail
frames=${1:-3}
build=${2:-build/release}
cd "$(dirname "$0")/../.."
out=$(mktemp -d)
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load: $(cut -d' ' -f1-3 /proc/loadavg)"
for scene in whitted cornell; do
  for size in 640x480 1920x1080; do
    "$build/diptych" compare "samples/scenes/$scene.json" --size "$size" --frames "$frames" --warmup 1 \
      --out "$out/$scene-$size" >/dev/null 2>&1
    /usr/bin/python3 - "$out/$scene-$size/results.json" "$scene" "$size" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print("\n#### %s %s (reference %s: %.0f ms)\n" % (sys.argv[2], sys.argv[3], r["reference"]["spec"], r["reference"]["ms"]))
print("| variant | producer pass ms | producer Mrays/s | frame ms | FLIP mean |")
print("|---|---:|---:|---:|---:|")
slot_pass = {"visibility": "shadows", "reflection": "reflection", "transmission": "transmission",
             "texture_filtering": "texture_filtering"}
def row(name, v, passes):
    ms = sum(v["pass_ms"][p] for p in passes)
    graph = json.load(open(sys.argv[1].replace("results.json", v["files"]["graph"])))
    rays = sum(n.get("timing", {}).get("counters", {}).get("rays", 0) for n in graph["schedule"] if n["name"] in passes)
    rate = "%.2f" % (rays / ms / 1e3) if rays and ms else "-"
    print("| %s | %.1f | %s | %.1f | %.4f |" % (name, ms, rate, v["total_ms"], v["metrics"]["flip_mean"]))
for v in r["variants"]:
    slots = [s.split("=")[0] for s in v["slots"]] or ["visibility", "reflection", "transmission"]
    passes = [slot_pass[s] for s in slots if slot_pass.get(s) in v["pass_ms"]]
    if "same_frame_as" in v:  # not timed: an earlier variant's frame (docs/compare.md)
        print("| %s | same frame as %s | | | |" % (v["name"], v["same_frame_as"]))
    elif v["name"] == "hybrid-exact":  # one row per exact producer (a culled one has no time)
        for exact, p in (("rt_shadows", "shadows"), ("rt_reflection", "reflection"), ("rt_transmission", "transmission")):
            if p in v["pass_ms"]:
                row("hybrid-exact: " + exact, v, [p])
    else:
        row(v["name"], v, passes)
PY
  done
done
rm -rf "$out"
