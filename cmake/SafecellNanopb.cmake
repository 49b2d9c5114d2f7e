# nanopb for the controller side: the generator is Debian's nanopb package (a host tool, used by
# every build including the cross builds); the runtime sources come from Debian's source package
# of the same version, unpacked by .ci/fetch-nanopb-source into a cache outside the repository.
#
# safecell_nanopb_generate(<target> PROTO_DIR <dir> PROTOS <file>...)
#   Generates <name>.nanopb.c/.nanopb.h for each .proto (not .pb.*: libprotobuf's C++ headers have
#   those names, and the interoperation tests include both) (relative to PROTO_DIR, which also holds the
#   .options files) and adds a static library <target> of them with the runtime linked in.

find_program(SAFECELL_NANOPB_GENERATOR nanopb_generator.py REQUIRED)
execute_process(COMMAND ${SAFECELL_NANOPB_GENERATOR} --version
                OUTPUT_VARIABLE nanopb_version_output OUTPUT_STRIP_TRAILING_WHITESPACE)
string(REGEX MATCH "[0-9]+\\.[0-9]+\\.[0-9]+" SAFECELL_NANOPB_VERSION "${nanopb_version_output}")
if(NOT SAFECELL_NANOPB_VERSION)
  message(FATAL_ERROR "could not read the nanopb generator's version from '${nanopb_version_output}'")
endif()

if(DEFINED ENV{SAFECELL_CACHE})
  set(nanopb_cache $ENV{SAFECELL_CACHE})
elseif(DEFINED ENV{XDG_CACHE_HOME})
  set(nanopb_cache $ENV{XDG_CACHE_HOME}/safecell)
else()
  set(nanopb_cache $ENV{HOME}/.cache/safecell)
endif()
set(SAFECELL_NANOPB_SOURCE_DIR ${nanopb_cache}/nanopb-${SAFECELL_NANOPB_VERSION}
    CACHE PATH "nanopb runtime sources of the generator's version")
if(NOT EXISTS ${SAFECELL_NANOPB_SOURCE_DIR}/pb_decode.c)
  message(FATAL_ERROR
    "the nanopb ${SAFECELL_NANOPB_VERSION} runtime sources are not in ${SAFECELL_NANOPB_SOURCE_DIR}; "
    "run `bash .ci/fetch-nanopb-source` (part of .ci/install-deps)")
endif()

# The runtime: static allocation only (no PB_ENABLE_MALLOC), as the controller's core requires.
add_library(safecell_nanopb_runtime STATIC
  ${SAFECELL_NANOPB_SOURCE_DIR}/pb_common.c
  ${SAFECELL_NANOPB_SOURCE_DIR}/pb_encode.c
  ${SAFECELL_NANOPB_SOURCE_DIR}/pb_decode.c)
add_library(safecell::nanopb_runtime ALIAS safecell_nanopb_runtime)
target_include_directories(safecell_nanopb_runtime SYSTEM PUBLIC
  $<BUILD_INTERFACE:${SAFECELL_NANOPB_SOURCE_DIR}>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/safecell/nanopb>)
safecell_install(safecell_nanopb_runtime)
install(FILES ${SAFECELL_NANOPB_SOURCE_DIR}/pb.h ${SAFECELL_NANOPB_SOURCE_DIR}/pb_common.h
              ${SAFECELL_NANOPB_SOURCE_DIR}/pb_encode.h ${SAFECELL_NANOPB_SOURCE_DIR}/pb_decode.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/safecell/nanopb)
if(SAFECELL_BARE_METAL)
  # The call graph too: the controller image's stack report walks through the decoder.
  target_compile_options(safecell_nanopb_runtime PRIVATE -ffreestanding -fcallgraph-info=su
                         -ffunction-sections -fdata-sections)
endif()
set_property(GLOBAL APPEND PROPERTY SAFECELL_FREESTANDING_LIBRARIES safecell_nanopb_runtime)

function(safecell_nanopb_generate target)
  cmake_parse_arguments(ARG "" "PROTO_DIR" "PROTOS" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/nanopb)
  set(sources)
  foreach(proto IN LISTS ARG_PROTOS)
    string(REGEX REPLACE "\\.proto$" "" stem ${proto})
    set(outputs ${out_dir}/${stem}.nanopb.c ${out_dir}/${stem}.nanopb.h)
    set(options ${ARG_PROTO_DIR}/${stem}.options)
    set(depends ${ARG_PROTO_DIR}/${proto})
    if(EXISTS ${options})
      list(APPEND depends ${options})
    endif()
    add_custom_command(
      OUTPUT ${outputs}
      COMMAND ${SAFECELL_NANOPB_GENERATOR} -q -e .nanopb -I ${ARG_PROTO_DIR} -D ${out_dir} ${proto}
      WORKING_DIRECTORY ${ARG_PROTO_DIR}
      DEPENDS ${depends}
      COMMENT "nanopb: ${proto}"
      VERBATIM)
    list(APPEND sources ${out_dir}/${stem}.nanopb.c)
  endforeach()
  add_library(${target} STATIC ${sources})
  target_include_directories(${target} SYSTEM PUBLIC $<BUILD_INTERFACE:${out_dir}>
                             $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC safecell::nanopb_runtime)
  safecell_install(${target})
  install(DIRECTORY ${out_dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
  if(SAFECELL_BARE_METAL)
    target_compile_options(${target} PRIVATE -ffreestanding -fcallgraph-info=su
                           -ffunction-sections -fdata-sections)
  endif()
  set_property(GLOBAL APPEND PROPERTY SAFECELL_FREESTANDING_LIBRARIES ${target})
endfunction()
