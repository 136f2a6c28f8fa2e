# The step fuzzer for anyone's step (docs/conform.md, "Protocol, properties or fuzzer"), in this tree and in
# the installed package (circlesConfig.cmake includes this file).
#
# circles_add_step_fuzzer(NAME SOURCES...): a libFuzzer program NAME from SOURCES, which define circles_step of
# <circles/step.h> (C, C++, or an object of another language), linked with circles::step_harness: libFuzzer's
# entry points, the custom mutator, and the oracle that judges every step. SOURCES are compiled with
# -fsanitize=fuzzer,address,undefined: coverage-guided on the user's code, which AddressSanitizer and UBSan
# check too. Needs Clang (libFuzzer is Clang's) for C and C++, and CXX enabled in the project (the harness is
# C++). Run it as ./NAME [-max_total_time=S] [CORPUS_DIR].
#
# circles_link_step_fuzzer(TARGET): the link of any step fuzzer: libFuzzer's main and the custom mutator,
# which libFuzzer refers to weakly and a static library would otherwise leave out.
function(circles_link_step_fuzzer target)
  target_link_options(${target} PRIVATE -fsanitize=fuzzer -Wl,--undefined=LLVMFuzzerCustomMutator
                                        -Wl,--undefined=LLVMFuzzerCustomCrossOver)
  set_target_properties(${target} PROPERTIES LINKER_LANGUAGE CXX)
endfunction()

function(circles_add_step_fuzzer name)
  if(NOT ARGN)
    message(FATAL_ERROR "circles_add_step_fuzzer(${name}): no sources; give the files that define circles_step")
  endif()
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} PRIVATE circles::step_harness)
  target_compile_options(${name} PRIVATE -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -g)
  target_link_options(${name} PRIVATE -fsanitize=address,undefined)
  circles_link_step_fuzzer(${name})
endfunction()
