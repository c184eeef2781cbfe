#!/usr/bin/env bash
# Diptych's traced passes against Embree's own tutorials and POV-Ray 3.7, in ONE run on this
# machine, printed as ratios (issue 14; docs/benchmarks.md explains the method and the peers).
#
# Peers, per pass (rays per second, as each program counts them):
#  - coherent single-bounce work (rt_shadows; the primary rays of rt_whitted): Embree's
#    `triangle_geometry` (its own 14-triangle scene, camera and shadow rays, one ray at a time in
#    8x8 tiles), and `pathtracer` with --max-path-length 1 (camera + one shadow ray per hit) on
#    the same scene as Diptych, exported to OBJ with the same camera and point light; and
#    `user_geometry`, the peer for scenes with analytic spheres (whitted's two spheres are Embree
#    user geometry in Diptych, as there): its own scene of analytic and tessellated spheres in
#    user-geometry instances on a plane, a camera ray and one shadow ray per hit, one ray at a
#    time in 8x8 tiles, float roots, a filter callback carving the analytic spheres, and the
#    top-level scene re-committed every frame (its instances move);
#  - incoherent bounces (rt_reflection, rt_transmission, rt_whitted's recursion, rt_distributed,
#    rt_path): `pathtracer` on that OBJ with --max-path-length 5, Diptych's recursion depth;
#  - the Whitted reference against POV-Ray on tests/bench/whitted.pov (its hand translation):
#    640x480, depth 5, no antialiasing; Diptych's `reference` node median vs POV-Ray's Trace Time;
#  - BVH build of MetalRoughSpheresNoTextures (1.04 M triangles): Diptych (flattened and
#    instanced) against `buildbench` on the same triangles (OBJ), CREATE_STATIC_STATIC (medium
#    quality, static scene: what Diptych builds), and Embree's peak allocation.
# Runs are interleaved (Diptych, tutorials, POV-Ray, Diptych, ...) so a change of load hits all.
# Two rates per program: rays per wall-clock second (what each prints), and rays per CPU-second
# of all its threads, which hardly moves when other processes load the machine: Diptych's node
# process_cpu_ms (--timings: CPU time of all threads over the node, median over the frames), a tutorial's rays (its Mrays/s over its fps, times the 18 frames
# of --benchmark 2 16, or 10 of 2 8) over its process user + sys seconds (/usr/bin/time; OBJ
# loading and BVH build included, which only lowers the tutorial's figure, by < 5% here).
# Usage (from the repository root, after building diptych_cli and diptych_rt_bench):
#   tests/bench/rt_vs_embree.sh [BUILD_DIR] [RUNS] [OUT_DIR]
set -euo pipefail

build=${1:-build/release}
runs=${2:-3}
out=${3:-$(mktemp -d)}
mkdir -p "$out"
diptych="$build/diptych"
tool="$build/tests/bench/diptych_rt_bench"
size=(640 480)
metal=${DIPTYCH_SHARED_SCENES:-../shared/scenes}/metal-rough-spheres-no-textures/MetalRoughSpheresNoTextures.glb

for exe in "$diptych" "$tool"; do
  [ -x "$exe" ] || { echo "$exe not found: build diptych_cli and diptych_rt_bench" >&2; exit 1; }
done
for exe in triangle_geometry user_geometry pathtracer buildbench povray; do
  command -v "$exe" >/dev/null || { echo "$exe not found (embree-tools, povray)" >&2; exit 1; }
done

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | xargs)"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "runs: $runs, interleaved; logs in $out"

# The same scene for Embree's pathtracer: whitted.json's triangles (its analytic spheres as
# their 128x64 tessellation), camera and point light.
read -r -a whitted_view <<<"$("$tool" obj samples/scenes/whitted.json "$out/whitted.obj" 2>/dev/null)"

mrays() {  # LOG -> the tutorial's BENCHMARK_RENDER_MRAYPS_AVG
  sed -n 's/^BENCHMARK_RENDER_MRAYPS_AVG \([0-9.e+-]*\).*/\1/p' "$1"
}
render() {  # NAME SCENE RECIPE: 5 frames after 1 warm-up, --timings in $out/NAME-RUN.json
  "$diptych" render "samples/scenes/$2.json" --recipe "samples/graphs/$3.json" \
    --size "${size[0]}x${size[1]}" --frames 5 --warmup 1 --timings "$out/$1-$r.json" \
    --out "$out/$1.exr" >"$out/$1-$r.log" 2>&1
}

