# What the installed-package tests (consumer_test.cmake, consumer_shared_test.cmake) share: running a
# command, matching its output, and building and running both example consumers against a prefix.

# run(COMMAND...): runs it, fails the test with its output unless it exits 0; its stdout in `out`.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

# expect_in(TEXT EXPECTED...): fails unless every EXPECTED occurs in TEXT.
function(expect_in text)
  foreach(expected ${ARGN})
    string(FIND "${text}" "${expected}" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "output lacks '${expected}':\n${text}")
    endif()
  endforeach()
endfunction()

# Builds examples/consumer (component `coefficients`) and examples/consumer_sim (component `sim`) in
# WORK/build and WORK/build-sim against the package installed in PREFIX, runs them and checks:
#  1. c = omega'(pi/2) = 0.2298504217 and theta_c = 1.891589 (tests/unit/coefficients_paper_test.cpp,
#     regime tests);
#  2. the bond-centred dark breather at omega_b = 2.42 converges with E_b <= 1e-10 and K_x = 0.4734
#     (tests/unit/dark_breather_test.cpp), and a 20 T_b bright run stays within E_x < 0.05 with
#     energy drift < 1e-9 (exp1: 0.0245 over 200 T_b);
#  3. the coefficients-only consumer found none of the simulator's dependencies (Eigen, nlohmann-json,
#     fmt, HDF5) and, against shared libraries, no OpenMP: not in its CMake cache, not on its link
#     line, and not in the installed core target's interface (lrchainTargets*.cmake).
function(check_consumers source_dir prefix work)
  run(${CMAKE_COMMAND} -S ${source_dir}/examples/consumer -B ${work}/build
      -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
  check_coefficients_consumer(${prefix} ${work}/build)
  run(${CMAKE_COMMAND} --build ${work}/build)
  run(${work}/build/nls_coefficients)
  message(STATUS "consumer output:\n${out}")
  expect_in("${out}" "c = 0.2298504217" "focusing = yes" "focusing interval: (0.000000, 1.891589)")

  run(${CMAKE_COMMAND} -S ${source_dir}/examples/consumer_sim -B ${work}/build-sim
      -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
  run(${CMAKE_COMMAND} --build ${work}/build-sim)
  run(${work}/build-sim/breathers)
  message(STATUS "consumer_sim output:\n${out}")
  expect_in("${out}" "dark: converged = yes" "K_x = 0.473")
  string(REGEX MATCH "E_b = ([0-9.e+-]+)" _ "${out}")
  if(NOT CMAKE_MATCH_1 OR CMAKE_MATCH_1 GREATER 1e-10)
    message(FATAL_ERROR "dark breather E_b = '${CMAKE_MATCH_1}', expected <= 1e-10")
  endif()
  string(REGEX MATCH "max E_x = ([0-9.]+) .* drift = ([0-9.e+-]+)" _ "${out}")
  if(NOT CMAKE_MATCH_1 OR CMAKE_MATCH_1 GREATER 0.05 OR CMAKE_MATCH_2 GREATER 1e-9)
    message(FATAL_ERROR "bright run: max E_x = '${CMAKE_MATCH_1}' (expected < 0.05), drift = '${CMAKE_MATCH_2}' (expected < 1e-9)")
  endif()
endfunction()

# check_coefficients_consumer(PREFIX BUILD): 3. above, for the configured examples/consumer in BUILD.
function(check_coefficients_consumer prefix build)
  file(READ ${build}/CMakeCache.txt cache)
  set(forbidden Eigen3_DIR nlohmann_json_DIR fmt_DIR HDF5_)
  file(GLOB static_core ${prefix}/lib*/liblrchain.a)
  if(NOT static_core)  # a static archive's consumer links its OpenMP runtime; a shared library's does not
    list(APPEND forbidden OpenMP)
    file(GLOB core_exports ${prefix}/lib*/cmake/lrchain/lrchainTargets*.cmake)
    foreach(f ${core_exports})
      file(READ ${f} text)
      string(FIND "${text}" "OpenMP" pos)
      if(NOT pos EQUAL -1)
        message(FATAL_ERROR "${f}: the shared core library's exported interface names OpenMP")
      endif()
    endforeach()
    file(READ ${build}/CMakeFiles/nls_coefficients.dir/link.txt link_line)
    if(link_line MATCHES "gomp|fopenmp")
      message(FATAL_ERROR "the coefficients-only consumer links OpenMP against shared libraries: ${link_line}")
    endif()
  endif()
  foreach(name ${forbidden})
    string(FIND "${cache}" "${name}" pos)
    if(NOT pos EQUAL -1)
      message(FATAL_ERROR "find_package(lrchain COMPONENTS coefficients) looked for '${name}' (in ${build}/CMakeCache.txt)")
    endif()
  endforeach()
  message(STATUS "coefficients-only consumer: none of ${forbidden} found or named")
endfunction()
