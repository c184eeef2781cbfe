#!/usr/bin/python3
"""CPU ms per frame of whole recipes and of each node, several configurations interleaved.

Each configuration (a binary, a recipe, optionally a shader folder for DIPTYCH_SHADER_DIR)
renders the scene with `--frames N --warmup 2 --timings`; per node, the median over the timed
frames of process_cpu_ms (CPU time of all threads over the node: llvmpipe's and TBB's) plus the
median of gl_completion_cpu_ms (the wait for the node's own GL work to complete, in which
llvmpipe's threads rasterize it), as tests/bench/ab_nodes.sh sums them; the frame is the sum
over nodes. One-time
work done in the warm-up frames (static shadow maps, prefiltered environments) is outside it.
Configurations run alternately, RUNS times; medians over runs are printed, frame and per node.
The images go to OUT/<label>-<run>.exr (compare them with tests/tools/compare_exr.py).

Usage: cpu_ms.py SCENE SIZE N RUNS OUT LABEL=BINARY:RECIPE[:SHADER_DIR] ...
"""
import json
import os
import statistics
import subprocess
import sys


def run(label, binary, recipe, shaders, scene, size, n, path):
    env = dict(os.environ)
    if shaders:
        env["DIPTYCH_SHADER_DIR"] = shaders
    subprocess.run([binary, "render", scene, "--recipe", recipe, "--size", size, "--frames",
                    str(n), "--warmup", "2", "--timings", path + ".json", "--out", path + ".exr"],
                   env=env, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    nodes = {}
    timings = json.load(open(path + ".json"))
    if "frame_gl_wait_cpu_ms" in timings:  # --gl-sync frame: the frame's GL work completes here
        nodes["gl wait at frame end"] = timings["frame_gl_wait_cpu_ms"]["median"]
    for node in timings["schedule"]:
        t = node.get("timing", {})
        cpu = t.get("process_cpu_ms", {}).get("median", 0.0)
        # The node's own GL work, completed after it returned (binaries before
        # gl_completion_cpu_ms: the wait before the next GL node, charged to that node).
        cpu += t.get("gl_completion_cpu_ms", t.get("gl_wait_cpu_ms", {})).get("median", 0.0)
        nodes[node["name"]] = cpu
    return nodes


def main():
    scene, size, n, runs, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
    configs = []
    for spec in sys.argv[6:]:
        label, rest = spec.split("=", 1)
        parts = rest.split(":")
        configs.append((label, parts[0], parts[1], parts[2] if len(parts) > 2 else ""))
    os.makedirs(out, exist_ok=True)
    results = {c[0]: [] for c in configs}
    for r in range(runs):
        for label, binary, recipe, shaders in configs:
            results[label].append(run(label, binary, recipe, shaders, scene, size, n,
                                      f"{out}/{label}-{r}"))
    load = open("/proc/loadavg").read().split()[:3]
    print(f"{scene} {size}, N = {n} after 2 warm-up frames, {runs} interleaved runs, "
          f"load average after: {' '.join(load)}; CPU ms (all threads), medians over runs")
    names = []
    for label in results:
        for nodes in results[label]:
            names += [k for k in nodes if k not in names]
    print("| configuration | frame | " + " | ".join(names) + " |")
    print("|---|---:|" + "---:|" * len(names))
    for label, rows in results.items():
        frame = statistics.median(sum(r.values()) for r in rows)
        cells = [f"{statistics.median(r.get(k, 0.0) for r in rows):.1f}" for k in names]
        spread = ", ".join(f"{sum(r.values()):.0f}" for r in rows)
        print(f"| {label} | {frame:.1f} ({spread}) | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
