# ctest install_consumer (top-level CMakeLists.txt): installs the build tree into a fresh prefix, builds the
# consumer project (this folder) against it with find_package(Conforma) and runs its two programs, then runs the
# installed executable once. Nothing of the source tree is used at run time: the programs need no data files, and
# the environment variables that point at run-time files are cleared.
# cmake -DCONFORMA_BUILD_DIR=<build> -DCONFORMA_CONSUMER_SOURCE=<this folder> -DCONFORMA_WORK_DIR=<scratch>
#       [-DCMAKE_BUILD_TYPE=Release] [-DCONFORMA_SANITIZE=<-fsanitize= list>] -P run_install_consumer.cmake
foreach(_v CONFORMA_BUILD_DIR CONFORMA_CONSUMER_SOURCE CONFORMA_WORK_DIR)
  if(NOT ${_v})
    message(FATAL_ERROR "run_install_consumer.cmake: -D${_v}=... missing")
  endif()
endforeach()
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release)
endif()
set(_prefix "${CONFORMA_WORK_DIR}/prefix")
set(_build "${CONFORMA_WORK_DIR}/build")
file(REMOVE_RECURSE "${CONFORMA_WORK_DIR}")
file(MAKE_DIRECTORY "${CONFORMA_WORK_DIR}")
foreach(_e CONFORMA_SHARE_DIR CONFORMA_DATA_DIR CONFORMA_PYTHON CMAKE_PREFIX_PATH)
  unset(ENV{${_e}})
endforeach()

function(run what)
  string(TIMESTAMP _t0 "%s")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  string(TIMESTAMP _t1 "%s")
  math(EXPR _dt "${_t1} - ${_t0}")
  if(NOT _rc EQUAL 0)
    message("${_out}")
    message(FATAL_ERROR "install_consumer: ${what} failed (${_rc}): ${ARGN}")
  endif()
  message(STATUS "${what}: ok (${_dt} s)")
  set(run_output "${_out}" PARENT_SCOPE)
endfunction()

run("install" ${CMAKE_COMMAND} --install "${CONFORMA_BUILD_DIR}" --prefix "${_prefix}" --config ${CMAKE_BUILD_TYPE})
# a sanitizer build's libraries need the sanitizer runtime in the consumer's programs as well
set(_sanitize "")
if(CONFORMA_SANITIZE)
  set(_sanitize "-DCMAKE_CXX_FLAGS=-fsanitize=${CONFORMA_SANITIZE}" "-DCMAKE_C_FLAGS=-fsanitize=${CONFORMA_SANITIZE}")
endif()
run("configure consumer" ${CMAKE_COMMAND} -S "${CONFORMA_CONSUMER_SOURCE}" -B "${_build}"
    -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} "-DCMAKE_PREFIX_PATH=${_prefix}" ${_sanitize})
run("build consumer" ${CMAKE_COMMAND} --build "${_build}" --config ${CMAKE_BUILD_TYPE} -j 2)
foreach(_p consumer_contact consumer_capi_minimal)
  run("run ${_p}" "${_build}/${_p}")
  message("${run_output}")
endforeach()

# The installed executable: runs, and its help names no folder of this machine (defaults resolve at run time)
run("installed conforma --help" "${_prefix}/bin/conforma" bench --help)
get_filename_component(_source "${CONFORMA_CONSUMER_SOURCE}/../.." ABSOLUTE)
string(REPLACE "${_prefix}/bin/conforma" "conforma" _help "${run_output}")  # the usage line names the program
foreach(_path "${_source}" "${CONFORMA_BUILD_DIR}")
  string(FIND "${_help}" "${_path}" _at)
  if(NOT _at EQUAL -1)
    message("${run_output}")
    message(FATAL_ERROR "install_consumer: 'conforma bench --help' prints the path ${_path}")
  endif()
endforeach()
