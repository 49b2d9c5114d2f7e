# Cross-compile for 64-bit ARM Linux (Debian's g++-aarch64-linux-gnu). Tests run through
# qemu-aarch64 with the target's sysroot, so a plain `ctest` exercises the target instruction set.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

set(SAFECELL_AARCH64_SYSROOT /usr/aarch64-linux-gnu)
find_program(SAFECELL_QEMU_AARCH64 qemu-aarch64 REQUIRED)
set(CMAKE_CROSSCOMPILING_EMULATOR ${SAFECELL_QEMU_AARCH64} -L ${SAFECELL_AARCH64_SYSROOT})

set(CMAKE_FIND_ROOT_PATH ${SAFECELL_AARCH64_SYSROOT})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
