# scout_module(NAME SOURCES ... DEPS ... [PUBLIC_LIBS ...])
#   Declares the library target scout_<NAME>. DEPS names other Scout modules
#   (without prefix); only these may be included, which keeps the dependency
#   direction of the architecture enforced by the target graph.
function(scout_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;LIBS" ${ARGN})
  add_library(scout_${name} ${ARG_SOURCES})
  target_include_directories(scout_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
  foreach(dep IN LISTS ARG_DEPS)
    target_link_libraries(scout_${name} PUBLIC scout_${dep})
  endforeach()
  if(ARG_LIBS)
    target_link_libraries(scout_${name} PUBLIC ${ARG_LIBS})
  endif()
endfunction()

# scout_test(NAME SOURCES ... LIBS ...)
#   One GoogleTest executable; every TEST becomes its own CTest case.
function(scout_test name)
  if(NOT SCOUT_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main rapidcheck)
  target_compile_definitions(${name} PRIVATE
    SCOUT_SHARED_DATA_DIR="${PROJECT_SOURCE_DIR}/../shared/data"
    SCOUT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 300)
endfunction()
