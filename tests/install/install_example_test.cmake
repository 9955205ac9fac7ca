# The installable library end to end (ctest: install.library_example): install this build into a fresh
# prefix, build examples/library against it alone with find_package(glint), then run the example
#  1. on its scene built in code, whose every pixel is known without glint: a matte floor of albedo
#     (0.2, 0.4, 0.6) under a sun of irradiance π straight above shows exactly its albedo;
#  2. on a scene file, whose PFM must be the same bytes as `glint render`'s.
# Run as: cmake -DBUILD_DIR=… -DSOURCE_DIR=… -DWORK_DIR=… -DGLINT_CLI=… -DCXX_COMPILER=… -DGENERATOR=…
#         [-DLINK_FLAGS=…]
#         -P install_example_test.cmake
cmake_minimum_required(VERSION 3.25)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "failed (${code}): ${ARGN}\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed include/glint/scene/scene.hpp include/glint/render/render.hpp lib/libglint.a bin/glint
        lib/cmake/glint/glintConfig.cmake lib/cmake/glint/glintConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "the install lacks ${installed}")
  endif()
endforeach()

# The example sees only the prefix: not the source tree, not this build. CMAKE_FIND_USE_PACKAGE_REGISTRY
# off, so that no registered build tree can stand in for the install.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/library -B ${WORK_DIR}/build -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}")
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
set(example ${WORK_DIR}/build/glint_library_example)

run(${example})
if(NOT output MATCHES "mean radiance: 0\\.200000 0\\.400000 0\\.600000\n")
  message(FATAL_ERROR "the floor of albedo (0.2, 0.4, 0.6) under a sun of irradiance pi should show its albedo:\n${output}")
endif()
message(STATUS "in-code scene: ${output}")

set(scene ${SOURCE_DIR}/examples/spheres.yaml)
set(edits render.width=96 render.height=54 render.samples=4 render.seed=7)
run(${example} ${scene} ${WORK_DIR}/example.pfm ${edits})
set(cli_sets)
foreach(edit ${edits})
  list(APPEND cli_sets --set ${edit})
endforeach()
run(${GLINT_CLI} render ${scene} -q -o ${WORK_DIR}/cli.pfm ${cli_sets})
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/example.pfm ${WORK_DIR}/cli.pfm
                RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "the example's PFM differs from glint render's: ${WORK_DIR}/example.pfm ${WORK_DIR}/cli.pfm")
endif()
message(STATUS "examples/spheres.yaml: the example's PFM is glint render's, byte for byte")
