# Use ccache for every compile when it is installed; CI keeps its cache between runs. With the
# source tree as base directory (and no working directory in the hash), a fresh clone somewhere
# else hits the cache of the last one: ccache hashes paths under it as relative ones.
# Not in the bare-metal build: ccache does not keep GCC's call-graph files (-fcallgraph-info), which
# the controller image's stack report reads, and that build is small.
find_program(SAFECELL_CCACHE ccache)
if(SAFECELL_CCACHE AND NOT SAFECELL_BARE_METAL)
  set(launcher ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${CMAKE_SOURCE_DIR} CCACHE_NOHASHDIR=1
      ${SAFECELL_CCACHE})
  set(CMAKE_CXX_COMPILER_LAUNCHER ${launcher})
  set(CMAKE_C_COMPILER_LAUNCHER ${launcher})
endif()
