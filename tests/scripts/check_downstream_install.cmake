# Proves that an installed tolip can be consumed with find_package(tolip) (cmake -P script).
#
#   cmake -DBUILD_DIR=<main build> -DDOWNSTREAM_SOURCE_DIR=<tests/downstream> -DWORK_DIR=<scratch>
#         [-DCONFIG=Release] [-DGENERATOR=...] [-DCXX_COMPILER=...]
#         -P check_downstream_install.cmake
#
# 1. cmake --install BUILD_DIR into WORK_DIR/prefix;
# 2. configure and build tests/downstream against it (CMAKE_PREFIX_PATH = the prefix);
# 3. run the downstream program, which must print kOk.
cmake_minimum_required(VERSION 3.20)

foreach(var BUILD_DIR DOWNSTREAM_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "check_downstream_install.cmake: -D${var}=... is required")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(downstream_build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(config_args "")
if(DEFINED CONFIG AND NOT "${CONFIG}" STREQUAL "")
  set(config_args --config "${CONFIG}")
endif()
run_step("install into ${prefix}"
  "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}" ${config_args})

set(configure_args -S "${DOWNSTREAM_SOURCE_DIR}" -B "${downstream_build}"
  "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release)
if(DEFINED GENERATOR AND NOT "${GENERATOR}" STREQUAL "")
  list(APPEND configure_args -G "${GENERATOR}")
endif()
if(DEFINED CXX_COMPILER AND NOT "${CXX_COMPILER}" STREQUAL "")
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
run_step("configure downstream project" "${CMAKE_COMMAND}" ${configure_args})
run_step("build downstream project" "${CMAKE_COMMAND}" --build "${downstream_build}" --config Release)

# Single-config generators put the program at the top of the build tree; multi-config ones under
# the configuration's folder.
set(program "")
foreach(candidate "${downstream_build}/downstream" "${downstream_build}/Release/downstream")
  if(EXISTS "${candidate}")
    set(program "${candidate}")
    break()
  endif()
endforeach()
if(program STREQUAL "")
  message(FATAL_ERROR "downstream program not found under ${downstream_build}")
endif()
run_step("run downstream program" "${program}")
string(STRIP "${step_output}" printed)
if(NOT printed STREQUAL "kOk")
  message(FATAL_ERROR "downstream program printed '${printed}', expected 'kOk'")
endif()
message(STATUS "find_package(tolip) works downstream: ${program} printed ${printed}")
