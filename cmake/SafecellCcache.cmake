# Use ccache for every compile when it is installed; CI keeps its cache between runs. With the
# source tree as base directory (and no working directory in the hash), a fresh clone somewhere
# else hits the cache of the last one: ccache hashes paths under it as relative ones.
find_program(SAFECELL_CCACHE ccache)
if(SAFECELL_CCACHE)
  set(launcher ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${CMAKE_SOURCE_DIR} CCACHE_NOHASHDIR=1
      ${SAFECELL_CCACHE})
  set(CMAKE_CXX_COMPILER_LAUNCHER ${launcher})
  set(CMAKE_C_COMPILER_LAUNCHER ${launcher})
endif()
