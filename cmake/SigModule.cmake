# sig_library(TARGET SOURCES <files...> INCLUDE <dir> [PUBLIC <deps...>] [PRIVATE <deps...>])
# One library of the project: built from SOURCES (an INTERFACE library when there are none), its
# headers under INCLUDE/<module>/ (used as #include "<module>/x.hpp"), exported and installed as
# Signorini::<name> (TARGET without its sig_ prefix). PUBLIC lists what the public headers need
# (a user of the library gets those too); PRIVATE what only the sources need.
function(sig_library target)
  cmake_parse_arguments(ARG "" "INCLUDE" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  string(REGEX REPLACE "^sig_" "" export_name ${target})
  if(ARG_SOURCES)
    add_library(${target} STATIC ${ARG_SOURCES})
    set(scope PUBLIC)
    target_link_libraries(${target} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
    target_link_libraries(${target} INTERFACE ${ARG_PUBLIC} ${ARG_PRIVATE})
  endif()
  target_include_directories(${target} ${scope} $<BUILD_INTERFACE:${ARG_INCLUDE}>
                             $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/signorini>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  add_library(Signorini::${export_name} ALIAS ${target})
  install(TARGETS ${target} EXPORT SignoriniTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${ARG_INCLUDE}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/signorini
          FILES_MATCHING PATTERN "*.hpp")
endfunction()

# sig_module(NAME [PUBLIC <deps...>] [PRIVATE <deps...>] [APP_DEPS <targets...>])
# A module is modules/NAME/{include,src,app}: the library sig_NAME (sig_library above) is built
# from src/*.cpp, every app/sig-*.cpp becomes a stage executable of the same name in the build's
# bin/ and the install's bin/. Files added there are picked up at the next configure, so no
# module CMakeLists needs editing when a file is added.
function(sig_module name)
  cmake_parse_arguments(ARG "" "" "PUBLIC;PRIVATE;APP_DEPS" ${ARGN})
  set(dir ${CMAKE_CURRENT_SOURCE_DIR})
  file(GLOB sources CONFIGURE_DEPENDS ${dir}/src/*.cpp)
  sig_library(sig_${name} SOURCES ${sources} INCLUDE ${dir}/include PUBLIC ${ARG_PUBLIC}
              PRIVATE ${ARG_PRIVATE})
  if(SIG_UNIT_TESTS_ONLY)
    return()
  endif()
  file(GLOB apps CONFIGURE_DEPENDS ${dir}/app/sig-*.cpp)
  foreach(app ${apps})
    get_filename_component(exe ${app} NAME_WE)
    add_executable(${exe} ${app})
    target_link_libraries(${exe} PRIVATE sig_${name} ${ARG_APP_DEPS})
    set_target_properties(${exe} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/bin)
    install(TARGETS ${exe} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endforeach()
endfunction()
