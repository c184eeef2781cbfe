# compare's error-versus-time plot (samples/diptych/compare/plot_error_vs_time.py) on a crowded
# synthetic run, shaped like whitted's (a cluster of environment maps and blends within a few ms
# and a few hundredths of FLIP, accurate variants three decades lower, one variant at error 0):
# every label is placed clear of every other label and every point, inside the axes (leader lines
# join the farther ones), as checked here from the drawn texts' extents; the error axis is logarithmic (symlog with a 0). The same
# labels at one fixed offset, as the script placed them before, overlap.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
expect_python("plot labels clear" [=[
import importlib.util, sys
spec = importlib.util.spec_from_file_location("plot", sys.argv[1])
plot = importlib.util.module_from_spec(spec)
spec.loader.exec_module(plot)

def variant(name, ms, flip, **extra):
    return dict(name=name, total_ms=ms, metrics={"flip_mean": flip}, **extra)

variants = [variant("hybrid-exact", 66.2, 2.1e-4, pareto=True),
            variant("raster", 57.6, 0.082, exact_variant="hybrid-exact"),
            variant("reference-self", 58.4, 0.0, pareto=True)]
variants += [variant("texture-%d" % i, 0, 0, same_frame_as="hybrid-exact") for i in range(6)]
for i, (ms, flip) in enumerate([(65.3, 0.0264), (66.0, 0.0265), (67.0, 0.0264), (61.2, 0.026),
                                (59.3, 0.065), (55.8, 0.065), (60.1, 0.039), (61.4, 0.077),
                                (67.0, 0.049), (73.4, 0.032)]):
    variants.append(variant("clustered-variant-%d" % i, ms, flip))
for i, (ms, flip) in enumerate([(68.9, 7.5e-4), (70.8, 7.5e-4), (70.7, 1.2e-3), (85.1, 1.5e-3),
                                (73.5, 4.0e-3), (87.7, 4.2e-3), (109.9, 5.2e-4), (117.9, 0.021)]):
    variants.append(variant("accurate-variant-%d" % i, ms, flip))
results = {"variants": variants, "scene": "synthetic.json",
           "reference": {"ms": 58.4, "spec": "whitted"}}

import matplotlib.text

def boxes(ax):  # each label's text (an Annotation's own extent includes its leader line)
    r = ax.figure.canvas.get_renderer()
    out = []
    for t in ax.texts:
        t.update_positions(r)
        out.append(matplotlib.text.Text.get_window_extent(t, r))
    return out

def overlapping(bs):
    return sum(1 for i in range(len(bs)) for j in range(i) if bs[i].overlaps(bs[j]))

fig, ax, crowded = plot.build(results, "flip_mean")
assert crowded == 0, crowded
assert ax.get_yscale() == "symlog", ax.get_yscale()
# The reference's time and the all-exact frame's, both in the legend.
legend = [t.get_text() for t in ax.get_legend().get_texts()]
assert "reference whitted (58 ms)" in legend and "all-exact frame hybrid-exact (66 ms)" in legend, legend
shown = [v for v in variants if "same_frame_as" not in v]
assert len(ax.texts) == len(shown), (len(ax.texts), len(shown))
assert any(t.get_text() == "hybrid-exact (+6 same frame)" for t in ax.texts)
bs = boxes(ax)
assert overlapping(bs) == 0, overlapping(bs)
frame = ax.get_window_extent(ax.figure.canvas.get_renderer())
for t, b in zip(ax.texts, bs):
    assert frame.contains(b.x0, b.y0) and frame.contains(b.x1, b.y1), t.get_text()
    for v in shown:
        x, y = ax.transData.transform((v["total_ms"], v["metrics"]["flip_mean"]))
        assert not b.contains(x, y), (t.get_text(), v["name"])

# The same labels at one fixed offset (the old placement) overlap: the set is crowded.
for t in list(ax.texts):
    t.remove()
for v in shown:
    ax.annotate(v["name"], (v["total_ms"], v["metrics"]["flip_mean"]), textcoords="offset points",
                xytext=(5, 4), fontsize=7)
fixed = overlapping(boxes(ax))
assert fixed > 0, fixed

# Without an error of 0 the axis is a plain log scale.
fig2, ax2, _ = plot.build(dict(results, variants=[v for v in variants if v["name"] != "reference-self"]),
                          "flip_mean")
assert ax2.get_yscale() == "log", ax2.get_yscale()
# A time or an error that is not a number (results.json writes NaN and infinities as null) is
# no point: the title names the variant, and the plot is still drawn.
broken = [dict(v) for v in variants if v["name"] in ("hybrid-exact", "raster", "reference-self",
                                                      "clustered-variant-0")]
broken[1] = dict(broken[1], metrics={"flip_mean": None})
broken[2] = dict(broken[2], total_ms=0.0)
broken[3] = dict(broken[3], metrics={"flip_mean": float("inf")})
fig3, ax3, _ = plot.build(dict(results, variants=broken), "flip_mean")
title = ax3.get_title().replace("\n", " ")
for v in broken[1:]:
    assert v["name"] in title.split(": ", 2)[-1], (v["name"], title)
assert len(ax3.texts) == 1, [t.get_text() for t in ax3.texts]
print("labels clear: %d; at one fixed offset %d pairs overlap" % (len(shown), fixed))
]=] "${SOURCE_DIR}/samples/diptych/compare/plot_error_vs_time.py")
