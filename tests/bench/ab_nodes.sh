#!/usr/bin/env bash
# Before/after of a change, per frame-graph node, in ONE run: two diptych binaries (e.g. one built
# from main, one from a branch) render the same scene and recipe alternately, RUNS times each,
# and the medians of every node's process_cpu_ms (CPU time of all threads over the node,
# median over the timed frames; --timings) and wall median are printed side by side with their ratio.
# Interleaving, in alternating order, puts a change of machine load on both sides; on a loaded machine trust the CPU
# columns. The images of each pair are compared byte for byte (tests/tools/compare_exr.py).
# Usage (from the repository root):
#   tests/bench/ab_nodes.sh OLD_DIPTYCH NEW_DIPTYCH SCENE RECIPE [RUNS] [WxH] [OUT_DIR]
set -euo pipefail
old=$1 new=$2 scene=$3 recipe=$4 runs=${5:-3} size=${6:-640x480} out=${7:-$(mktemp -d)}
mkdir -p "$out/old" "$out/new"
# The order alternates per round: run first in every round, one binary gained 7% over an
# identical copy of itself on session 29's machine (the drift of a shared VM within a round).
for r in $(seq "$runs"); do
  order="old new"
  [ $((r % 2)) -eq 0 ] && order="new old"
  for side in $order; do
    bin=$old
    [ "$side" = new ] && bin=$new
    "$bin" render "$scene" --recipe "$recipe" --size "$size" --frames 3 --warmup 1 \
      --timings "$out/$side-$r.json" --out "$out/$side/$r.exr" >/dev/null
  done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg); $runs runs, $size, logs in $out"
python3 - "$out" "$runs" <<'PY'
import json, statistics as st, sys
out, runs = sys.argv[1], int(sys.argv[2])
nodes, totals = {}, {"old": [], "new": []}
for side in ("old", "new"):
    for r in range(1, runs + 1):
        total = 0.0
        timings = json.load(open(f"{out}/{side}-{r}.json"))
        # --gl-sync frame: the frame's GL work completes in one wait at its end.
        total += timings.get("frame_gl_wait_cpu_ms", {}).get("median", 0.0)
        for n in timings["schedule"]:
            t = n.get("timing", {})
            # A median summary since the timing export's 2026-11-29 change; older binaries
            # (the "old" side) wrote the last frame's value as a counter.
            cpu = (t["process_cpu_ms"]["median"] if "process_cpu_ms" in t
                   else t.get("counters", {}).get("process_cpu_ms", 0.0))
            # The wait for a GL node's work to complete is its CPU time too (llvmpipe's
            # threads). Binaries before gl_completion_cpu_ms charged it to the next GL node
            # (gl_wait_cpu_ms): frame totals compare across the change, GL nodes do not.
            cpu += t.get("gl_completion_cpu_ms", t.get("gl_wait_cpu_ms", {})).get("median", 0.0)
            total += cpu
            nodes.setdefault(n["name"], {"old": [], "new": []})[side].append(
                (cpu, t.get("cpu_ms", {}).get("median", 0.0)))
        totals[side].append(total)
print(f"| node | old CPU ms | new CPU ms | new / old | old wall ms | new wall ms |")
print("|---|---:|---:|---:|---:|---:|")
med = lambda xs: st.median(xs) if xs else 0.0
for name, s in nodes.items():
    o, n = med([c for c, _ in s["old"]]), med([c for c, _ in s["new"]])
    ow, nw = med([w for _, w in s["old"]]), med([w for _, w in s["new"]])
    print(f"| {name} | {o:.1f} | {n:.1f} | {n / o if o else 0:.2f} | {ow:.1f} | {nw:.1f} |")
o, n = med(totals["old"]), med(totals["new"])
print(f"| frame (sum of nodes) | {o:.1f} | {n:.1f} | {n / o:.2f} | | |")
PY
python3 "$(dirname "$0")/../tools/compare_exr.py" "$out/old" "$out/new" || true
