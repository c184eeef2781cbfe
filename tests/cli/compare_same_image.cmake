# diptych compare says when a variant timed on its own renders an earlier variant's image
# (samples/diptych/compare/same_image.h): on whitted the environment is one colour and there is
# one transparent sphere, so env-sphere is env-cube's image and unsorted-blend sorted-blend's,
# each with the producers that differ and the scene's reason; a shadow map that changes pixels is
# not matched. On techniques.json (a sky with a sun, two overlapping glass objects) the same
# variants differ and nothing is matched. Tiny sizes, one frame: no timing is asserted.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(variants hybrid-exact,env-cube,env-sphere,sorted-blend,unsorted-blend,shadow-map-256-none)
set(size --size 96x72 --frames 1 --warmup 0)
expect_success(whitted ARGS compare --variants ${variants} ${size} --out wh
               FILES wh/results.json wh/results.csv wh/report.html)
file(WRITE "${WORK_DIR}/stdout.txt" "${LAST_STDOUT}")
expect_python("whitted: same images" [=[
import csv, json, re, sys
variants = {v["name"]: v for v in json.load(open(sys.argv[1] + "/results.json"))["variants"]}
stdout = open(sys.argv[2]).read()
expected = {
    "env-sphere": ("env-cube", "reflection: env_sphere, not env_cube: the scene's environment is one colour"),
    "unsorted-blend": ("sorted-blend", "transmission: unsorted_blend, not sorted_blend: the scene has at most one transparent mesh"),
}
for name, (earlier, reason) in expected.items():
    v = variants[name]
    assert v.get("same_image_as") == earlier, (name, v.get("same_image_as"))
    assert v["same_image_reason"].startswith(reason), (name, v["same_image_reason"])
    assert 0 <= v["same_image_difference"] <= 1e-5, (name, v["same_image_difference"])
    # Timed on its own (its frame differs), its metrics equal to the earlier image's.
    assert "same_frame_as" not in v and v["total_ms"] > 0, name
    for metric in ("rmse", "flip_mean"):
        assert abs(v["metrics"][metric] - variants[earlier]["metrics"][metric]) <= 1e-6 * variants[earlier]["metrics"][metric] + 1e-12, (name, metric)
    assert re.search(r"^" + name + r" .* = " + earlier + r"$", stdout, re.M), ("table row", name, stdout)
    assert re.search(r"^" + name + r": same image as " + earlier + r" \(largest difference ", stdout, re.M), stdout
for name in ("hybrid-exact", "env-cube", "sorted-blend", "shadow-map-256-none"):
    assert "same_image_as" not in variants[name], (name, variants[name].get("same_image_reason"))
rows = {r["variant"]: r for r in csv.DictReader(open(sys.argv[1] + "/results.csv"))}
assert rows["env-sphere"]["same_image_as"] == "env-cube" and rows["env-cube"]["same_image_as"] == "", rows
print("whitted:", {n: v["same_image_reason"] for n, v in variants.items() if "same_image_as" in v})
]=] "${WORK_DIR}/wh" "${WORK_DIR}/stdout.txt")

# The report says it in a real browser, in the results table and in the image captions.
chromium_dump_dom(wh/report.html dom)
string(REGEX MATCHALL "same image as env-cube" hits "${dom}")
list(LENGTH hits count)
if(count LESS 2)
  message(FATAL_ERROR "report.html names env-cube's image fewer than twice:\n${dom}")
endif()

# A scene that tells them apart: nothing matched.
expect_success(techniques ARGS compare "${SOURCE_DIR}/samples/scenes/techniques.json"
               --variants ${variants} ${size} --out tq FILES tq/results.json)
expect_python("techniques: different images" [=[
import json, sys
variants = json.load(open(sys.argv[1]))["variants"]
matched = {v["name"]: v["same_image_as"] for v in variants if "same_image_as" in v}
assert not matched, matched
print("techniques: no variant matched")
]=] "${WORK_DIR}/tq/results.json")