for ((r = 1; r <= runs; ++r)); do
  render hybrid whitted hybrid
  render whitted whitted whitted
  render distributed whitted distributed
  render path whitted path
  render cornell cornell hybrid
  /usr/bin/time -f "%U %S" -o "$out/tg-$r.cpu" \
    triangle_geometry --size "${size[@]}" --benchmark 2 16 >"$out/tg-$r.log" 2>&1
  /usr/bin/time -f "%U %S" -o "$out/ug-$r.cpu" \
    user_geometry --size "${size[@]}" --benchmark 2 16 >"$out/ug-$r.log" 2>&1
  /usr/bin/time -f "%U %S" -o "$out/pt1-$r.cpu" \
    pathtracer -i "$out/whitted.obj" "${whitted_view[@]}" --size "${size[@]}" \
    --max-path-length 1 --benchmark 2 8 >"$out/pt1-$r.log" 2>&1
  /usr/bin/time -f "%U %S" -o "$out/pt5-$r.cpu" \
    pathtracer -i "$out/whitted.obj" "${whitted_view[@]}" --size "${size[@]}" \
    --max-path-length 5 --benchmark 2 8 >"$out/pt5-$r.log" 2>&1
  povray -D +W"${size[0]}" +H"${size[1]}" -A -J +Q9 +FN +WT"$(nproc)" +O"$out/pov.png" \
    tests/bench/whitted.pov >"$out/pov-$r.log" 2>&1
  echo "tutorials run $r: triangle_geometry $(mrays "$out/tg-$r.log"), user_geometry" \
    "$(mrays "$out/ug-$r.log"), pathtracer depth 1" \
    "$(mrays "$out/pt1-$r.log"), depth 5 $(mrays "$out/pt5-$r.log") Mrays/s;" \
    "load $(cut -d' ' -f1 /proc/loadavg)"
done
echo "load average after the ray runs: $(cut -d' ' -f1-3 /proc/loadavg)"

# Ratios are taken per run (Diptych's pass and the tutorial of the same iteration, seconds
# apart) and then the median over runs is printed with the range: on a loaded machine the
# absolute rates of one program move by several times between runs, the ratios much less.
python3 - "$out" "$runs" <<'PY'
import json, re, statistics, sys
out, runs = sys.argv[1], int(sys.argv[2])
R = range(1, runs + 1)
med = statistics.median

def node(name, node_name, r, cpu=False):  # (ms, rays) of a node in run r
    for n in json.load(open(f"{out}/{name}-{r}.json"))["schedule"]:
        if n["name"] == node_name:
            t, counters = n["timing"], n["timing"].get("counters", {})
            ms = t["process_cpu_ms"]["median"] if cpu else t["cpu_ms"]["median"]
            return ms, counters.get("rays", 0.0)
    raise SystemExit(f"{name}-{r}.json has no node {node_name}")

def mrays(name, node_name, r):
    ms, rays = node(name, node_name, r)
    return rays / ms / 1e3

def mrays_cpu(name, node_name, r):  # Mrays per CPU-second of all threads
    ms, rays = node(name, node_name, r, cpu=True)
    return rays / ms / 1e3

def tutorial(prefix, r):
    m = re.search(r"^BENCHMARK_RENDER_MRAYPS_AVG ([0-9.e+-]+)",
                  open(f"{out}/{prefix}-{r}.log").read(), re.M)
    return float(m.group(1)) if m else float("nan")

def tutorial_cpu(prefix, r):  # Mrays per CPU-second (user + sys of the whole process)
    log = open(f"{out}/{prefix}-{r}.log").read()
    rate = re.search(r"^BENCHMARK_RENDER_MRAYPS_AVG ([0-9.e+-]+)", log, re.M)
    fps = re.search(r"^BENCHMARK_RENDER_AVG ([0-9.e+-]+)", log, re.M)
    if not (rate and fps):
        return float("nan")
    frames = 18 if prefix in ("tg", "ug") else 10  # --benchmark 2 16 / 2 8: skipped + measured
    mrays = float(rate.group(1)) / float(fps.group(1)) * frames
    cpu = sum(float(x) for x in open(f"{out}/{prefix}-{r}.cpu").read().split()[:2])
    return mrays / cpu

def pov_cpu_ms(r):  # "using 2 thread(s) with 0.180 CPU-seconds total" after Trace Time
    m = re.search(r"Trace Time:.*\n.*with ([0-9.]+) CPU-seconds", open(f"{out}/pov-{r}.log").read())
    return float(m.group(1)) * 1e3 if m else float("nan")

