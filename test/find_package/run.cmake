# Checks that the installed package works for a user: run with `cmake -P`.
#   cmake -DMLS_BUILD_DIR=<top build dir> -DMLS_CONSUMER_SOURCE_DIR=<this folder>
#         -DMLS_WORK_DIR=<scratch dir> [-DCMAKE_CXX_COMPILER=...] [-DMLS_CXX_COMPILER_LAUNCHER=ccache]
#         -P run.cmake
# 1. installs the package from the top build dir into <scratch>/prefix (emptied first);
# 2. configures the consumer in <scratch>/build with CMAKE_PREFIX_PATH=<scratch>/prefix;
# 3. builds it and runs it. Any failure stops with an error, so the ctest test fails.
cmake_minimum_required(VERSION 3.16)

foreach(var MLS_BUILD_DIR MLS_CONSUMER_SOURCE_DIR MLS_WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run.cmake: ${var} is not set")
  endif()
endforeach()

set(prefix ${MLS_WORK_DIR}/prefix)
set(build ${MLS_WORK_DIR}/build)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "find_package test: ${what} failed (${rc})")
  endif()
  message(STATUS "find_package test: ${what}: ok")
endfunction()

file(REMOVE_RECURSE ${prefix})
run_step("install into ${prefix}" ${CMAKE_COMMAND} --install ${MLS_BUILD_DIR} --prefix ${prefix})
if(NOT EXISTS ${prefix}/include/CGAL/MLS_projection.h)
  message(FATAL_ERROR "find_package test: the headers were not installed in ${prefix}/include")
endif()

set(configure_args -S ${MLS_CONSUMER_SOURCE_DIR} -B ${build} -DCMAKE_BUILD_TYPE=Release
                   -DCMAKE_PREFIX_PATH=${prefix})
if(CMAKE_CXX_COMPILER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER})
endif()
if(MLS_CXX_COMPILER_LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${MLS_CXX_COMPILER_LAUNCHER})
endif()
run_step("configure the consumer" ${CMAKE_COMMAND} ${configure_args})
run_step("build the consumer" ${CMAKE_COMMAND} --build ${build})

find_program(consumer NAMES consumer PATHS ${build} NO_DEFAULT_PATH)
if(NOT consumer)
  message(FATAL_ERROR "find_package test: the consumer was not built in ${build}")
endif()
run_step("run the consumer" ${consumer})
