# The surface-detail comparison (docs/materials.md#bump-vs-normal-maps): on
# samples/scenes/surface-detail.json, compare's default set gains detail-flat, detail-bump,
# detail-normal-map and detail-displaced, measured against a reference traced on the displaced
# surfaces. Orderings that must hold whatever the machine (no timings):
#  - the displaced variant is the reference's own surface through the all-exact hybrid: its error
#    is float noise, far below the others';
#  - flat has the largest error (it has no detail at all);
#  - bump and normal map are closer to each other than either is to flat (one height field).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
expect_success(surface-detail ARGS compare "${SOURCE_DIR}/samples/scenes/surface-detail.json"
               --variants detail-flat,detail-bump,detail-normal-map,detail-displaced
               --size 200x150 --frames 1 --warmup 0 --out cmp FILES cmp/results.json)
string(FIND "${LAST_STDERR}" "reference whitted on the displaced surfaces" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "the reference did not say it traces the displaced surfaces:\n${LAST_STDERR}")
endif()
expect_python("surface-detail compare check" [=[
import json, sys
results = json.load(open(sys.argv[1]))
v = {x["name"]: x for x in results["variants"]}
for name, mode in (("detail-flat", "flat"), ("detail-bump", "bump"),
                   ("detail-normal-map", "normal_map"), ("detail-displaced", "displaced")):
    if v[name]["surface_detail"] != mode:
        sys.exit(f"{name}: surface_detail {v[name]['surface_detail']!r}, expected {mode!r}")
if results["reference"]["surfaces"] != "displaced":
    sys.exit(f"reference surfaces: {results['reference']['surfaces']!r}")
if not results["one_time_ms"].get("displaced_reference_build_ms", 0) > 0:
    sys.exit("one_time_ms lacks displaced_reference_build_ms")
for metric in ("flip_mean", "rmse"):
    e = {n: v[n]["metrics"][metric] for n in v}
    print(metric, e)
    flat, bump, nmap, disp = e["detail-flat"], e["detail-bump"], e["detail-normal-map"], e["detail-displaced"]
    if not disp < 0.05 * min(bump, nmap):
        sys.exit(f"{metric}: displaced hybrid is not the reference's surface ({disp} vs {bump}, {nmap})")
    if not flat > max(bump, nmap):
        sys.exit(f"{metric}: flat ({flat}) is not the worst (bump {bump}, normal map {nmap})")
    if not abs(bump - nmap) < min(flat - bump, flat - nmap):
        sys.exit(f"{metric}: bump ({bump}) and normal map ({nmap}) are not closer to each other than to flat ({flat})")
]=] "${WORK_DIR}/cmp/results.json")

# A variants file with an unknown mode names the file and the place.
file(WRITE "${WORK_DIR}/bad.json" "{\"variants\": [{\"name\": \"x\", \"surface_detail\": \"wavy\"}]}")
expect_failure(surface-detail-bad EXPECT "bad.json" "variants[0].surface_detail"
               ARGS compare "${SOURCE_DIR}/samples/scenes/surface-detail.json" --variants bad.json --out cmp2)
