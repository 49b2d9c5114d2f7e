# Compiler flags as INTERFACE targets: a target opts in by linking them.

# safecell::warnings - every project target; warnings are errors.
add_library(safecell_warnings INTERFACE)
add_library(safecell::warnings ALIAS safecell_warnings)
target_compile_options(safecell_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast
  -Wnon-virtual-dtor -Woverloaded-virtual -Wcast-align -Wdouble-promotion
  -Werror)

# safecell::freestanding - shared/ and controller/: no exceptions, no RTTI, and no fused
# multiply-add contraction, so x86-64, aarch64 and Cortex-M compute the same grid bit for bit
# (the geometry fingerprint and the cell counts must agree on both ends of the link).
add_library(safecell_freestanding INTERFACE)
add_library(safecell::freestanding ALIAS safecell_freestanding)
target_compile_options(safecell_freestanding INTERFACE -fno-exceptions -fno-rtti -ffp-contract=off)
if(SAFECELL_BARE_METAL)
  # The call graph with each function's frame (.ci files) gives the controller image's stack depth;
  # sections per function let the linker drop what the image does not call.
  target_compile_options(safecell_freestanding INTERFACE -ffreestanding -fcallgraph-info=su
                         -ffunction-sections -fdata-sections)
endif()
