#!/usr/bin/python3
"""Error-versus-time plot of a `diptych compare` run (matplotlib, Debian python3-matplotlib).

usage: plot_error_vs_time.py results.json METRIC OUT_PREFIX
Writes OUT_PREFIX.svg and OUT_PREFIX.png: one point per variant (total frame ms, log scale, vs the
metric), the reference's time and the all-exact frame's (`exact_variant`) as vertical lines,
and the Pareto front (variants no other
variant beats in both time and error) joined and highlighted. A variant whose compiled frame is an
earlier one's ("same_frame_as") is no point of its own: that point's label counts it.

The error axis is logarithmic: a default run's errors span three decades (FLIP 2e-4 for
hybrid-exact to 0.08 for raster), and on a linear axis every accurate variant sat on the zero
line. An error of exactly 0 (a variant that is the reference's image) is drawn at the axis floor
(symlog, linear below the smallest positive error). Labels are placed so that none covers another
label, a point, the Pareto front's line or a vertical time line (a greedy search over offsets
around each point, nearest first, then farther out with a leader line); the script says on stderr
how many it could not place clear, and with --check-labels it always says and exits non-zero if
any.
"""
import json
import math
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")  # no display: files only
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.text  # noqa: E402
import matplotlib.ticker  # noqa: E402

# Offsets (points) tried for a label, nearest first: right, left, above, below and the diagonals
# next to the marker, then rings farther out in 16 directions (all but the side-by-side ones get
# a leader line back to their point).
_NEAR = [(6, 0), (-6, 0), (0, 6), (0, -6), (6, 6), (-6, 6), (6, -6), (-6, -6)]
_OFFSETS = _NEAR + [(round(r * math.cos(a * math.pi / 8)), round(r * math.sin(a * math.pi / 8)))
                    for r in (16, 26, 38, 52, 70) for a in range(16)]


def _text_box(annotation, renderer):
    """The label's own box: an Annotation's window extent includes its leader line, which may
    cross other points' space as long as its text does not."""
    annotation.update_positions(renderer)  # the offset applied, as Annotation's own extent does
    return matplotlib.text.Text.get_window_extent(annotation, renderer)


def _overlaps(box, boxes):
    return any(box.overlaps(b) for b in boxes)


def _polyline_samples(ax, vertices, per_segment=40):
    """Display-space points along a polyline given in data coordinates."""
    out = []
    shown = [ax.transData.transform(v) for v in vertices]
    for (x0, y0), (x1, y1) in zip(shown, shown[1:]):
        for k in range(per_segment + 1):
            f = k / per_segment
            out.append((x0 + f * (x1 - x0), y0 + f * (y1 - y0)))
    return out


def place_labels(fig, ax, points, labels, lines=(), fontsize=7):
    """Annotates each point (x, y in data coordinates) with its label where it covers no placed
    label, no point and no line of `lines` (polylines in data coordinates), and stays inside the
    axes. Returns how many labels could not be placed clear (those keep their nearest
    position)."""
    renderer = fig.canvas.get_renderer()
    axes_box = ax.get_window_extent(renderer)
    line_points = [p for line in lines for p in _polyline_samples(ax, line)]
    # Each marker as a small box in display coordinates (s=46 points^2: ~7 points across).
    radius = 4.0 * fig.dpi / 72.0
    point_boxes = []
    for x, y in points:
        px, py = ax.transData.transform((x, y))
        point_boxes.append(matplotlib.transforms.Bbox.from_extents(
            px - radius, py - radius, px + radius, py + radius))
    placed = []
    crowded = 0
    # The lowest-error points first: they are the interesting corner and the most crowded.
    order = sorted(range(len(points)), key=lambda i: (points[i][1], points[i][0]))
    for i in order:
        (x, y), label = points[i], labels[i]
        chosen = None
        for dx, dy in _OFFSETS:
            # Beside the point (right or left) a label needs no line; anywhere else, with three
            # points within a label's width, a thin leader says which point it names.
            far = dy != 0 or abs(dx) > 8
            ha = "left" if dx > 0 else "right" if dx < 0 else "center"
            va = "bottom" if dy > 0 else "top" if dy < 0 else "center"
            a = ax.annotate(label, (x, y), textcoords="offset points", xytext=(dx, dy),
                            fontsize=fontsize, ha=ha, va=va,
                            arrowprops=dict(arrowstyle="-", color="grey", linewidth=0.5,
                                            shrinkA=0, shrinkB=3) if far else None)
            box = _text_box(a, renderer)
            others = point_boxes[:i] + point_boxes[i + 1:]
            inside = axes_box.contains(box.x0, box.y0) and axes_box.contains(box.x1, box.y1)
            if inside and not _overlaps(box, placed) and not _overlaps(box, others) and \
                    not any(box.contains(px, py) for px, py in line_points):
                chosen = (a, box)
                break
            a.remove()
        if chosen is None:
            crowded += 1
            dx, dy = _NEAR[0]
            a = ax.annotate(label, (x, y), textcoords="offset points", xytext=(dx, dy),
                            fontsize=fontsize, va="center")
            chosen = (a, _text_box(a, renderer))
        placed.append(chosen[1])
    return crowded


