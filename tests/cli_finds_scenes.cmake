# The CLI finds the example scenes whatever the working directory, from the build tree and from an
# installation (io/scene_loader.h), and says where it looked when they are not there.
# cmake -DCLI=<built obscura> -DBUILD_DIR=<build tree> -DWORK_DIR=<scratch folder> -P this file
file(REMOVE_RECURSE "${WORK_DIR}")
set(elsewhere "${WORK_DIR}/elsewhere")  # a working directory with no scenes in or above it
set(prefix "${WORK_DIR}/prefix")
set(no_scenes "${WORK_DIR}/no-scenes")
file(MAKE_DIRECTORY "${elsewhere}" "${no_scenes}")
unset(ENV{OBSCURA_SCENES_DIR})

# Runs `program args…` from the scratch working directory; `out` gets its exit code and output.
function(run_from_elsewhere out program)
  execute_process(COMMAND "${program}" ${ARGN} WORKING_DIRECTORY "${elsewhere}"
                  RESULT_VARIABLE code OUTPUT_VARIABLE output ERROR_VARIABLE output)
  set(${out}_code "${code}" PARENT_SCOPE)
  set(${out}_output "${output}" PARENT_SCOPE)
endfunction()

function(expect_render program image)
  run_from_elsewhere(render "${program}" render bunny --width 32 --height 32 --spp 1
                     -o "${image}")
  if(NOT render_code EQUAL 0 OR NOT EXISTS "${image}")
    message(FATAL_ERROR "${program} render bunny from ${elsewhere} failed:\n${render_output}")
  endif()
endfunction()

expect_render("${CLI}" "${WORK_DIR}/build-tree.png")

# The installed CLI (its own component: the executable, its plugins, share/obscura/scenes) reads
# the installed copy of the scene, marked so that the source tree's copy would fail the check.
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}"
                        --component Unspecified
                RESULT_VARIABLE code OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "cmake --install failed:\n${output}")
endif()
set(installed_bunny "${prefix}/share/obscura/scenes/bunny.json")
file(READ "${installed_bunny}" text)
string(REPLACE "\"name\": \"bunny\"" "\"name\": \"installed-bunny\"" text "${text}")
file(WRITE "${installed_bunny}" "${text}")
run_from_elsewhere(info "${prefix}/bin/obscura" info bunny)
if(NOT info_code EQUAL 0 OR NOT info_output MATCHES "scene +installed-bunny")
  message(FATAL_ERROR "the installed CLI did not read its own copy of bunny.json:\n${info_output}")
endif()
expect_render("${prefix}/bin/obscura" "${WORK_DIR}/installed.png")

# No scenes where it is told to look: the error names the file it looked for.
set(ENV{OBSCURA_SCENES_DIR} "${no_scenes}")
run_from_elsewhere(missing "${CLI}" render bunny --width 32 --height 32 --spp 1
                   -o "${WORK_DIR}/missing.png")
string(FIND "${missing_output}" "${no_scenes}/bunny.json" named)
if(missing_code EQUAL 0 OR named EQUAL -1)
  message(FATAL_ERROR "a missing scenes folder is not reported with where it looked:\n"
                      "${missing_output}")
endif()
