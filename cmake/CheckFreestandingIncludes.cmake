# cmake -DSOURCE_DIR=<repo> -P CheckFreestandingIncludes.cmake
#
# Fails when code in shared/, the controller's side of protocol/ (safety_layer/, nanopb/) or
# controller/ (outside controller/host/) includes anything but the
# freestanding C++ headers below, safecell's own headers, or nanopb's; or allocates from the heap.
# DESIGN.md §2 names the banned headers; this is the stricter allow-list form of that rule.
cmake_minimum_required(VERSION 3.25)

set(allowed_system_headers
  cstddef cstdint climits cfloat cstdarg limits type_traits bit new initializer_list
  concepts compare atomic version source_location)

file(GLOB_RECURSE sources
  ${SOURCE_DIR}/shared/*.hpp ${SOURCE_DIR}/shared/*.cpp ${SOURCE_DIR}/shared/*.h
  ${SOURCE_DIR}/protocol/safety_layer/*.hpp ${SOURCE_DIR}/protocol/safety_layer/*.cpp
  ${SOURCE_DIR}/protocol/nanopb/*.hpp ${SOURCE_DIR}/protocol/nanopb/*.cpp
  ${SOURCE_DIR}/controller/*.hpp ${SOURCE_DIR}/controller/*.cpp ${SOURCE_DIR}/controller/*.h)
list(FILTER sources EXCLUDE REGEX "/controller/host/")

set(violations "")
foreach(source IN LISTS sources)
  file(STRINGS ${source} lines)
  file(RELATIVE_PATH shown ${SOURCE_DIR} ${source})
  set(line_number 0)
  foreach(line IN LISTS lines)
    math(EXPR line_number "${line_number} + 1")
    if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*<([^>]+)>")
      if(NOT CMAKE_MATCH_1 IN_LIST allowed_system_headers)
        string(APPEND violations "${shown}:${line_number}: <${CMAKE_MATCH_1}> is not a freestanding header\n")
      endif()
    elseif(line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\"")
      if(NOT CMAKE_MATCH_1 MATCHES "^(safecell/|pb\\.h$|pb_encode\\.h$|pb_decode\\.h$|pb_common\\.h$)")
        string(APPEND violations "${shown}:${line_number}: \"${CMAKE_MATCH_1}\" is neither safecell's nor nanopb's\n")
      endif()
    endif()
    # Heap use: a non-placement new-expression, or the C allocator.
    string(REGEX REPLACE "//.*$" "" code "${line}")
    if(code MATCHES "(^|[^A-Za-z0-9_])new[ \t]+[A-Za-z_:]" OR code MATCHES "(^|[^A-Za-z0-9_.])(malloc|calloc|realloc|free)[ \t]*\\(")
      string(APPEND violations "${shown}:${line_number}: heap allocation\n")
    endif()
  endforeach()
endforeach()

if(violations)
  message(FATAL_ERROR "shared/ and controller/ must stay freestanding:\n${violations}")
endif()
list(LENGTH sources checked)
message(STATUS "freestanding check: ${checked} files clean")
