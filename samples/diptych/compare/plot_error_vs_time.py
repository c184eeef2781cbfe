#!/usr/bin/python3
"""Error-versus-time plot of a `diptych compare` run (matplotlib, Debian python3-matplotlib).

usage: plot_error_vs_time.py results.json METRIC OUT_PREFIX
Writes OUT_PREFIX.svg and OUT_PREFIX.png: one point per variant (total frame ms, log scale, vs the
metric), the reference's time as a vertical line, and the Pareto front (variants no other
variant beats in both time and error) joined and highlighted. A variant whose compiled frame is an
earlier one's ("same_frame_as") is no point of its own: that point's label counts it.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402


def main():
    results_path, metric, out_prefix = sys.argv[1], sys.argv[2], sys.argv[3]
    with open(results_path) as f:
        results = json.load(f)
    same = {}  # variant -> how many others are its frame
    for v in results["variants"]:
        if "same_frame_as" in v:
            same[v["same_frame_as"]] = same.get(v["same_frame_as"], 0) + 1
    variants = [v for v in results["variants"] if "same_frame_as" not in v]
    fig, ax = plt.subplots(figsize=(9, 5.5), dpi=110)
    for v in variants:
        t, e = v["total_ms"], v["metrics"].get(metric, 0.0)
        ax.scatter([t], [e], s=46, zorder=3,
                   color="#d62728" if v.get("pareto") else "#1f77b4",
                   edgecolor="black", linewidth=0.5)
        label = v["name"] + (" (+%d same frame)" % same[v["name"]] if v["name"] in same else "")
        ax.annotate(label, (t, e), textcoords="offset points", xytext=(5, 4), fontsize=7)
    front = sorted((v for v in variants if v.get("pareto")), key=lambda v: v["total_ms"])
    if len(front) > 1:
        ax.step([v["total_ms"] for v in front], [v["metrics"].get(metric, 0.0) for v in front],
                where="post", color="#d62728", linewidth=1.2, label="Pareto front")
    ref_ms = results["reference"]["ms"]
    if ref_ms > 0:
        ax.axvline(ref_ms, color="grey", linestyle="--", linewidth=1,
                   label="reference %s (%.0f ms)" % (results["reference"]["spec"], ref_ms))
    ax.set_xscale("log")
    ax.set_xlabel("frame time, ms (sum of per-pass medians, log scale)")
    ax.set_ylabel(metric + " against the reference")
    ax.set_title("Error against run time: %s" % results["scene"].split("/")[-1])
    ax.grid(True, which="both", alpha=0.3)
    # Below the axes: inside, it would cover points or their labels.
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, fontsize=8, frameon=False)
    fig.tight_layout()
    fig.savefig(out_prefix + ".svg")
    fig.savefig(out_prefix + ".png")


if __name__ == "__main__":
    main()
