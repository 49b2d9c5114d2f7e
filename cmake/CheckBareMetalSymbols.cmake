# cmake -DNM=<nm> -DARCHIVES="a;b" -P CheckBareMetalSymbols.cmake
#
# Proves that the freestanding libraries need no hosted C or C++ library: every symbol they leave
# undefined is their own, the compiler runtime's (libgcc's __aeabi_* helpers), or one of the four
# memory functions GCC may emit even under -ffreestanding.
cmake_minimum_required(VERSION 3.25)

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
    if(NOT symbol MATCHES "^(safecell::|__aeabi_|__gnu_thumb1_|memcpy$|memmove$|memset$|memcmp$)")
      string(APPEND undefined "  ${archive}: ${symbol}\n")
    endif()
  endforeach()
endforeach()

if(undefined)
  message(FATAL_ERROR "freestanding libraries call into a hosted library:\n${undefined}")
endif()
message(STATUS "bare-metal symbol check: only compiler-runtime and memory functions undefined")
