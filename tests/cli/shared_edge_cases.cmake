# `diptych render` on the shared malformed glTF files: each must fail with a non-zero exit and
# exactly one `diptych: error:` line naming the file and the problem, leaving no image behind.
# Files the loader recovers (documented in tests/shared_scenes/test_shared_loaders.cpp) must
# render, with their warning on stderr. Expected substrings are what the loader reports (the
# element path and the defect), not the whole line, so wording around them may change.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
if(NOT IS_DIRECTORY "${SHARED_SCENES}")
  # CTest reports this as skipped (SKIP_REGULAR_EXPRESSION in tests/CMakeLists.txt), not passed.
  message("DIPTYCH_SKIP: no shared scenes at ${SHARED_SCENES}")
  return()
endif()
set(assimp "${SHARED_SCENES}/edge-cases-assimp")
set(bounds "${SHARED_SCENES}/edge-cases-tinygltf/BoundsChecking")
set(small --size 64x48 --frames 1 --warmup 0)

# Every edge-case file must be listed below, so that a new file is not silently untested.
file(GLOB_RECURSE edge_files RELATIVE "${SHARED_SCENES}"
     "${assimp}/*.gltf" "${assimp}/*.glb" "${bounds}/*.gltf" "${bounds}/*.glb")
set(covered
    edge-cases-assimp/BoxWithInfinites.glb
    edge-cases-assimp/RecursiveNodes.gltf
    edge-cases-assimp/IndexOutOfRange/IndexOutOfRange.gltf
    edge-cases-assimp/IndexOutOfRange/AllIndicesOutOfRange.gltf
    edge-cases-assimp/BoxBadNormals.glb
    edge-cases-tinygltf/BoundsChecking/integer-out-of-bounds.gltf
    edge-cases-tinygltf/BoundsChecking/invalid-buffer-index.gltf
    edge-cases-tinygltf/BoundsChecking/invalid-buffer-view-index.gltf
    edge-cases-tinygltf/BoundsChecking/invalid-primitive-indices.gltf)
foreach(f IN LISTS edge_files)
  list(FIND covered "${f}" index)  # not IN_LIST: -P scripts run without CMP0057
  if(index EQUAL -1)
    message(FATAL_ERROR "edge-case file ${f} has no expectation in ${CMAKE_CURRENT_LIST_FILE}")
  endif()
endforeach()

expect_failure(box-with-infinites
  EXPECT "diptych: error: ${assimp}/BoxWithInfinites.glb: "
         "meshes[0].primitives[0].attributes.POSITION" "non-finite value"
  ARGS render "${assimp}/BoxWithInfinites.glb" ${small})
expect_failure(recursive-nodes
  EXPECT "diptych: error: ${assimp}/RecursiveNodes.gltf: " "node cycle"
         "nodes[0] -> nodes[1] -> nodes[0]"
  ARGS render "${assimp}/RecursiveNodes.gltf" ${small})
expect_failure(index-out-of-range
  EXPECT "diptych: error: ${assimp}/IndexOutOfRange/IndexOutOfRange.gltf: "
         "meshes[0].primitives[0].indices" "index 255" "out of range" "24 vertices"
  ARGS render "${assimp}/IndexOutOfRange/IndexOutOfRange.gltf" ${small})
expect_failure(all-indices-out-of-range
  EXPECT "diptych: error: ${assimp}/IndexOutOfRange/AllIndicesOutOfRange.gltf: "
         "meshes[0].primitives[0].indices" "index 65535" "out of range" "24 vertices"
  ARGS render "${assimp}/IndexOutOfRange/AllIndicesOutOfRange.gltf" ${small})

# tinygltf rejects these while parsing; its own message follows the file name.
expect_failure(integer-out-of-bounds
  EXPECT "diptych: error: ${bounds}/integer-out-of-bounds.gltf: " "glTF parse error (tinygltf)"
         "byteLength"
  ARGS render "${bounds}/integer-out-of-bounds.gltf" ${small})
expect_failure(invalid-buffer-index
  EXPECT "diptych: error: ${bounds}/invalid-buffer-index.gltf: " "glTF parse error (tinygltf)"
         "buffer \"1\" not found"
  ARGS render "${bounds}/invalid-buffer-index.gltf" ${small})
expect_failure(invalid-buffer-view-index
  EXPECT "diptych: error: ${bounds}/invalid-buffer-view-index.gltf: "
         "glTF parse error (tinygltf)" "invalid bufferView"
  ARGS render "${bounds}/invalid-buffer-view-index.gltf" ${small})
expect_failure(invalid-primitive-indices
  EXPECT "diptych: error: ${bounds}/invalid-primitive-indices.gltf: "
         "glTF parse error (tinygltf)" "indices accessor out of bounds"
  ARGS render "${bounds}/invalid-primitive-indices.gltf" ${small})

# Recovered, not rejected: renders, with one warning naming the fix.
function(expect_render label file warning)
  file(REMOVE "${WORK_DIR}/${label}.png")
  expect_success(${label} ARGS render "${file}" ${small} --out ${label}.png FILES ${label}.png)
  if(LAST_STDERR MATCHES "diptych: error:")
    message(FATAL_ERROR "[${label}] exit 0 but an error line on stderr:\n${LAST_STDERR}")
  endif()
  if(warning)
    string(FIND "${LAST_STDERR}" "${warning}" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "[${label}] stderr lacks the warning '${warning}':\n${LAST_STDERR}")
    endif()
  endif()
endfunction()
expect_render(box-bad-normals "${assimp}/BoxBadNormals.glb" "zero-length normals replaced")
expect_render(negative-scale "${SHARED_SCENES}/negative-scale-test/NegativeScaleTest.glb" "")
# KHR_materials_iridescence is a required extension of this file, now supported.
expect_render(iridescence-suzanne "${SHARED_SCENES}/iridescence-suzanne/IridescenceSuzanne.glb" "")
expect_render(mesh-primitive-modes "${SHARED_SCENES}/mesh-primitive-modes/MeshPrimitiveModes.gltf"
              "skipped POINTS primitive")
