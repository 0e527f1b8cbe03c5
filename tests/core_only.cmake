# STEPLAB_CORE_ONLY: core/ and the tests of tests/core/ that use nothing beyond it (no kernel
# table, no studies, no peers), in one executable. CI runs them under AddressSanitizer and
# UndefinedBehaviorSanitizer (`make test-sanitize-core`): the run-time-size scenes (rope, soft
# body) with Newton's sparse solve (core/sparse.cpp, KLU), the springs' constraint methods (XPBD,
# PBD, Baraff-Witkin's CG), output between steps, the small LU and the scenes' scratch space.
# The whole suite under the sanitizers is `make test-sanitize`: each method's kernel file costs
# the compiler 4-5 times its Release time there (rk4's: 44 s at -O3, 111 s sanitized at -O1), about
# 40 minutes of compiling on 2 cores, beyond CI's 30.
find_package(GTest REQUIRED)
include(GoogleTest)
set(STEPLAB_CORE_TESTS baraff_witkin dense_output scratch small_lu spring springs xpbd)
list(TRANSFORM STEPLAB_CORE_TESTS PREPEND ${CMAKE_CURRENT_SOURCE_DIR}/tests/core/)
list(TRANSFORM STEPLAB_CORE_TESTS APPEND _test.cpp)
# the out-of-line parts of the scenes that have them (core/scene.hpp, STEPLAB_SCENE_SOURCE), as
# their kernel files have them
set(scene_sources "")
foreach(h IN LISTS STEPLAB_SCENE_HEADERS)
  file(STRINGS "${h}" out_of_line REGEX "STEPLAB_SCENE_SOURCE")
  if(NOT out_of_line)
    continue()
  endif()
  get_filename_component(stem "${h}" NAME_WE)
  file(CONFIGURE OUTPUT "${CMAKE_BINARY_DIR}/generated/core_only/scene_${stem}.cpp"
       CONTENT "#define STEPLAB_SCENE_SOURCE\n#include \"${h}\"\n" @ONLY)
  list(APPEND scene_sources "${CMAKE_BINARY_DIR}/generated/core_only/scene_${stem}.cpp")
endforeach()
add_executable(steplab_core_tests ${STEPLAB_CORE_TESTS} ${scene_sources} core/sparse.cpp)
set_source_files_properties(core/sparse.cpp PROPERTIES INCLUDE_DIRECTORIES ${STEPLAB_KLU_INCLUDE_DIR})
target_include_directories(steplab_core_tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/tests)
target_link_libraries(steplab_core_tests PRIVATE steplab::core ${FFTW3_LIBRARY} ${STEPLAB_KLU_LIBRARY} GTest::gtest_main steplab_warnings)
enable_testing()
gtest_discover_tests(steplab_core_tests DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600)
