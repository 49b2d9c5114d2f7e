# Cross-compile for 64-bit ARM Linux (Debian's g++-aarch64-linux-gnu). Tests run through
# qemu-aarch64 with the target's sysroot, so a plain `ctest` exercises the target instruction set.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

set(SAFECELL_AARCH64_SYSROOT /usr/aarch64-linux-gnu)
find_program(SAFECELL_QEMU_AARCH64 qemu-aarch64 REQUIRED)
set(CMAKE_CROSSCOMPILING_EMULATOR ${SAFECELL_QEMU_AARCH64} -L ${SAFECELL_AARCH64_SYSROOT})

# Debian's arm64 yaml-cpp and CLI11, unpacked by .ci/fetch-aarch64-packages (part of
# .ci/install-deps --cross): with them the build makes the controller program too.
if(DEFINED ENV{SAFECELL_CACHE})
  set(SAFECELL_AARCH64_PACKAGES $ENV{SAFECELL_CACHE}/aarch64-root)
elseif(DEFINED ENV{XDG_CACHE_HOME})
  set(SAFECELL_AARCH64_PACKAGES $ENV{XDG_CACHE_HOME}/safecell/aarch64-root)
else()
  set(SAFECELL_AARCH64_PACKAGES $ENV{HOME}/.cache/safecell/aarch64-root)
endif()
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

set(CMAKE_FIND_ROOT_PATH ${SAFECELL_AARCH64_SYSROOT} ${SAFECELL_AARCH64_PACKAGES})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
