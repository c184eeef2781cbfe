# diptych compare measures a frame once (issue 9): on whitted the texture_filtering slot is culled
# (no colour textures), so every texture-* variant compiles to hybrid-exact's frame and must be
# reported as "same_frame_as" it, not timed again; variants that differ (raster, a shadow map)
# are timed. With --rounds 2 each speed-up carries its per-round ratios and the table their
# range; with one round the summary says such speed-ups do not separate small differences from
# load noise. Tiny sizes, one frame: the timings' values are never asserted, only their shape.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(textures texture-nearest,texture-bilinear,texture-distance,texture-trilinear,texture-anisotropic,texture-sampler)
set(size --size 96x72 --frames 1 --warmup 0)
expect_success(same-frame ARGS compare --variants hybrid-exact,${textures},raster,shadow-map-256-none
               ${size} --rounds 2 --out cmp
               FILES cmp/results.json cmp/report.html cmp/images/texture-sampler.png
               cmp/panels/texture-nearest.png cmp/graphs/texture-nearest.json)
file(WRITE "${WORK_DIR}/stdout.txt" "${LAST_STDOUT}")
expect_python("same-frame results" [=[
import json, re, statistics, sys
results = json.load(open(sys.argv[1] + "/results.json"))
variants = {v["name"]: v for v in results["variants"]}
stdout = open(sys.argv[2]).read()
exact = variants["hybrid-exact"]
textures = [n for n in variants if n.startswith("texture-")]
assert len(textures) == 6, textures
for name in textures:
    v = variants[name]
    assert v.get("same_frame_as") == "hybrid-exact", (name, v.get("same_frame_as"))
    assert v["timings_from"] == "hybrid-exact", name
    assert "texture_filtering culled" in v["same_frame_reason"], v["same_frame_reason"]
    # The same frame: hybrid-exact's metrics and timings, no point of its own on the front.
    for key in ("metrics", "total_ms", "total_ms_rounds", "speedup_vs_reference", "speedup_rounds", "rays"):
        assert v[key] == exact[key], (name, key, v[key], exact[key])
    assert v["pareto"] is False and v["one_time_ms"] == {}, name
    # Its own compiled graph, with its own texture pass culled.
    graph = json.load(open(sys.argv[1] + "/" + v["files"]["graph"]))
    culled = [p for p in graph["passes"] if p["name"] == "texture_filtering"]
    assert culled and culled[0]["culled"] and culled[0]["type"] != "texture_exact", culled
    row = re.search(r"^" + name + r"\s+same frame as hybrid-exact \(texture_filtering culled: .+\)$", stdout, re.M)
    assert row, ("summary row", name, stdout)
for name in ("hybrid-exact", "raster", "shadow-map-256-none"):
    v = variants[name]
    assert "same_frame_as" not in v, (name, v.get("same_frame_reason"))
    # Two rounds: two paired ratios, each reference / variant of its round, their median the
    # speed-up, and their range printed beside it.
    r = v["speedup_rounds"]
    assert len(r) == 2 and len(v["total_ms_rounds"]) == 2, (name, r)
    for ratio, ms, ref in zip(r, v["total_ms_rounds"], results["reference"]["ms_rounds"]):
        assert abs(ratio - ref / ms) < 1e-9, (name, ratio, ref, ms)
    assert abs(v["speedup_vs_reference"] - statistics.median(r)) < 1e-9, name
    # Against the all-exact frame likewise: hybrid-exact / variant per round, paired; "-" on
    # hybrid-exact's own row.
    against = "-"
    if name != "hybrid-exact":
        e = v["speedup_vs_exact_rounds"]
        for ratio, ms, ex in zip(e, v["total_ms_rounds"], variants["hybrid-exact"]["total_ms_rounds"]):
            assert abs(ratio - ex / ms) < 1e-9, (name, ratio, ex, ms)
        assert len(e) == 2 and abs(v["speedup_vs_exact"] - statistics.median(e)) < 1e-9, (name, e)
        # And in milliseconds: hybrid-exact - variant per round, their median.
        d = v["saved_ms_vs_exact_rounds"]
        for saved, ms, ex in zip(d, v["total_ms_rounds"], variants["hybrid-exact"]["total_ms_rounds"]):
            assert abs(saved - (ex - ms)) < 1e-9, (name, saved, ex, ms)
        assert len(d) == 2 and abs(v["saved_ms_vs_exact"] - statistics.median(d)) < 1e-9, (name, d)
        assert v["exact_variant"] == "hybrid-exact", (name, v["exact_variant"])
        against = "%.2fx (%.2f-%.2f)" % (v["speedup_vs_exact"], min(e), max(e))
    else:
        assert "speedup_vs_exact" not in v, name
    shown = "%.2fx (%.2f-%.2f)" % (v["speedup_vs_reference"], min(r), max(r))
    assert re.search(r"^" + name + r"\s+[0-9.]+\s+" + re.escape(shown) + r"\s+" + re.escape(against) + r"\s",
                     stdout, re.M), (shown, against, stdout)
assert "not distinguishable" not in stdout, "the one-round note printed with two rounds"
print("same frame:", textures, "->", variants["texture-nearest"]["same_frame_reason"])
]=] "${WORK_DIR}/cmp" "${WORK_DIR}/stdout.txt")

