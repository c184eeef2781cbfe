#!/usr/bin/python3
"""Checks a `diptych compare` output folder (used by tests/cli/compare.cmake).

usage: check_compare.py OUT_DIR
Asserts: every file is written; results.json parses and holds every variant; the reference
rendered as a variant scores 0 error; the all-exact hybrid scores ~0; a 256 shadow map scores
worse than a 4096 one; results.csv has a row per variant; the devices (GL renderer, CPU,
Embree) and the one-time costs are reported apart from the frame times.
"""
import csv
import json
import os
import sys


def fail(message):
    print("check_compare: FAIL: " + message)
    sys.exit(1)


def main():
    out = sys.argv[1]
    with open(os.path.join(out, "results.json")) as f:
        results = json.load(f)
    variants = {v["name"]: v for v in results["variants"]}
    expected = ["reference-self", "hybrid-exact", "sm-256", "sm-4096", "geometry-16"]
    if sorted(variants) != sorted(expected):
        fail("variants %s, expected %s" % (sorted(variants), expected))
    for name in ["plot.svg", "plot.png", "report.html", "results.csv", "images/reference.exr",
                 "images/reference.png"]:
        if not os.path.getsize(os.path.join(out, name)):
            fail(name + " is empty")
    for v in results["variants"]:
        for kind, path in v["files"].items():
            if not os.path.isfile(os.path.join(out, path)) or not os.path.getsize(os.path.join(out, path)):
                fail("%s: %s file %s missing" % (v["name"], kind, path))
        for key in ["total_ms", "pass_ms", "rays", "metrics", "signals", "pareto"]:
            if key not in v:
                fail("%s lacks %s" % (v["name"], key))
        for metric in ["mse", "rmse", "relmse", "psnr", "ssim", "flip_mean", "flip_p95"]:
            if metric not in v["metrics"]:
                fail("%s lacks metric %s" % (v["name"], metric))
    self_metrics = variants["reference-self"]["metrics"]
    if self_metrics["mse"] != 0 or self_metrics["flip_mean"] != 0 or self_metrics["ssim"] != 1:
        fail("the reference against itself must score 0 error: %s" % self_metrics)
    exact = variants["hybrid-exact"]["metrics"]
    if not exact["relmse"] < 1e-6 or not exact["flip_mean"] < 1e-3:
        fail("the all-exact hybrid must score ~0 against the Whitted reference: %s" % exact)
    # The geometry axis: the analytic sphere traced as a 16 x 8 tessellation (224 triangles, plus
    # the plane's 2) is measurably wrong where the exact hybrid is not.
    geo = variants["geometry-16"]
    if geo["tessellation"] != 16 or geo["traced_triangles"] != 226:
        fail("geometry-16: tessellation %s, traced triangles %s (expected 16, 226)" %
             (geo["tessellation"], geo["traced_triangles"]))
    # Memory: the exact sphere is one AnalyticInstance (a few hundred bytes with the plane's 72);
    # its 16 x 8 tessellation holds kilobytes of vertices and triangles.
    exact_bytes = variants["hybrid-exact"]["traced_geometry_bytes"]
    if not exact_bytes < 1000 or not geo["traced_geometry_bytes"] > exact_bytes + 3000:
        fail("traced_geometry_bytes: exact %s, geometry-16 %s" % (exact_bytes, geo["traced_geometry_bytes"]))
    if not geo["metrics"]["rmse"] > 10 * max(exact["rmse"], 1e-9):
        fail("geometry-16 (rmse %g) must score clearly worse than the exact hybrid (%g)" %
             (geo["metrics"]["rmse"], exact["rmse"]))
    for metric in ["rmse", "flip_mean"]:
        lo, hi = variants["sm-4096"]["metrics"][metric], variants["sm-256"]["metrics"][metric]
        if not hi > lo:
            fail("%s: the 256 shadow map (%g) must score worse than the 4096 one (%g)" % (metric, hi, lo))
    vis256 = variants["sm-256"]["signals"]["visibility"][0]
    vis4096 = variants["sm-4096"]["signals"]["visibility"][0]
    wrong = lambda s: s["false_shadow_inside"] + s["false_lit_inside"] + s["false_shadow_outside"] + s["false_lit_outside"]
    if not wrong(vis256) > wrong(vis4096):
        fail("visibility signal: 256 map misclassifies %d pixels, 4096 map %d" % (wrong(vis256), wrong(vis4096)))
    devices = results.get("devices", {})
    if not (devices.get("gl") or {}).get("renderer") or not devices.get("cpu", {}).get("model") \
            or not devices.get("embree", {}).get("version"):
        fail("results.json must name the GL renderer, the CPU and the Embree version: %s" % devices)
    one_time = results.get("one_time_ms", {})
    for key in ["gl_context_ms", "embree_bvh_build_ms", "gl_scene_upload_ms"]:
        if not one_time.get(key, -1) >= 0:
            fail("one-time cost %s missing: %s" % (key, one_time))
    if "reference and variants alike" not in results["method"]:
        fail("the method must say the reference is timed like the variants: " + results["method"])
    # Without warm-up and with fewer than 3 frames the medians hold the first frame's driver
    # compilation: the method must say so, and only then.
    unsteady = results["warmup"] == 0 and results["frames"] < 3
    if unsteady != ("NO WARM-UP" in results["method"]):
        fail("warm-up %d, %d frames: the method %s the first frame's first-use work: %s" % (
            results["warmup"], results["frames"], "must name" if unsteady else "must not name",
            results["method"]))
    for v in results["variants"]:
        if not v.get("first_frame_ms", -1) >= 0:
            fail("%s lacks first_frame_ms" % v["name"])
        first = v.get("first_frame", {})
        if not all(k in first for k in ("wall_ms", "one_time_ms", "steady_ms", "unrecorded_ms")):
            fail("%s lacks first_frame {wall_ms, one_time_ms, steady_ms, unrecorded_ms}" % v["name"])
    # Static shadow maps are a one-time cost of each variant that renders its own (the two map
    # resolutions differ, so each builds once), never inside its frame medians.
    for name in ["sm-256", "sm-4096"]:
        if not variants[name]["one_time_ms"].get("shadow_map build", -1) > 0:
            fail("%s: its shadow-map build is not among its one-time costs: %s"
                 % (name, variants[name]["one_time_ms"]))
    # What each technique saves against the all-exact frame of the run (hybrid-exact: the built-in
    # recipe, no override): exact / variant in the same round, absent for hybrid-exact itself.
    if "speedup_vs_exact" in variants["hybrid-exact"]:
        fail("hybrid-exact has a speed-up against itself")
    for name in ["sm-256", "sm-4096", "geometry-16", "reference-self"]:
        v = variants[name]
        if v.get("exact_variant") != "hybrid-exact":
            fail("%s: exact_variant %r" % (name, v.get("exact_variant")))
        expected_ratio = variants["hybrid-exact"]["total_ms"] / v["total_ms"]
        if abs(v["speedup_vs_exact"] - expected_ratio) > 1e-9 * expected_ratio:
            fail("%s: speedup_vs_exact %r, exact / variant %r" % (name, v["speedup_vs_exact"],
                                                                  expected_ratio))
        # The same in milliseconds: exact - variant (one round here).
        expected_saved = variants["hybrid-exact"]["total_ms"] - v["total_ms"]
        if abs(v["saved_ms_vs_exact"] - expected_saved) > 1e-9 * variants["hybrid-exact"]["total_ms"]:
            fail("%s: saved_ms_vs_exact %r, exact - variant %r" % (name, v["saved_ms_vs_exact"],
                                                                   expected_saved))
    with open(os.path.join(out, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    if sorted(r["variant"] for r in rows) != sorted(expected) or "flip_mean" not in rows[0]:
        fail("results.csv rows/columns are wrong")
    by_name = {r["variant"]: r for r in rows}
    if by_name["hybrid-exact"]["speedup_vs_exact"] != "" or \
            abs(float(by_name["sm-256"]["speedup_vs_exact"]) - variants["sm-256"]["speedup_vs_exact"]) > 1e-6:
        fail("results.csv speedup_vs_exact: %r" % {n: r["speedup_vs_exact"] for n, r in by_name.items()})
    if by_name["hybrid-exact"]["saved_ms_vs_exact"] != "" or \
            abs(float(by_name["sm-256"]["saved_ms_vs_exact"]) - variants["sm-256"]["saved_ms_vs_exact"]) > 1e-6:
        fail("results.csv saved_ms_vs_exact: %r" % {n: r["saved_ms_vs_exact"] for n, r in by_name.items()})
    print("check_compare: ok (sm-256 flip %.4g > sm-4096 flip %.4g; exact relmse %.3g)"
          % (variants["sm-256"]["metrics"]["flip_mean"], variants["sm-4096"]["metrics"]["flip_mean"], exact["relmse"]))


if __name__ == "__main__":
    main()
