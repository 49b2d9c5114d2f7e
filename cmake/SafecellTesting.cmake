# GoogleTest for the tests, and safecell_add_test().
#
# Native builds use the system's GoogleTest. Cross builds compile it from Debian's source package
# (/usr/src/googletest) with the cross compiler, so no target-architecture packages are needed.
if(CMAKE_CROSSCOMPILING)
  set(SAFECELL_GOOGLETEST_SOURCE /usr/src/googletest/googletest CACHE PATH "GoogleTest sources")
  if(NOT EXISTS ${SAFECELL_GOOGLETEST_SOURCE}/CMakeLists.txt)
    message(FATAL_ERROR "GoogleTest sources not found at ${SAFECELL_GOOGLETEST_SOURCE}; "
                        "install Debian's googletest package (bash .ci/install-deps --cross)")
  endif()
  set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
  add_subdirectory(${SAFECELL_GOOGLETEST_SOURCE} ${CMAKE_BINARY_DIR}/googletest SYSTEM EXCLUDE_FROM_ALL)
  # GoogleTest 1.12 defines the GTest::gtest alias itself.
else()
  find_package(GTest REQUIRED)
endif()

# The tests CI runs again under AddressSanitizer + UBSan (.ci/asan, label "sanitized"): the code
# that reads what others write (files, images, the link's frames) and the controller side. The
# table builders, fusion and the closed loop run on trusted, generated data; under the sanitizers
# they took most of an hour of CI, and the one file reader among them (the LUT file) runs under the
# same sanitizers in the fuzz stage and in fuzz_corpus.
set(SAFECELL_SANITIZED_TESTS base cspace safety protocol protocol_interop fuzz_corpus controller
    controller_no_allocation controller_module files cell camera robot acquisition reference
    service link campaign)

# safecell_add_test(<name> SOURCES ... LIBRARIES ...)
# One test executable per module, run by ctest (through the emulator when cross-compiling).
function(safecell_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  add_executable(test_${name} ${ARG_SOURCES})
  target_link_libraries(test_${name} PRIVATE ${ARG_LIBRARIES} safecell::test_support GTest::gtest
                                             safecell::warnings)
  add_test(NAME ${name} COMMAND test_${name})
  if(name IN_LIST SAFECELL_SANITIZED_TESTS)
    set_tests_properties(${name} PROPERTIES LABELS sanitized)
    set_property(GLOBAL APPEND PROPERTY SAFECELL_SANITIZED_PROGRAMS test_${name})
  endif()
endfunction()
