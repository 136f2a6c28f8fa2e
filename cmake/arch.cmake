# The engines' instruction set: circles::arch, an interface library that circles::impl and the benchmarks'
# baselines link (the yardsticks get the engines' level, or the comparison would favour the engines).
#
# CIRCLES_ARCH is a -march level, or one of two words:
#   auto      (the default) x86-64-v3 where the building machine runs it, else the compiler's default, as
#             GROMACS picks its SIMD level at configure time. The binary then runs on machines of that level.
#   portable  the compiler's default (baseline x86-64 with Debian's GCC): a binary for any x86-64 machine.
# x86-64-v3 (AVX2, FMA, BMI2) lets GCC vectorize the correctly rounded update and the broad phase's loops;
# -ffp-contract=off (circles::numeric) keeps FMA out of our arithmetic, so every level gives the same bits,
# which the golden tests hold for the level chosen and for baseline x86-64 (tests/CMakeLists.txt). auto stops
# at v3: the highest level the golden tests and the benchmarks cover.
#
# Sets CIRCLES_ARCH_LEVEL (the -march level used, empty for the compiler's default) and prints the choice.
set(CIRCLES_ARCH auto CACHE STRING "-march level for the engines, or auto (this machine's, up to x86-64-v3) or portable")

# circles_host_runs_x86_64_v3(VAR): TRUE where the compiler emits x86-64-v3 code and this machine runs it, as
# cmake/x86_64_v3.cpp reads the CPUID bits of the level (Linux's /proc/cpuinfo is no substitute: some
# machines that run LZCNT do not list its flag, abm, there).
function(circles_host_runs_x86_64_v3 var)
  set(${var} FALSE PARENT_SCOPE)
  if(CMAKE_CROSSCOMPILING OR NOT CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
    return()
  endif()
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag(-march=x86-64-v3 circles_compiler_has_x86_64_v3)
  if(NOT circles_compiler_has_x86_64_v3)
    return()
  endif()
  try_run(runs compiles ${CMAKE_BINARY_DIR}/arch ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/x86_64_v3.cpp)
  if(compiles AND runs EQUAL 0)
    set(${var} TRUE PARENT_SCOPE)
  endif()
endfunction()

circles_host_runs_x86_64_v3(CIRCLES_HOST_RUNS_X86_64_V3)
if(CIRCLES_ARCH STREQUAL "auto")
  if(CIRCLES_HOST_RUNS_X86_64_V3)
    set(CIRCLES_ARCH_LEVEL x86-64-v3)
    set(circles_arch_why "auto: this machine runs it; -DCIRCLES_ARCH=portable for a binary that runs on any x86-64")
  else()
    set(CIRCLES_ARCH_LEVEL "")
    set(circles_arch_why "auto: this machine does not run x86-64-v3")
  endif()
elseif(CIRCLES_ARCH STREQUAL "portable" OR CIRCLES_ARCH STREQUAL "")
  set(CIRCLES_ARCH_LEVEL "")
  set(circles_arch_why "CIRCLES_ARCH=portable")
else()
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag(-march=${CIRCLES_ARCH} circles_compiler_has_arch_${CIRCLES_ARCH})
  if(NOT circles_compiler_has_arch_${CIRCLES_ARCH})
    message(FATAL_ERROR "CIRCLES_ARCH=${CIRCLES_ARCH}: ${CMAKE_CXX_COMPILER} does not accept -march=${CIRCLES_ARCH}; "
                        "use auto, portable or a level it knows, such as x86-64-v3")
  endif()
  set(CIRCLES_ARCH_LEVEL ${CIRCLES_ARCH})
  set(circles_arch_why "CIRCLES_ARCH=${CIRCLES_ARCH}")
endif()
# Kept in the cache for scripts/benchmarks, which names the level of the build it measures.
set(CIRCLES_ARCH_LEVEL "${CIRCLES_ARCH_LEVEL}" CACHE INTERNAL "the -march level the engines are built with")
if(CIRCLES_ARCH_LEVEL)
  message(STATUS "circles: engines built with -march=${CIRCLES_ARCH_LEVEL} (${circles_arch_why})")
else()
  message(STATUS "circles: engines built for the compiler's default instruction set (${circles_arch_why})")
endif()

add_library(circles_arch INTERFACE)
if(CIRCLES_ARCH_LEVEL)
  target_compile_options(circles_arch INTERFACE -march=${CIRCLES_ARCH_LEVEL})
endif()
add_library(circles::arch ALIAS circles_arch)
