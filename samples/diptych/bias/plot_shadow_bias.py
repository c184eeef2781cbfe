#!/usr/bin/python3
"""Plots of a `diptych shadow-bias` study (matplotlib, Debian python3-matplotlib).

usage: plot_shadow_bias.py summary.json OUT_DIR
Writes OUT_DIR/MODE.svg/.png for every swept mode: acne % (left) and peter-panning % and light
leak % (right) against the mode's amount, one curve per (resolution, elevation, filter), the
predicted acne threshold of each curve as a dashed vertical line in the curve's colour, and for
constant bias the predicted acne rate (per-pixel texel model) as a dash-dot curve; and
OUT_DIR/time.svg/.png: misclassified % against the producer's time, one colour per mode.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402


def label(curve):
    parts = ["%d map" % curve["resolution"]]
    if curve.get("elevation") is not None:
        parts.append("%g° sun" % curve["elevation"])
    if curve.get("filter", "none") != "none":
        parts.append(curve["filter"])
    return ", ".join(parts)


def mode_plot(mode, out_dir):
    key = mode["key"]
    points = {p["index"]: p for p in mode["points"]}
    fig, (acne_ax, pp_ax) = plt.subplots(1, 2, figsize=(11, 4.4), dpi=100, sharex=True)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, curve in enumerate(mode["curves"]):
        colour = colours[i % len(colours)]
        rows = [points[j] for j in curve["indices"]]
        x = [r["params"][key] for r in rows]
        s = [r["signal"] for r in rows]
        acne_ax.plot(x, [100 * v["acne_rate"] for v in s], "o-", ms=3, color=colour,
                     label=label(curve))
        predicted = [r["geometry"].get("predicted_acne_rate") for r in rows]
        if all(p is not None for p in predicted):
            acne_ax.plot(x, [100 * p for p in predicted], "-.", linewidth=1, color=colour,
                         label=label(curve) + " predicted")
        pp_ax.plot(x, [100 * v["peter_panning_rate"] for v in s], "o-", ms=3, color=colour,
                   label=label(curve) + " peter-panning")
        pp_ax.plot(x, [100 * v["light_leak_rate"] for v in s], "x:", ms=4, color=colour,
                   label=label(curve) + " leak")
        if curve.get("predicted_threshold"):
            for ax in (acne_ax, pp_ax):
                ax.axvline(curve["predicted_threshold"], color=colour, linestyle="--", linewidth=1)
    for ax, title in ((acne_ax, "acne (% of exactly lit pixels)"),
                      (pp_ax, "peter-panning — and leak ·· (% of exactly shadowed pixels)")):
        ax.set_xscale("log")
        ax.set_xlabel(key + (" (world units)" if key == "constant_bias" else ""))
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    acne_ax.set_ylabel("% of pixels outside the boundary band")
    acne_ax.legend(fontsize=7, loc="upper right")
    title = "%s bias: dashed lines = predicted acne threshold (w/2) tan θ" % mode["mode"]
    if mode["mode"] == "constant":
        title += "; dash-dot = predicted acne rate"
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    for ext in ("svg", "png"):
        fig.savefig(os.path.join(out_dir, "%s.%s" % (mode["mode"], ext)))
    plt.close(fig)


def time_plot(summary, out_dir):
    fig, ax = plt.subplots(figsize=(8, 4.6), dpi=100)
    for mode in summary["modes"]:
        ax.scatter([p["producer_ms"] for p in mode["points"]],
                   [100 * p["signal"]["misclassified"] for p in mode["points"]],
                   s=14, label=mode["mode"], alpha=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("shadow_map pass, ms (median CPU wall clock per frame, log scale)")
    ax.set_ylabel("misclassified % (acne + peter-panning + leak)")
    ax.set_title("Error against time, every swept point")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    for ext in ("svg", "png"):
        fig.savefig(os.path.join(out_dir, "time.%s" % ext))
    plt.close(fig)


def main():
    with open(sys.argv[1]) as f:
        summary = json.load(f)
    out_dir = sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    for mode in summary["modes"]:
        if mode["key"]:
            mode_plot(mode, out_dir)
    time_plot(summary, out_dir)


if __name__ == "__main__":
    main()
