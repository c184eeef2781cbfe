# Issue 12's classes from contacts (docs/shadow-bias.md §3): on contact-slab the ground's false
# light next to the slab's foot is peter-panning, never a leak; in closed-room the light through
# the thin roof and walls is a leak (tests/tools/check_bias_classes.py).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
expect_success(contact ARGS sweep "${SOURCE_DIR}/samples/scenes/contact-slab.json"
               --slot visibility=shadow_map:bias=constant,resolution=1024
               --vary constant_bias=0.01,0.05,0.2,0.5 --receiver ground --size 240x180 --out contact
               FILES contact/results.json contact/classes/contacts-p0000.png)
expect_success(room ARGS sweep "${SOURCE_DIR}/samples/scenes/closed-room.json"
               --slot visibility=shadow_map:bias=constant,resolution=1024
               --vary constant_bias=0.01,0.03,0.3 --size 240x180 --out room FILES room/results.json)
foreach(case contact room)
  expect_check(${case} check_bias_classes.py ${case} "${WORK_DIR}/${case}/results.json")
endforeach()
expect_failure(contact-negative EXPECT "--contact" "finite distance"
               ARGS sweep "${SOURCE_DIR}/samples/scenes/contact-slab.json"
                    --slot visibility=shadow_map --vary resolution=64 --contact -1 --out bad)
expect_failure(contact-nan EXPECT "--contact" "finite distance" ARGS shadow-bias --contact nan
               --out bad)