# The report: a row per variant (same-frame ones say whose frame they are), in a real browser.
chromium_dump_dom(cmp/report.html dom)
foreach(expected "data-plot-loaded=\"true\"" "data-rows=\"9\"" "same frame as hybrid-exact (texture_filtering culled")
  string(FIND "${dom}" "${expected}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "report.html lacks '${expected}':\n${dom}")
  endif()
endforeach()

# The claim itself: a texture variant timed alone (nothing earlier to match) renders exactly
# hybrid-exact's image. One round: no range, and the note on load noise, once.
expect_success(timed-alone ARGS compare --variants texture-anisotropic ${size} --out cmp
               FILES cmp/images/texture-anisotropic.exr)
string(REGEX MATCHALL "not distinguishable from that noise" notes "${LAST_STDOUT}")
list(LENGTH notes count)
# No all-exact frame in this run: its "vs exact" column is "-".
string(REGEX MATCH "texture-anisotropic +[0-9.]+ +[0-9.]+x +- +[0-9]" row "${LAST_STDOUT}")
if(NOT count EQUAL 1 OR NOT row)
  message(FATAL_ERROR "one round: expected the row without a range and the note once:\n${LAST_STDOUT}")
endif()
expect_success(diff ARGS diff cmp/images/texture-anisotropic.exr cmp/images/hybrid-exact.exr)
string(REGEX MATCH "\nrmse +0\n" zero "${LAST_STDOUT}")
if(NOT zero)
  message(FATAL_ERROR "texture-anisotropic differs from hybrid-exact:\n${LAST_STDOUT}")
endif()

# Where the scene has colour textures the texture variants differ and are timed; and a user's
# variants that set a parameter to its default are one frame ("the same compiled graph").
file(WRITE "${WORK_DIR}/variants.json" "{\"variants\": [
  {\"name\": \"hybrid-exact\"},
  {\"name\": \"nearest\", \"slots\": [\"texture_filtering=texture_nearest\"]},
  {\"name\": \"sm\", \"slots\": [\"visibility=shadow_map\"]},
  {\"name\": \"sm-2048\", \"slots\": [\"visibility=shadow_map:resolution=2048\"]},
  {\"name\": \"sm-1024\", \"slots\": [\"visibility=shadow_map:resolution=1024\"]}]}")
expect_success(textured ARGS compare "${SOURCE_DIR}/samples/scenes/textures.json" --variants variants.json
               --size 64x48 --frames 1 --warmup 0 --out tex FILES tex/results.json)
expect_python("textured scene" [=[
import json, sys
variants = {v["name"]: v for v in json.load(open(sys.argv[1]))["variants"]}
for name in ("hybrid-exact", "nearest", "sm", "sm-1024"):
    assert "same_frame_as" not in variants[name], (name, variants[name].get("same_frame_reason"))
assert variants["nearest"]["metrics"]["rmse"] > variants["hybrid-exact"]["metrics"]["rmse"]
v = variants["sm-2048"]
assert v.get("same_frame_as") == "sm" and v["same_frame_reason"] == "the same compiled graph", v
print("textured:", {n: v.get("same_frame_as") for n, v in variants.items()})
]=] "${WORK_DIR}/tex/results.json")

# On a bump-mapped scene detail-bump is the scene as authored (bump): hybrid-exact's frame;
# detail-flat changes the scene and is timed.
expect_success(detail ARGS compare "${SOURCE_DIR}/samples/scenes/surface-detail.json"
               --variants hybrid-exact,detail-bump,detail-flat --size 48x36 --frames 1 --warmup 0
               --out det FILES det/results.json)
expect_python("surface detail" [=[
import json, sys
variants = {v["name"]: v for v in json.load(open(sys.argv[1]))["variants"]}
bump, flat = variants["detail-bump"], variants["detail-flat"]
assert bump.get("same_frame_as") == "hybrid-exact", bump.get("same_frame_as")
assert bump["same_frame_reason"] == "surface_detail bump: the scene as authored", bump["same_frame_reason"]
assert "same_frame_as" not in flat, flat.get("same_frame_reason")
print("detail-bump:", bump["same_frame_reason"])
]=] "${WORK_DIR}/det/results.json")
