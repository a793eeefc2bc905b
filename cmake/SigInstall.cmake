# cmake --install: the stage executables in bin/ (sig_module), the libraries and headers with a
# CMake package (find_package(Signorini) -> Signorini::core, Signorini::mesh, ...), and under
# share/signorini/ the drivers, report scripts, datafiles and meshes, laid out as in the source
# tree so that the drivers run from there (drivers/lib/installed.sh tells them where bin/ is).
include(CMakePackageConfigHelpers)
set(sig_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/Signorini)
set(sig_share_dir ${CMAKE_INSTALL_DATADIR}/signorini)

install(EXPORT SignoriniTargets NAMESPACE Signorini:: DESTINATION ${sig_cmake_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/SignoriniConfig.cmake.in
  ${PROJECT_BINARY_DIR}/SignoriniConfig.cmake INSTALL_DESTINATION ${sig_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/SignoriniConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/SignoriniConfig.cmake
  ${PROJECT_BINARY_DIR}/SignoriniConfigVersion.cmake
  ${CMAKE_CURRENT_LIST_DIR}/FindSuiteSparse.cmake ${CMAKE_CURRENT_LIST_DIR}/FindMETIS.cmake
  ${CMAKE_CURRENT_LIST_DIR}/FindMUMPS.cmake DESTINATION ${sig_cmake_dir})

if(SIG_UNIT_TESTS_ONLY)
  return()
endif()
# The path from share/signorini/drivers/lib to bin/, relative so that the tree can move.
file(RELATIVE_PATH sig_bin_from_lib /prefix/${sig_share_dir}/drivers/lib
  /prefix/${CMAKE_INSTALL_BINDIR})
configure_file(${CMAKE_CURRENT_LIST_DIR}/installed.sh.in ${PROJECT_BINARY_DIR}/installed.sh @ONLY)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/drivers DESTINATION ${sig_share_dir} USE_SOURCE_PERMISSIONS
  PATTERN setup.sh EXCLUDE PATTERN test.sh EXCLUDE)
install(FILES ${PROJECT_BINARY_DIR}/installed.sh DESTINATION ${sig_share_dir}/drivers/lib)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/postproc ${PROJECT_SOURCE_DIR}/datafiles
  ${PROJECT_SOURCE_DIR}/meshes DESTINATION ${sig_share_dir} USE_SOURCE_PERMISSIONS
  PATTERN __pycache__ EXCLUDE)
