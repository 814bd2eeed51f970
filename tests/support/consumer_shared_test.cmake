# The package built with shared libraries (-DBUILD_SHARED_LIBS=ON) as another project uses it.
# Configures a scratch build of the source tree in WORK_DIR/build with only what the consumers and
# the command-line tool need (no derivation, Python module, MPI, benchmarks or tests), builds it
# with JOBS jobs, installs it into WORK_DIR/prefix and deletes the build tree, then:
#  1. the prefix holds liblrchain.so and liblrchain_sim.so (no static archive); the installed
#     lrchain needs both, finds them in the prefix through the RUNPATH $ORIGIN/../lib, and computes
#     c = omega'(pi/2) = 0.22985042169 (tests/unit/coefficients_paper_test.cpp);
#  2. examples/consumer and examples/consumer_sim build and run against the prefix with the numbers
#     of consumer_test.cmake (consumer_checks.cmake);
#  3. the consumers need the shared libraries and the dynamic loader resolves them in the prefix;
#     no RUNPATH and no installed file names the deleted build tree.
include(${CMAKE_CURRENT_LIST_DIR}/consumer_checks.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
set(build ${WORK_DIR}/build)
set(prefix ${WORK_DIR}/prefix)
set(launcher)
if(CXX_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX}
    ${launcher} -DBUILD_SHARED_LIBS=ON -DLRCHAIN_BUILD_DERIVATION=OFF -DLRCHAIN_BUILD_PYTHON=OFF
    -DLRCHAIN_BUILD_TESTS=OFF -DLRCHAIN_BUILD_BENCH=OFF -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON)
string(TIMESTAMP start %s)
run(${CMAKE_COMMAND} --build ${build} -j ${JOBS})
string(TIMESTAMP end %s)
math(EXPR seconds "${end} - ${start}")
message(STATUS "shared build: ${seconds} s with ${JOBS} jobs")
run(${CMAKE_COMMAND} --install ${build} --prefix ${prefix})
file(REMOVE_RECURSE ${build})  # what follows must not need it

find_program(READELF readelf REQUIRED)
find_program(LDD ldd REQUIRED)
# dynamic_section(FILE): `needed` (DT_NEEDED names) and `runpath` (DT_RUNPATH, DT_RPATH) of FILE.
function(dynamic_section file)
  run(${READELF} -d ${file})
  string(REGEX MATCHALL "\\(NEEDED\\)[^[]*\\[([^]]*)\\]" lines "${out}")
  set(needed)
  foreach(line ${lines})
    string(REGEX REPLACE ".*\\[([^]]*)\\]" "\\1" name "${line}")
    list(APPEND needed ${name})
  endforeach()
  set(runpath)
  string(REGEX MATCHALL "\\((RUNPATH|RPATH)\\)[^[]*\\[([^]]*)\\]" lines "${out}")
  foreach(line ${lines})
    string(REGEX REPLACE ".*\\[([^]]*)\\]" "\\1" path "${line}")
    list(APPEND runpath ${path})
  endforeach()
  set(needed "${needed}" PARENT_SCOPE)
  set(runpath "${runpath}" PARENT_SCOPE)
endfunction()
# expect_linked(PROGRAM LIBRARY...): PROGRAM needs each lib<LIBRARY>.so.<major>, the dynamic loader
# resolves it in the prefix, and no RUNPATH entry names the build or source tree.
function(expect_linked program)
  dynamic_section(${program})
  # Entries in the prefix or relative to the program ($ORIGIN) are fine, even when the prefix lies
  # inside the source tree (a build directory inside the checkout); any other entry must name
  # neither the build nor the source tree.
  foreach(entry ${runpath})
    string(FIND "${entry}" "${prefix}" in_prefix)
    string(FIND "${entry}" "$ORIGIN" relative)
    if(in_prefix EQUAL 0 OR relative EQUAL 0)
      continue()
    endif()
    foreach(bad ${build} ${SOURCE_DIR})
      string(FIND "${entry}" "${bad}" pos)
      if(NOT pos EQUAL -1)
        message(FATAL_ERROR "${program}: RUNPATH '${runpath}' names ${bad}")
      endif()
    endforeach()
  endforeach()
  run(${LDD} ${program})
  set(resolved "${out}")
  foreach(library ${ARGN})
    if(NOT "${needed}" MATCHES "lib${library}\\.so\\.[0-9]")
      message(FATAL_ERROR "${program} does not need lib${library}.so (NEEDED: ${needed})")
    endif()
    string(REGEX MATCH "lib${library}\\.so\\.[0-9]+ => ([^ ]+)" _ "${resolved}")
    set(found "${CMAKE_MATCH_1}")
    if(found)
      file(REAL_PATH "${found}" found)  # $ORIGIN/../lib/... as the loader prints it
    endif()
    file(REAL_PATH "${prefix}/lib/lib${library}.so.${VERSION_MAJOR}" expected)
    if(NOT found STREQUAL expected)
      message(FATAL_ERROR "${program}: lib${library} resolves to '${CMAKE_MATCH_1}', not the prefix's:\n${resolved}")
    endif()
  endforeach()
  message(STATUS "${program}: RUNPATH ${runpath}")
  set(runpath "${runpath}" PARENT_SCOPE)
endfunction()

# 1. the installed libraries and program
foreach(library lrchain lrchain_sim)
  if(NOT EXISTS ${prefix}/lib/lib${library}.so.${VERSION_MAJOR} OR EXISTS ${prefix}/lib/lib${library}.a)
    message(FATAL_ERROR "the prefix lacks lib${library}.so.${VERSION_MAJOR} or holds a static lib${library}.a")
  endif()
endforeach()
expect_linked(${prefix}/bin/lrchain lrchain lrchain_sim)
if(NOT runpath STREQUAL "$ORIGIN/../lib")
  message(FATAL_ERROR "the installed lrchain has the RUNPATH '${runpath}', expected '$ORIGIN/../lib'")
endif()
expect_linked(${prefix}/lib/liblrchain_sim.so.${VERSION_MAJOR} lrchain)
run(${prefix}/bin/lrchain coeffs --branch optical --theta pi/2)
expect_in("${out}" "0.22985042169")

# 2. the consumers against the shared package
check_consumers(${SOURCE_DIR} ${prefix} ${WORK_DIR})

# 3. how they are linked, and no installed file holding the build tree's path
expect_linked(${WORK_DIR}/build/nls_coefficients lrchain)
expect_linked(${WORK_DIR}/build-sim/breathers lrchain_sim)
file(GLOB_RECURSE installed ${prefix}/bin/* ${prefix}/lib/*)
foreach(f ${installed})
  file(STRINGS ${f} strings REGEX "${build}")
  if(strings)
    message(FATAL_ERROR "${f} holds the build tree's path: ${strings}")
  endif()
endforeach()
