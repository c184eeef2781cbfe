# Issue 13's reproducers (docs/robustness.md): crashes, hangs, unbounded work and silent
# overflow, each of which must now end in one named error line with a non-zero exit below 128
# (expect_failure rejects exits by signal).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(whitted "${SOURCE_DIR}/samples/scenes/whitted.json")
set(image "${SOURCE_DIR}/docs/images/whitted.png")

# A face index nested 100,000 deep crashed in nlohmann's recursive dump() while the error text
# was built; the parse now refuses nesting deeper than 256 levels, in scenes, recipes and glTF.
string(REPEAT "[" 100000 open)
string(REPEAT "]" 100000 close)
file(WRITE "${WORK_DIR}/deep-face.json" "{\"objects\": [{\"type\": \"mesh\", \"vertices\": [[0,0,0],[1,0,0],[0,1,0]], \"faces\": [[0, 1, ${open}2${close}]]}]}")
expect_failure(deep-face-index EXPECT "deep-face.json" "nested deeper than 256" ARGS render deep-face.json)
file(WRITE "${WORK_DIR}/deep-recipe.json" "{\"passes\": [{\"type\": \"gbuffer\", \"params\": {\"x\": ${open}${close}}}], \"outputs\": [\"gbuffer.normal\"]}")
expect_failure(deep-recipe EXPECT "deep-recipe.json" "nested deeper" ARGS render ${whitted} --recipe deep-recipe.json)
file(WRITE "${WORK_DIR}/deep.gltf" "{\"asset\": {\"version\": \"2.0\"}, \"extras\": ${open}${close}}")
expect_failure(deep-gltf EXPECT "deep.gltf" "nested deeper" ARGS render deep.gltf)
# Shallow nesting reaches the loader, whose message describes the value without dumping it.
file(WRITE "${WORK_DIR}/nested-face.json" "{\"objects\": [{\"type\": \"mesh\", \"vertices\": [[0,0,0],[1,0,0],[0,1,0]], \"faces\": [[0, 1, [[[2]]]]]}]}")
expect_failure(nested-face-index EXPECT "nested-face.json" "objects[0].faces[0][2]" "an array of 1 elements" ARGS render nested-face.json)

# FLIP's filter radius overflowed an int at --ppd 1e12 (SIGSEGV) and took minutes at 1e9.
foreach(ppd 1e12 1e9 0 nan -inf)
  expect_failure(diff-ppd-${ppd} EXPECT "--ppd" "[1, 1000]" ARGS diff ${image} ${image} --ppd ${ppd})
endforeach()
expect_success(diff-ppd-1000 ARGS diff ${image} ${image} --ppd 1000 --metrics flip)

# Devices, FIFOs and folders were read forever or failed without naming the file.
file(CREATE_LINK /dev/zero "${WORK_DIR}/zero.json" SYMBOLIC)
file(CREATE_LINK /dev/zero "${WORK_DIR}/zero.gltf" SYMBOLIC)
file(CREATE_LINK /dev/zero "${WORK_DIR}/zero.png" SYMBOLIC)
expect_failure(scene-dev-zero EXPECT "zero.json" "not a regular file" ARGS render zero.json)
expect_failure(gltf-dev-zero EXPECT "zero.gltf" "not a regular file" ARGS render zero.gltf)
expect_failure(recipe-dev-zero EXPECT "zero.json" "not a regular file" ARGS render ${whitted} --recipe zero.json)
expect_failure(diff-dev-zero EXPECT "zero.png" "not a regular file" ARGS diff zero.png ${image})
expect_failure(recipe-directory EXPECT "${WORK_DIR}" "is a directory" ARGS render ${whitted} --recipe ${WORK_DIR})
execute_process(COMMAND mkfifo "${WORK_DIR}/fifo.json" RESULT_VARIABLE mkfifo_rc)
if(mkfifo_rc EQUAL 0)
  expect_failure(scene-fifo EXPECT "fifo.json" "not a regular file" ARGS render fifo.json)
endif()
# A glTF buffer that links to /dev/zero: tinygltf reads it through the same check.
file(CREATE_LINK /dev/zero "${WORK_DIR}/zero.bin" SYMBOLIC)
file(WRITE "${WORK_DIR}/zero-buffer.gltf" "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": \"zero.bin\", \"byteLength\": 12}]}")
expect_failure(gltf-buffer-dev-zero EXPECT "zero-buffer.gltf" "not a regular file" ARGS render zero-buffer.gltf)

