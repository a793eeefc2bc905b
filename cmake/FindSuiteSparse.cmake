# Debian's SuiteSparse 5.x ships no CMake package: find CHOLMOD and UMFPACK by hand.
# Defines SuiteSparse::CHOLMOD and SuiteSparse::UMFPACK.
find_path(SuiteSparse_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
set(_ss_libs cholmod umfpack amd camd colamd ccolamd suitesparseconfig)
foreach(lib ${_ss_libs})
  find_library(SuiteSparse_${lib}_LIBRARY ${lib})
  list(APPEND _ss_required SuiteSparse_${lib}_LIBRARY)
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse REQUIRED_VARS SuiteSparse_INCLUDE_DIR ${_ss_required})
if(SuiteSparse_FOUND AND NOT TARGET SuiteSparse::CHOLMOD)
  foreach(lib ${_ss_libs})
    add_library(SuiteSparse::${lib} UNKNOWN IMPORTED)
    set_target_properties(SuiteSparse::${lib} PROPERTIES
      IMPORTED_LOCATION ${SuiteSparse_${lib}_LIBRARY}
      INTERFACE_INCLUDE_DIRECTORIES ${SuiteSparse_INCLUDE_DIR})
  endforeach()
  add_library(SuiteSparse::CHOLMOD INTERFACE IMPORTED)
  target_link_libraries(SuiteSparse::CHOLMOD INTERFACE SuiteSparse::cholmod SuiteSparse::amd
    SuiteSparse::camd SuiteSparse::colamd SuiteSparse::ccolamd SuiteSparse::suitesparseconfig)
  add_library(SuiteSparse::UMFPACK INTERFACE IMPORTED)
  target_link_libraries(SuiteSparse::UMFPACK INTERFACE SuiteSparse::umfpack SuiteSparse::CHOLMOD)
endif()
