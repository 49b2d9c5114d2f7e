# Use ccache for every compile when it is installed; CI keeps its cache between runs.
find_program(SAFECELL_CCACHE ccache)
if(SAFECELL_CCACHE)
  set(CMAKE_CXX_COMPILER_LAUNCHER ${SAFECELL_CCACHE})
  set(CMAKE_C_COMPILER_LAUNCHER ${SAFECELL_CCACHE})
endif()
