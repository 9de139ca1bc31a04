# Builds a YADE_PREFIX tree in the build directory: YADE's own files (those Debian's packages own)
# linked in, plus the freshly built plugin, so that `YADE_PREFIX=<tree> yade` loads this build
# without installing it and never a second, installed copy.
# Inputs: PREFIX, YADE_LIBDIR, PLUGIN.
file(RELATIVE_PATH _rel "/usr" "${YADE_LIBDIR}")
set(_dst "${PREFIX}/${_rel}")
file(REMOVE_RECURSE "${_dst}")
file(MAKE_DIRECTORY "${_dst}")
get_filename_component(_p "${PLUGIN}" NAME)
file(GLOB _entries "${YADE_LIBDIR}/*")
foreach(_e IN LISTS _entries)
  get_filename_component(_n "${_e}" NAME)
  if(_n STREQUAL _p)
    continue()  # the installed yade-meso package's copy: the build tree has its own
  endif()
  execute_process(COMMAND dpkg-query -S "${_e}" RESULT_VARIABLE _notOwned OUTPUT_QUIET ERROR_QUIET)
  if(_notOwned EQUAL 0)
    file(CREATE_LINK "${_e}" "${_dst}/${_n}" SYMBOLIC)
  endif()
endforeach()
file(CREATE_LINK "${PLUGIN}" "${_dst}/${_p}" SYMBOLIC)
