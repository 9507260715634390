# FindSuiteSparse: UMFPACK, CHOLMOD and their support libraries from Debian's libsuitesparse-dev
# (SuiteSparse 5.x ships no CMake package). Defines SuiteSparse::UMFPACK and SuiteSparse::CHOLMOD.
find_path(SuiteSparse_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse)
foreach(lib umfpack cholmod amd colamd camd ccolamd suitesparseconfig)
  string(TOUPPER ${lib} LIB)
  find_library(SuiteSparse_${LIB}_LIBRARY ${lib})
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse REQUIRED_VARS SuiteSparse_INCLUDE_DIR
  SuiteSparse_UMFPACK_LIBRARY SuiteSparse_CHOLMOD_LIBRARY SuiteSparse_AMD_LIBRARY
  SuiteSparse_SUITESPARSECONFIG_LIBRARY)
if(SuiteSparse_FOUND AND NOT TARGET SuiteSparse::UMFPACK)
  add_library(SuiteSparse::config UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::config PROPERTIES IMPORTED_LOCATION ${SuiteSparse_SUITESPARSECONFIG_LIBRARY}
    INTERFACE_INCLUDE_DIRECTORIES ${SuiteSparse_INCLUDE_DIR})
  add_library(SuiteSparse::UMFPACK UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::UMFPACK PROPERTIES IMPORTED_LOCATION ${SuiteSparse_UMFPACK_LIBRARY}
    INTERFACE_LINK_LIBRARIES "${SuiteSparse_AMD_LIBRARY};SuiteSparse::config")
  add_library(SuiteSparse::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::CHOLMOD PROPERTIES IMPORTED_LOCATION ${SuiteSparse_CHOLMOD_LIBRARY}
    INTERFACE_LINK_LIBRARIES "${SuiteSparse_AMD_LIBRARY};${SuiteSparse_COLAMD_LIBRARY};${SuiteSparse_CAMD_LIBRARY};${SuiteSparse_CCOLAMD_LIBRARY};SuiteSparse::config")
endif()
