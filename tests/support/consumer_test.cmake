# The installed package as another project uses it. Installs the built project into
# WORK_DIR/prefix, then:
#  1. examples/consumer (component `coefficients` only): c = omega'(pi/2) = 0.2298504217 and
#     theta_c = 1.891589 (tests/unit/coefficients_paper_test.cpp, regime tests);
#  2. examples/consumer_sim (component `sim`): the bond-centred dark breather at omega_b = 2.42
#     converges with E_b <= 1e-10 and K_x = 0.4734 (tests/unit/dark_breather_test.cpp), and a
#     20 T_b bright run stays within E_x < 0.05 with energy drift < 1e-9 (exp1: 0.0245 over 200 T_b);
#  3. every installed header compiles on its own (the public headers include no private one);
#  4. the exported targets name no absolute include path, and the installed lrchain binary holds
#     no path of the source or build tree;
#  5. without HDF5 (no pkg-config), find_package(lrchain COMPONENTS jobs) (a static archive, which
#     writes the HDF5 result files) fails at find_package with a message naming HDF5, not later
#     when CMake generates the build.
include(${CMAKE_CURRENT_LIST_DIR}/consumer_checks.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# 1 and 2: examples/consumer and examples/consumer_sim (consumer_checks.cmake)
check_consumers(${SOURCE_DIR} ${prefix} ${WORK_DIR})

# 3. every installed header on its own
file(GLOB_RECURSE headers RELATIVE ${prefix}/include ${prefix}/include/lrchain/*)
set(sources)
set(index 0)
foreach(h ${headers})
  math(EXPR index "${index} + 1")
  file(WRITE ${WORK_DIR}/headers/h${index}.cpp "#include \"${h}\"\n")
  list(APPEND sources h${index}.cpp)
endforeach()
list(LENGTH headers count)
message(STATUS "${count} installed headers")
file(WRITE ${WORK_DIR}/headers/CMakeLists.txt "cmake_minimum_required(VERSION 3.20)
project(lrchain_headers LANGUAGES CXX)
find_package(lrchain REQUIRED)
add_library(each_header OBJECT ${sources})
target_compile_features(each_header PRIVATE cxx_std_20)
target_link_libraries(each_header PRIVATE lrchain::lrchain lrchain::sim lrchain::jobs)
")
run(${CMAKE_COMMAND} -S ${WORK_DIR}/headers -B ${WORK_DIR}/headers/build -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/headers/build -j 2)

# 4. no absolute include paths in the exported targets, no build path in the binary
file(GLOB exports ${prefix}/lib*/cmake/lrchain/lrchain*Targets*.cmake)
foreach(f ${exports})
  file(READ ${f} text)
  foreach(bad /usr/include ${SOURCE_DIR} ${BUILD_DIR})
    string(FIND "${text}" "${bad}" pos)
    if(NOT pos EQUAL -1)
      message(FATAL_ERROR "${f} names the absolute path ${bad}")
    endif()
  endforeach()
endforeach()
file(STRINGS ${prefix}/bin/lrchain strings REGEX "${SOURCE_DIR}")
if(strings)
  message(FATAL_ERROR "the installed lrchain holds the source tree's path: ${strings}")
endif()

# 5. the jobs component without HDF5
file(WRITE ${WORK_DIR}/jobs-no-hdf5/CMakeLists.txt "cmake_minimum_required(VERSION 3.20)
project(lrchain_jobs_no_hdf5 LANGUAGES CXX)
find_package(lrchain REQUIRED COMPONENTS jobs)
")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK_DIR}/jobs-no-hdf5 -B ${WORK_DIR}/build-no-hdf5
                        -DCMAKE_PREFIX_PATH=${prefix} -DPKG_CONFIG_EXECUTABLE=${WORK_DIR}/no-such-pkg-config
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "find_package(lrchain COMPONENTS jobs) succeeded without pkg-config (no HDF5):\n${out}\n${err}")
endif()
string(REGEX REPLACE "[ \n]+" " " err_one_line "${err}")  # CMake wraps the reason it prints
expect_in("${err_one_line}" "needs HDF5's C library, which pkg-config did not find")
string(FIND "${err}" "was not found" pos)  # "Target ... links to PkgConfig::HDF5 but the target was not found"
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "a missing HDF5 surfaced at generation, not at find_package:\n${err}")
endif()
