# MUMPS from Debian's libmumps-dev: the MPI build (OpenMPI, ScaLAPACK). The sequential
# libmumps-seq-dev cannot share a binary with it (both define dmumps_c, and the sequential one
# exports stub MPI symbols): this one build also runs as a plain process, an MPI singleton
# (solver/mpi_session.hpp). Defines MUMPS::MUMPS, which carries MPI.
# MPI's C interface, or its C++ one in a project without C (a user of the installed package that
# enables only CXX: FindMPI needs the language enabled); either links libmpi.
get_property(_mumps_languages GLOBAL PROPERTY ENABLED_LANGUAGES)
if("C" IN_LIST _mumps_languages)
  find_package(MPI REQUIRED COMPONENTS C)
  set(_mumps_mpi MPI::MPI_C)
else()
  find_package(MPI REQUIRED COMPONENTS CXX)
  set(_mumps_mpi MPI::MPI_CXX)
endif()
find_path(MUMPS_INCLUDE_DIR dmumps_c.h)
foreach(lib dmumps mumps_common)
  find_library(MUMPS_${lib}_LIBRARY ${lib})
  list(APPEND _mumps_required MUMPS_${lib}_LIBRARY)
  list(APPEND _mumps_libs ${MUMPS_${lib}_LIBRARY})
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MUMPS REQUIRED_VARS MUMPS_INCLUDE_DIR ${_mumps_required})
if(MUMPS_FOUND AND NOT TARGET MUMPS::MUMPS)
  add_library(MUMPS::MUMPS INTERFACE IMPORTED)
  target_include_directories(MUMPS::MUMPS INTERFACE ${MUMPS_INCLUDE_DIR})
  target_link_libraries(MUMPS::MUMPS INTERFACE ${_mumps_libs} ${_mumps_mpi})
endif()
