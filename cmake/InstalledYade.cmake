# Finds Debian's installed YADE and derives what a plugin must be compiled with.
# Sets: YADE_LIBDIR, YADE_VERSION, YADE_FEATURES, YADE_REAL_BITS, YADE_COMPILE_DEFINITIONS,
#       YADE_PYTHON (the interpreter YADE runs on).

set(YADE_LIBDIR "" CACHE PATH "Directory of libyade.so (found automatically when empty)")
if(NOT YADE_LIBDIR)
  file(GLOB _candidates "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/yade*/libyade.so" "/usr/lib/yade*/libyade.so")
  list(LENGTH _candidates _n)
  if(_n EQUAL 0)
    message(FATAL_ERROR "YADE is not installed (no libyade.so under /usr/lib). Run: scripts/install-deps.sh")
  endif()
  list(GET _candidates 0 _lib)
  get_filename_component(_dir "${_lib}" DIRECTORY)
  set(YADE_LIBDIR "${_dir}" CACHE PATH "Directory of libyade.so" FORCE)
endif()
set(_config "${YADE_LIBDIR}/py/yade/config.py")
if(NOT EXISTS "${_config}")
  message(FATAL_ERROR "YADE's config.py not found at ${_config}")
endif()

find_program(YADE_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT YADE_PYTHON)
  message(FATAL_ERROR "/usr/bin/python3 (the interpreter of Debian's YADE) not found")
endif()

# Read the settings of config.py without importing yade (text only; its values are literals).
file(STRINGS "${_config}" _lines REGEX "^(features|version|highPrecisionBits|highPrecisionDecimalPlaces) *=")
foreach(_l IN LISTS _lines)
  if(_l MATCHES "^features=' *([^']*)'")
    string(REGEX REPLACE " +" ";" YADE_FEATURES "${CMAKE_MATCH_1}")
  elseif(_l MATCHES "^version='([^']*)'")
    set(YADE_VERSION "${CMAKE_MATCH_1}")
  elseif(_l MATCHES "^highPrecisionBits *= *([0-9]+)")
    set(YADE_REAL_BITS "${CMAKE_MATCH_1}")
  elseif(_l MATCHES "^highPrecisionDecimalPlaces *= *([0-9]+)")
    set(YADE_REAL_DEC "${CMAKE_MATCH_1}")
  endif()
endforeach()
foreach(_v YADE_VERSION YADE_REAL_BITS YADE_REAL_DEC)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "could not read ${_v} from ${_config}")
  endif()
endforeach()
list(REMOVE_DUPLICATES YADE_FEATURES)
if(NOT YADE_REAL_BITS EQUAL 64)
  message(FATAL_ERROR "YADE was built with ${YADE_REAL_BITS}-bit Real; this plugin's core computes in double (64 bits)")
endif()

# Feature -> compile definitions, as YADE's own top-level CMakeLists.txt maps its ENABLE_* options.
# They change class layouts (Scene, Body, ...), so they must match the installed build exactly.
set(_map
  "LOGGER:YADE_BOOST_LOG,BOOST_LOG_DYN_LINK"
  "COMPLEX_MP:YADE_COMPLEX_MP"
  "VTK:YADE_VTK"
  "OPENMP:YADE_OPENMP"
  "QT5:YADE_OPENGL,YADE_QT5,QT_NO_KEYWORDS"
  "CGAL:YADE_CGAL,CGAL_DISABLE_ROUNDING_MATH_CHECK"
  "PFVFLOW:FLOW_ENGINE"
  "LINSOLV:LINSOLV"
  "MPI:YADE_MPI"
  "TWOPHASEFLOW:TWOPHASEFLOW"
  "LS_DEM:YADE_LS_DEM"
  "FEMLIKE:YADE_FEM"
  "GL2PS:YADE_GL2PS"
  "LBMFLOW:LBM_ENGINE"
  "THERMAL:THERMAL"
  "PARTIALSAT:PARTIALSAT"
  "POTENTIAL_PARTICLES:YADE_POTENTIAL_PARTICLES"
  "POTENTIAL_BLOCKS:YADE_POTENTIAL_BLOCKS"
  "SPH:YADE_SPH"
  "DEFORM:YADE_DEFORM"
  "LIQMIGRATION:YADE_LIQMIGRATION"
  "MASK_ARBITRARY:YADE_MASK_ARBITRARY"
  "PROFILING:USE_TIMING_DELTAS,ISC_TIMING")
# Features that change nothing a plugin sees (or only link-time options of YADE itself).
set(_inert USEFUL_ERRORS GTS ASAN FAST_NATIVE MPFR MPC CHOLMOD_GPU)
set(YADE_COMPILE_DEFINITIONS MAX_LOG_LEVEL=5 YADE_REAL_BIT=${YADE_REAL_BITS} YADE_REAL_DEC=${YADE_REAL_DEC}
    YADE_DISABLE_REAL_MULTI_HP YADE_ODEINT)
foreach(_f IN LISTS YADE_FEATURES)
  set(_found FALSE)
  foreach(_m IN LISTS _map)
    if(_m MATCHES "^${_f}:(.*)$")
      string(REPLACE "," ";" _defs "${CMAKE_MATCH_1}")
      list(APPEND YADE_COMPILE_DEFINITIONS ${_defs})
      set(_found TRUE)
    endif()
  endforeach()
  list(FIND _inert "${_f}" _i)
  if(NOT _found AND _i EQUAL -1)
    message(FATAL_ERROR "YADE feature '${_f}' has no known mapping to compile definitions; extend cmake/InstalledYade.cmake")
  endif()
endforeach()
list(FIND YADE_FEATURES VECTORIZE _vec)
if(_vec EQUAL -1)
  list(APPEND YADE_COMPILE_DEFINITIONS EIGEN_DONT_VECTORIZE EIGEN_DONT_ALIGN EIGEN_DISABLE_UNALIGNED_ARRAY_ASSERT)
endif()
message(STATUS "YADE ${YADE_VERSION} in ${YADE_LIBDIR}; features: ${YADE_FEATURES}")