# Unbounded work: more lights than kMaxLights, tessellation beyond kMaxTriangles.
string(REPEAT "{\"type\": \"point\", \"position\": [0, 5, 0]}," 1100 lights)
file(WRITE "${WORK_DIR}/many-lights.json" "{\"lights\": [${lights} {\"type\": \"point\", \"position\": [0, 5, 0]}], \"objects\": [{\"type\": \"sphere\"}]}")
expect_failure(too-many-lights EXPECT "many-lights.json" "1101 lights" "limit is 1024" ARGS render many-lights.json)
file(WRITE "${WORK_DIR}/huge-sphere.json" "{\"objects\": [{\"type\": \"sphere\", \"segments\": [4096, 4096]}]}")
expect_failure(too-many-segments EXPECT "huge-sphere.json" "objects[0].segments" "triangles" ARGS render huge-sphere.json)

# Finite but huge values overflowed in shading products and reached the image.
file(WRITE "${WORK_DIR}/huge-light.json" "{\"lights\": [{\"type\": \"sphere\", \"position\": [0, 5, 0], \"radius\": 3e38}], \"objects\": [{\"type\": \"sphere\"}]}")
expect_failure(huge-light-radius EXPECT "huge-light.json" "radius" "at most" ARGS render huge-light.json)
file(WRITE "${WORK_DIR}/huge-checker.json" "{\"materials\": {\"c\": {\"checker\": {\"a\": [1e30, 0, 0]}}}, \"objects\": [{\"type\": \"sphere\", \"material\": \"c\"}]}")
expect_failure(huge-checker EXPECT "huge-checker.json" "checker.a" "at most" ARGS render huge-checker.json)
file(WRITE "${WORK_DIR}/huge-env.json" "{\"environment\": {\"color\": [3.4e38, 3.4e38, 3.4e38]}, \"objects\": [{\"type\": \"sphere\"}]}")
expect_failure(huge-environment EXPECT "huge-env.json" "environment color" "at most" ARGS render huge-env.json)

# Command line: overflow, non-finite numbers, the right option named, outputs checked first.
set(small --size 32x24 --frames 1 --warmup 0)
expect_failure(size-overflow EXPECT "--size" "4294967360x48" ARGS render ${whitted} --size 4294967360x48)
expect_failure(size-sign EXPECT "--size" ARGS render ${whitted} --size +64x48)
foreach(ev nan inf -inf 1e9)
  expect_failure(exposure-${ev} EXPECT "--exposure" ARGS render ${whitted} --exposure ${ev})
endforeach()
expect_failure(warmup-negative EXPECT "--warmup" ARGS render ${whitted} --warmup -5)
expect_failure(out-missing-folder EXPECT "--out" "/nonexistent/dir" "does not exist" ARGS render ${whitted} ${small} --out /nonexistent/dir/a.png)
if(NOT EXISTS "/nonexistent")
  message(STATUS "out-missing-folder created nothing, as expected")
else()
  message(FATAL_ERROR "render created /nonexistent")
endif()
expect_failure(graph-out-unwritable EXPECT "--graph-out" "/nonexistent" ARGS render ${whitted} ${small} --out out.png --graph-out /nonexistent/g.dot)
expect_failure(timings-in-proc EXPECT "--timings" "/proc/diptych-timings.json" "cannot be written" ARGS render ${whitted} ${small} --out out.png --timings /proc/diptych-timings.json)
expect_failure(timings-is-folder EXPECT "--timings" "not a regular file" ARGS render ${whitted} ${small} --out out.png --timings ${WORK_DIR})

# SDF objects: every distance evaluation walks every node and polygonisation evaluates the tree
# (resolution + 1)^3 times at load, so both the node count and their product are bounded.
set(sdf_children "{\"type\": \"sphere\", \"radius\": 0.1}")
foreach(i RANGE 1 10)
  set(sdf_children "{\"type\": \"union\", \"children\": [${sdf_children}, ${sdf_children}]}")
endforeach()
file(WRITE "${WORK_DIR}/sdf-nodes.json" "{\"objects\": [{\"type\": \"sdf\", \"shape\": ${sdf_children}}]}")
expect_failure(sdf-too-many-nodes EXPECT "sdf-nodes.json" "more than 1024 nodes" ARGS render sdf-nodes.json)
set(sdf_children "{\"type\": \"sphere\", \"radius\": 0.1}")
foreach(i RANGE 1 6)
  set(sdf_children "{\"type\": \"union\", \"children\": [${sdf_children}, ${sdf_children}]}")
endforeach()
file(WRITE "${WORK_DIR}/sdf-budget.json"
     "{\"objects\": [{\"type\": \"sdf\", \"resolution\": 256, \"shape\": ${sdf_children}}]}")
expect_failure(sdf-polygonise-budget EXPECT "sdf-budget.json" "resolution" "distance evaluations"
               ARGS render sdf-budget.json)
