# cmake -DNM=<nm> -DARCHIVES="a;b" -P CheckBareMetalSymbols.cmake
#
# Proves that the freestanding libraries need no hosted C or C++ library: every symbol they leave
# undefined is defined by one of them, is the compiler runtime's (libgcc's __aeabi_* and bit-count
# helpers), or is one of the four memory functions GCC may emit even under -ffreestanding.
cmake_minimum_required(VERSION 3.25)

# Every symbol the libraries define themselves (one library may call another: the nanopb runtime,
# the generated message descriptors).
set(defined "")
foreach(archive IN LISTS ARCHIVES)
  execute_process(COMMAND ${NM} --defined-only --demangle ${archive}
                  OUTPUT_VARIABLE listing RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${NM} failed on ${archive}")
  endif()
  string(REGEX MATCHALL "[0-9a-f]+ [A-Za-z] [^\n]+" symbols "${listing}")
  foreach(entry IN LISTS symbols)
    string(REGEX REPLACE "^[0-9a-f]+ [A-Za-z] " "" symbol "${entry}")
    list(APPEND defined "${symbol}")
  endforeach()
endforeach()

set(undefined "")
foreach(archive IN LISTS ARCHIVES)
  execute_process(COMMAND ${NM} --undefined-only --demangle ${archive}
                  OUTPUT_VARIABLE listing RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${NM} failed on ${archive}")
  endif()
  string(REGEX MATCHALL "U [^\n]+" symbols "${listing}")
  foreach(entry IN LISTS symbols)
    string(SUBSTRING "${entry}" 2 -1 symbol)
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
