# Bad command lines, scenes and recipes: one clear error line, non-zero exit, no output image.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(whitted "${SOURCE_DIR}/samples/scenes/whitted.json")

expect_failure(no-subcommand EXPECT "subcommand" ARGS)
expect_failure(unknown-option EXPECT "--bogus" ARGS render ${whitted} --bogus)
expect_failure(missing-scene EXPECT "missing-scene.json" "not found" ARGS render missing-scene.json)
expect_failure(bad-size EXPECT "--size" "12by3" ARGS render ${whitted} --size 12by3)
expect_failure(bad-out-ext EXPECT "--out" ".txt" ARGS render ${whitted} --out out.txt)
expect_failure(missing-recipe EXPECT "nope.json" ARGS render ${whitted} --recipe nope.json)

file(WRITE "${WORK_DIR}/malformed.json" "{ \"camera\": { ")
expect_failure(malformed-scene EXPECT "malformed.json" ARGS render malformed.json)

file(WRITE "${WORK_DIR}/unknown-key.json" "{\"objects\": [{\"type\": \"sphere\", \"radius\": 1, \"colour\": [1,0,0]}]}")
expect_failure(unknown-scene-key EXPECT "unknown-key.json" "objects[0]" ARGS render unknown-key.json)

file(WRITE "${WORK_DIR}/neg-radius.json" "{\"objects\": [{\"type\": \"sphere\", \"radius\": -1}]}")
expect_failure(negative-radius EXPECT "neg-radius.json" "radius" ARGS render neg-radius.json)

file(WRITE "${WORK_DIR}/inf.json" "{\"objects\": [{\"type\": \"sphere\", \"radius\": 1e999}]}")
expect_failure(infinite-number EXPECT "inf.json" ARGS render inf.json)

file(WRITE "${WORK_DIR}/cycle-recipe.json" "{\"passes\": [{\"name\": \"a\", \"type\": \"shade\", \"inputs\": {\"hits\": \"b.color\"}}, {\"name\": \"b\", \"type\": \"shade\", \"inputs\": {\"hits\": \"a.color\"}}], \"outputs\": [\"a.color\"]}")
expect_failure(recipe-cycle EXPECT "cycle-recipe.json" "cycle" ARGS render ${whitted} --recipe cycle-recipe.json)

file(WRITE "${WORK_DIR}/unknown-pass.json" "{\"passes\": [{\"type\": \"warp_drive\"}], \"outputs\": [\"warp_drive.color\"]}")
expect_failure(recipe-unknown-pass EXPECT "unknown-pass.json" "passes[0].type" "warp_drive" ARGS render ${whitted} --recipe unknown-pass.json)

file(WRITE "${WORK_DIR}/bad-param.json" "{\"passes\": [{\"type\": \"gbuffer\", \"params\": {\"zoom\": 2}}], \"outputs\": [\"gbuffer.normal\"]}")
expect_failure(recipe-unknown-param EXPECT "bad-param.json" "passes[0].params.zoom" ARGS render ${whitted} --recipe bad-param.json)

file(WRITE "${WORK_DIR}/missing-producer.json" "{\"passes\": [{\"type\": \"gbuffer\"}, {\"type\": \"shade\", \"inputs\": {\"hits\": \"gbuffer.vis\"}}], \"outputs\": [\"shade.color\"]}")
expect_failure(recipe-never-written EXPECT "missing-producer.json" "gbuffer.vis" "never written" ARGS render ${whitted} --recipe missing-producer.json)

expect_failure(integer-output EXPECT "holds integers" ARGS render ${whitted} --output gbuffer.hits --size 32x24 --frames 1 --warmup 0)

# The G-buffer output is `hits` (it was `visibility`, which also named a light's V_i): the old
# spelling is one error that gives the new name.
file(WRITE "${WORK_DIR}/old-gbuffer-spelling.json" "{\"passes\": [{\"type\": \"gbuffer\"}, {\"type\": \"shade\", \"inputs\": {\"hits\": \"gbuffer.visibility\"}}], \"outputs\": [\"shade.color\"]}")
expect_failure(recipe-old-gbuffer-spelling EXPECT "old-gbuffer-spelling.json" "passes[1].inputs.hits" "gbuffer.hits" ARGS render ${whitted} --recipe old-gbuffer-spelling.json)
file(WRITE "${WORK_DIR}/old-input-spelling.json" "{\"passes\": [{\"type\": \"gbuffer\"}, {\"type\": \"shade\", \"inputs\": {\"visibility\": \"gbuffer.hits\"}}], \"outputs\": [\"shade.color\"]}")
expect_failure(recipe-old-input-spelling EXPECT "old-input-spelling.json" "passes[1].inputs.visibility" "'hits'" ARGS render ${whitted} --recipe old-input-spelling.json)

# --slot on a recipe whose shade input names a pass that does not exist (was a null dereference).
file(WRITE "${WORK_DIR}/slot-ghost-producer.json" "{\"passes\": [{\"type\": \"gbuffer\"}, {\"type\": \"shade\", \"inputs\": {\"hits\": \"gbuffer.hits\", \"light_visibility\": \"ghost.visibility\"}}], \"outputs\": [\"shade.color\"]}")
expect_failure(slot-override-ghost-producer EXPECT "slot-ghost-producer.json" "light_visibility" "no pass named 'ghost'" ARGS render ${whitted} --recipe slot-ghost-producer.json --slot visibility=shadow_map)
