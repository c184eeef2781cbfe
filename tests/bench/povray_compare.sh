#!/usr/bin/env bash
# Times Diptych's Whitted reference (rt_whitted, samples/graphs/whitted.json) against POV-Ray
# 3.7 on the same scene (tests/bench/whitted.pov, a hand translation of
# samples/scenes/whitted.json) at 640x480, in one run, on this machine, and prints both medians
# and their ratios. See docs/benchmarks.md (issue 14) and, for earlier runs, docs/benchmarks-history.md.
#
# Two ratios, because the two programs report different things:
#  - render phase: Diptych's `reference` node median (schedule[].timing.cpu_ms.median of
#    --timings; excludes scene loading, tessellation and the Embree BVH build, which happen
#    before the first frame) vs POV-Ray's "Trace Time" (excludes parsing and its bounding
#    setup, which it reports apart).
#  - whole process: wall time of one process that renders ONE image and writes a PNG, for each
#    program. Diptych's includes the OSMesa context, scene load and BVH build; POV-Ray's its
#    parsing and setup. The timed Diptych run above renders 6 frames (1 warm-up + 5), so it
#    is not used for this; a separate `--frames 1 --warmup 0` run is.
#  - CPU time of the render phase: Diptych's is the `reference` node's process_cpu_ms median
#    (CPU time of all the process's threads over the node, last timed frame); POV-Ray's is the
#    "CPU-seconds total" it reports for its Trace Time.
#    On a loaded machine (other builds sharing the cores) wall times stretch with whatever else
#    runs, CPU seconds much less: this ratio is the one to trust there.
# Threads: both use every core (TBB's default for Diptych; POV-Ray is given +WT$(nproc),
# which is also its default).
# Usage: tests/bench/povray_compare.sh [BUILD_DIR] [RUNS] [OUT_DIR]   (from the repository root)
set -euo pipefail

build=${1:-build/release}
runs=${2:-5}
out=${3:-$(mktemp -d)}
mkdir -p "$out"
diptych="$build/diptych"
threads=$(nproc)

command -v povray >/dev/null || { echo "povray not found (apt-get install povray)" >&2; exit 1; }
[ -x "$diptych" ] || { echo "$diptych not found: build the release preset first" >&2; exit 1; }

# Nanosecond wall clock (GNU date): /usr/bin/time only has 10 ms resolution.
now_ns() { date +%s%N; }

echo "machine: $threads cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | xargs)"
echo "povray: $(povray --version 2>&1 | grep -m1 'POV-Ray')"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "runs: $runs of each, interleaved; images and logs in $out"

diptych_pass=()   # ms, median of 5 frames of the reference node, one value per run
diptych_proc=()   # ms, whole process rendering one frame
pov_trace=()      # ms, POV-Ray's reported Trace Time
pov_proc=()       # ms, whole POV-Ray process
diptych_cpu=()    # ms of CPU (all threads) per frame of the reference pass
pov_cpu=()        # ms of CPU (all threads) of POV-Ray's trace

# Interleaved (Diptych, POV-Ray, Diptych, ...) rather than all of one then all of the other, so
# that a change in the machine's load during the run hits both programs alike.
for ((r = 1; r <= runs; ++r)); do
  # 1) Render-phase timing: 1 warm-up frame (BVH build, allocations) then 5 measured frames.
  # --out is given only so that the default out.png does not land in the working directory.
  "$diptych" render samples/scenes/whitted.json --recipe samples/graphs/whitted.json \
    --size 640x480 --frames 5 --warmup 1 --timings "$out/t-$r.json" \
    --out "$out/ours-timed.png" >"$out/diptych-$r.log"
  diptych_pass+=("$(python3 -c '
import json, sys
nodes = json.load(open(sys.argv[1]))["schedule"]
print(next(n["timing"]["cpu_ms"]["median"] for n in nodes if n["name"] == "reference"))
' "$out/t-$r.json")")
  diptych_cpu+=("$(python3 -c '
import json, sys
nodes = json.load(open(sys.argv[1]))["schedule"]
print(next(n["timing"]["process_cpu_ms"]["median"] for n in nodes if n["name"] == "reference"))
' "$out/t-$r.json")")

  # 2) Whole-process timing of Diptych: one frame, no warm-up, PNG written (as POV-Ray does).
  t0=$(now_ns)
  "$diptych" render samples/scenes/whitted.json --recipe samples/graphs/whitted.json \
    --size 640x480 --frames 1 --warmup 0 --out "$out/ours.png" >"$out/diptych-proc-$r.log"
  t1=$(now_ns)
  diptych_proc+=("$(( (t1 - t0) / 1000000 ))")

  # 3) POV-Ray. -A: antialiasing off, one ray per pixel (3.7 rejects +A0 as an option);
  # -D: no display; -J: no jitter; +Q9: full quality (reflection, refraction, shadows); +FN:
  # PNG. Its statistics go to stderr; the progress lines are noise in the log but harmless.
  t0=$(now_ns)
  povray -D +W640 +H480 -A -J +Q9 +FN +WT"$threads" +O"$out/pov.png" tests/bench/whitted.pov \
    >"$out/pov-$r.log" 2>&1
  t1=$(now_ns)
  pov_proc+=("$(( (t1 - t0) / 1000000 ))")
  # "  Trace Time:       0 hours  0 minutes  0 seconds (0.558 seconds)" -> 558
  pov_trace+=("$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$out/pov-$r.log" |
    python3 -c 'import sys; print(float(sys.stdin.read()) * 1000)')")
  # "              using 2 thread(s) with 0.180 CPU-seconds total", the line after Trace Time
  pov_cpu+=("$(sed -n '/Trace Time:/{n;s/.* with \([0-9.]*\) CPU-seconds.*/\1/p}' "$out/pov-$r.log" |
    python3 -c 'import sys; print(float(sys.stdin.read()) * 1000)')")
  echo "run $r: diptych pass ${diptych_pass[-1]} ms, process ${diptych_proc[-1]} ms;" \
    "povray trace ${pov_trace[-1]} ms, process ${pov_proc[-1]} ms;" \
    "CPU per frame: diptych ${diptych_cpu[-1]} ms, povray ${pov_cpu[-1]} ms" \
    "(load $(cut -d' ' -f1 /proc/loadavg))"
done

echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"

# Medians and ratios (> 1: Diptych is slower).
python3 - "${diptych_pass[*]}" "${pov_trace[*]}" "${diptych_proc[*]}" "${pov_proc[*]}" \
  "${diptych_cpu[*]}" "${pov_cpu[*]}" <<'PY'
import statistics, sys
dp, pt, dw, pw, dc, pc = ([float(x) for x in a.split()] for a in sys.argv[1:7])
m = statistics.median
print(f"render phase  : diptych reference {m(dp):8.1f} ms | povray trace   {m(pt):8.1f} ms"
      f" | ratio diptych/povray {m(dp) / m(pt):.2f}")
print(f"whole process : diptych (1 frame) {m(dw):8.1f} ms | povray process {m(pw):8.1f} ms"
      f" | ratio diptych/povray {m(dw) / m(pw):.2f}")
print(f"render CPU    : diptych per frame {m(dc):8.1f} ms | povray trace   {m(pc):8.1f} ms"
      f" | ratio diptych/povray {m(dc) / m(pc):.2f}")
PY

# How different the pictures are (different shading models: see the header of whitted.pov).
echo "image difference (diptych diff ours.png pov.png):"
"$diptych" diff "$out/ours.png" "$out/pov.png" --json
