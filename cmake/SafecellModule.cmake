# Helpers that give every module the same shape.

# safecell_check_headers_alone(<target> <include-dir> [extra flag targets...])
# Compiles every public header of <target> in a translation unit of its own (twice, to test the
# include guard), so a header that leans on an include it does not make fails the build.
function(safecell_check_headers_alone target include_dir)
  file(GLOB_RECURSE headers RELATIVE ${include_dir} CONFIGURE_DEPENDS ${include_dir}/*.hpp)
  set(sources)
  foreach(header IN LISTS headers)
    string(MAKE_C_IDENTIFIER ${header} stem)
    set(source ${CMAKE_CURRENT_BINARY_DIR}/header_alone/${stem}.cpp)
    file(CONFIGURE OUTPUT ${source} CONTENT "#include \"${header}\"\n#include \"${header}\"\n")
    list(APPEND sources ${source})
  endforeach()
  if(sources)
    add_library(${target}_headers_alone OBJECT ${sources})
    target_link_libraries(${target}_headers_alone PRIVATE ${target} ${ARGN} safecell::warnings)
  endif()
endfunction()

# safecell_add_freestanding_library(<name> SOURCES ...)
# A static library of shared/ or controller/: public headers in include/, freestanding flags.
function(safecell_add_freestanding_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_library(safecell_${name} STATIC ${ARG_SOURCES})
  add_library(safecell::${name} ALIAS safecell_${name})
  target_include_directories(safecell_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  # The flags stay PRIVATE: hosted users (the coprocessor, the tests) include these headers
  # with their own flags, and the header check below compiles them freestanding.
  target_link_libraries(safecell_${name}
    PUBLIC ${ARG_DEPENDS}
    PRIVATE safecell::freestanding safecell::warnings)
  safecell_check_headers_alone(safecell_${name} ${CMAKE_CURRENT_SOURCE_DIR}/include safecell::freestanding)
  set_property(GLOBAL APPEND PROPERTY SAFECELL_FREESTANDING_LIBRARIES safecell_${name})
endfunction()
