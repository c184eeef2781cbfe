# compare on a real glTF model (TransmissionTest, whose colour textures all sample trilinearly):
# texture-sampler (each texture's own glTF sampler) is texture-trilinear's image, and the reason
# names the samplers; texture-nearest (level 0, no mipmaps) is an image of its own. The texture
# variants now reach glTF materials at all (the signal is the base colour, docs/textures.md).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
if(NOT IS_DIRECTORY "${SHARED_SCENES}")
  # CTest reports this as skipped (SKIP_REGULAR_EXPRESSION in tests/CMakeLists.txt), not passed.
  message("DIPTYCH_SKIP: no shared scenes at ${SHARED_SCENES}")
  return()
endif()
expect_success(transmission-test ARGS compare "${SHARED_SCENES}/transmission-test/TransmissionTest.glb"
               --variants hybrid-exact,texture-nearest,texture-trilinear,texture-sampler
               --size 96x72 --frames 1 --warmup 0 --out tt FILES tt/results.json)
expect_python("TransmissionTest: same images" [=[
import json, sys
variants = {v["name"]: v for v in json.load(open(sys.argv[1]))["variants"]}
sampler = variants["texture-sampler"]
assert sampler.get("same_image_as") == "texture-trilinear", sampler.get("same_image_as")
assert sampler["same_image_reason"].endswith("every colour texture's glTF sampler asks for trilinear filtering"), sampler["same_image_reason"]
for name in ("hybrid-exact", "texture-nearest", "texture-trilinear"):
    assert "same_image_as" not in variants[name], (name, variants[name].get("same_image_reason"))
    assert "same_frame_as" not in variants[name], name
# The filters reach the glTF materials: nearest and trilinear differ from the exact frame.
exact = variants["hybrid-exact"]["metrics"]["flip_mean"]
for name in ("texture-nearest", "texture-trilinear"):
    assert variants[name]["metrics"]["flip_mean"] > exact, (name, variants[name]["metrics"]["flip_mean"], exact)
print("TransmissionTest:", sampler["same_image_reason"])
]=] "${WORK_DIR}/tt/results.json")