def build(results, metric):
    """The figure of `results` (a parsed results.json): returns (fig, ax, labels not placed
    clear)."""
    same = {}  # variant -> how many others are its frame
    for v in results["variants"]:
        if "same_frame_as" in v:
            same[v["same_frame_as"]] = same.get(v["same_frame_as"], 0) + 1
    variants = [v for v in results["variants"] if "same_frame_as" not in v]
    fig, ax = plt.subplots(figsize=(9, 5.5), dpi=110)
    points, labels = [], []
    unplotted = []  # a time or an error that is not a finite number has no place on the axes
    for v in variants:
        # results.json writes a NaN or an infinity as null (nlohmann::json).
        t, e = v.get("total_ms"), v["metrics"].get(metric, 0.0)
        t, e = (float("nan") if x is None else float(x) for x in (t, e))
        if not (math.isfinite(t) and t > 0 and math.isfinite(e) and e >= 0):
            unplotted.append(v["name"])
            continue
        ax.scatter([t], [e], s=46, zorder=3,
                   color="#d62728" if v.get("pareto") else "#1f77b4",
                   edgecolor="black", linewidth=0.5)
        points.append((t, e))
        labels.append(v["name"] + (" (+%d same frame)" % same[v["name"]]
                                   if v["name"] in same else ""))
    plotted = {v["name"] for v in variants} - set(unplotted)
    front = sorted((v for v in variants if v.get("pareto") and v["name"] in plotted),
                   key=lambda v: v["total_ms"])
    step = []  # the front's staircase, which the labels keep clear of
    if len(front) > 1:
        ax.step([v["total_ms"] for v in front], [v["metrics"].get(metric, 0.0) for v in front],
                where="post", color="#d62728", linewidth=1.2, label="Pareto front")
        for a, b in zip(front, front[1:]):
            ea, eb = a["metrics"].get(metric, 0.0), b["metrics"].get(metric, 0.0)
            step += [(a["total_ms"], ea), (b["total_ms"], ea), (b["total_ms"], eb)]
    ref_ms = results["reference"]["ms"]
    if ref_ms > 0:
        ax.axvline(ref_ms, color="grey", linestyle="--", linewidth=1,
                   label="reference %s (%.0f ms)" % (results["reference"]["spec"], ref_ms))
    # The all-exact frame's time too (`vs exact` in the table): a variant left of this line saves
    # time against the exact producers it replaces.
    exact_name = next((v["exact_variant"] for v in variants if "exact_variant" in v), None)
    exact = next((v for v in variants if v["name"] == exact_name), None)
    if exact is not None and exact["total_ms"] > 0:
        ax.axvline(exact["total_ms"], color="#d62728", linestyle=":", linewidth=1,
                   label="all-exact frame %s (%.0f ms)" % (exact_name, exact["total_ms"]))
    ax.set_xscale("log")
    # Milliseconds as plain numbers (60, 70, 100), not 6x10^1; the in-between ticks are labelled
    # too where the times span less than a decade (most runs), else they would crowd.
    plain = matplotlib.ticker.FuncFormatter(lambda x, _: "%g" % x)
    ax.xaxis.set_major_formatter(plain)
    times = [t for t, _ in points if t > 0]
    if times and max(times) < 10 * min(times):
        ax.xaxis.set_minor_formatter(plain)
    positive = [e for _, e in points if e > 0]
    if positive:
        # Room for the labels: half a decade above the highest point and below the lowest (or
        # down to the 0 of symlog, whose linear part is the band below the smallest error).
        top = max(positive) * 3.0
        if len(positive) < len(points):
            ax.set_yscale("symlog", linthresh=min(positive))
            ax.set_ylim(0.0, top)
        else:
            ax.set_yscale("log")
            ax.set_ylim(min(positive) / 3.0, top)
    ax.set_xlabel("frame time, ms (sum of per-pass medians, log scale)")
    ax.set_ylabel(metric + " against the reference (log scale)")
    title = "Error against run time: %s" % results["scene"].split("/")[-1]
    if unplotted:  # said on the plot, not dropped silently
        title += "\n" + "\n".join(textwrap.wrap(
            "not plotted (time not positive, or time or error not finite): " + ", ".join(unplotted),
            110))
    ax.set_title(title, fontsize=10 if unplotted else None)
    ax.grid(True, which="both", alpha=0.3)
    # Below the axes: inside, it would cover points or their labels.
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=3, fontsize=8, frameon=False)
    fig.tight_layout()
    # The labels keep clear of the front's staircase and of the two vertical time lines.
    lines = [step] if step else []
    y0, y1 = ax.get_ylim()
    for ms in (ref_ms, exact["total_ms"] if exact is not None else 0):
        if ms > 0:
            lines.append([(ms, y0), (ms, y1)])
    return fig, ax, place_labels(fig, ax, points, labels, lines=lines)


def main():
    args = [a for a in sys.argv[1:] if a != "--check-labels"]
    check = "--check-labels" in sys.argv[1:]
    results_path, metric, out_prefix = args[0], args[1], args[2]
    with open(results_path) as f:
        results = json.load(f)
    fig, ax, crowded = build(results, metric)
    if check or crowded:
        print("plot labels: %d placed clear, %d overlapping" % (len(ax.texts) - crowded, crowded),
              file=sys.stderr)
    fig.savefig(out_prefix + ".svg")
    fig.savefig(out_prefix + ".png")
    if check and crowded:
        sys.exit(1)


if __name__ == "__main__":
    main()