def pov_ms(r):
    m = re.search(r"Trace Time:.*\(([0-9.]+) seconds\)", open(f"{out}/pov-{r}.log").read())
    return float(m.group(1)) * 1e3 if m else float("nan")

def fmt(values):
    return f"{med(values):.2f}" + (f" ({min(values):.2f}-{max(values):.2f})" if len(values) > 1 else "")

peers = {"triangle_geometry": "tg", "user_geometry": "ug", "pathtracer depth 1": "pt1",
         "pathtracer depth 5": "pt5"}
print(f"\nper run: " + "; ".join(
    f"run {r}: " + ", ".join(f"{p} {tutorial(f, r):.2f}" for p, f in peers.items()) + " Mrays/s"
    for r in R))
rows = [("rt_shadows", "whitted", "hybrid", "shadows", "coherent"),
        ("rt_shadows (16 area samples)", "cornell", "cornell", "shadows", "coherent"),
        ("rt_reflection", "whitted", "hybrid", "reflection", "incoherent"),
        ("rt_transmission", "whitted", "hybrid", "transmission", "incoherent"),
        ("rt_whitted (reference)", "whitted", "whitted", "reference", "incoherent"),
        ("rt_distributed (4 spp)", "whitted", "distributed", "distributed", "incoherent"),
        ("rt_path (4 spp)", "whitted", "path", "path", "incoherent")]
print(f"\nMedian over {runs} runs (range); ratio = Diptych / peer of the same run, then median.")
print("Per wall-clock second, and per CPU-second of all threads (load-robust).")
print("\n| pass | scene | Diptych Mrays/s | peer | peer Mrays/s | ratio | Diptych Mrays/CPU-s |"
      " peer Mrays/CPU-s | ratio (CPU) |")
print("|---|---|---:|---|---:|---:|---:|---:|---:|")
for pass_name, scene, run_name, node_name, kind in rows:
    d = [mrays(run_name, node_name, r) for r in R]
    names = (["triangle_geometry", "pathtracer depth 1"] if kind == "coherent"
             else ["pathtracer depth 5"])
    if kind == "coherent" and scene == "whitted":  # analytic spheres: user_geometry's kind
        names.insert(1, "user_geometry")
    for peer in names:
        p = [tutorial(peers[peer], r) for r in R]
        ratio = [d[i] / p[i] for i in range(runs)]
        dc = [mrays_cpu(run_name, node_name, r) for r in R]
        pc = [tutorial_cpu(peers[peer], r) for r in R]
        rc = [dc[i] / pc[i] for i in range(runs)]
        print(f"| {pass_name} | {scene} | {fmt(d)} | {peer} | {fmt(p)} | {fmt(ratio)}x |"
              f" {fmt(dc)} | {fmt(pc)} | {fmt(rc)}x |")

ref = [node("whitted", "reference", r)[0] for r in R]
pov = [pov_ms(r) for r in R]
ratio = [ref[i] / pov[i] for i in range(runs)]
print(f"\nWhitted reference vs POV-Ray 3.7, 640x480, depth 5, no AA: diptych reference "
      f"{fmt(ref)} ms, povray Trace Time {fmt(pov)} ms, ratio diptych/povray {fmt(ratio)}")
ref_cpu = [node("whitted", "reference", r, cpu=True)[0] for r in R]
pov_cpu = [pov_cpu_ms(r) for r in R]
ratio_cpu = [ref_cpu[i] / pov_cpu[i] for i in range(runs)]
print(f"  in CPU time of all threads: diptych {fmt(ref_cpu)} ms, povray {fmt(pov_cpu)} ms, "
      f"ratio diptych/povray {fmt(ratio_cpu)}")
PY

echo
echo "BVH build, MetalRoughSpheresNoTextures (load $(cut -d' ' -f1 /proc/loadavg)):"
if [ -f "$metal" ]; then
  "$tool" build "$metal" 5
  "$tool" obj "$metal" "$out/metal.obj" >/dev/null 2>&1
  buildbench -i "$out/metal.obj" --legacy --benchmark 1 5 >"$out/buildbench.log" 2>&1 || true
  grep -E "^BENCHMARK_CREATE_(STATIC_STATIC|HQ_STATIC_STATIC) " "$out/buildbench.log" |
    sed 's/^/buildbench: /'
else
  echo "($metal not found: set DIPTYCH_SHARED_SCENES)"
fi
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
