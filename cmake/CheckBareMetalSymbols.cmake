# cmake -DNM=<nm> -DARCHIVES="a;b" -P CheckBareMetalSymbols.cmake
#
# Proves that the freestanding libraries need no hosted C or C++ library: every symbol they leave
# undefined is defined by one of them, is the compiler runtime's (libgcc's __aeabi_* and bit-count
# helpers), or is one of the four memory functions GCC may emit even under -ffreestanding.
cmake_minimum_required(VERSION 3.25)

# symbols_of(<archive> <--defined-only|--undefined-only> <out>): the symbol names nm lists.
function(symbols_of archive which out)
  execute_process(COMMAND ${NM} ${which} --demangle ${archive}
                  OUTPUT_VARIABLE listing RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${NM} failed on ${archive}")
  endif()
  # Lines are "<address> <type> <name>" (defined) or "<spaces> U <name>" (undefined).
  string(REPLACE ";" "\\;" listing "${listing}")
  string(REPLACE "\n" ";" lines "${listing}")
  set(names "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^[0-9a-fA-F ]* [A-Za-z] (.+)$")
      list(APPEND names "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  set(${out} "${names}" PARENT_SCOPE)
endfunction()

# Every symbol the libraries define themselves (one library may call another: the nanopb runtime,
# the generated message descriptors).
set(defined "")
foreach(archive IN LISTS ARCHIVES)
  symbols_of(${archive} --defined-only names)
  list(APPEND defined ${names})
endforeach()

set(undefined "")
foreach(archive IN LISTS ARCHIVES)
  symbols_of(${archive} --undefined-only names)
  foreach(symbol IN LISTS names)
    if(symbol IN_LIST defined)
      continue()
    endif()
    # libgcc: the ARM EABI helpers and the bit-count helpers std::countr_zero and std::popcount
    # may become on a core without those instructions.
    if(NOT symbol MATCHES "^(__aeabi_|__gnu_thumb1_|__(ctz|clz|popcount|ffs|parity)[sdt]i2$|memcpy$|memmove$|memset$|memcmp$)")
      string(APPEND undefined "  ${archive}: ${symbol}\n")
    endif()
  endforeach()
endforeach()

if(undefined)
  message(FATAL_ERROR "freestanding libraries call into a hosted library:\n${undefined}")
endif()
message(STATUS "bare-metal symbol check: only compiler-runtime and memory functions undefined")
