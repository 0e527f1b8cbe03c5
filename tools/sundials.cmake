# SUNDIALS CVODE and ARKODE, the multistep and Runge-Kutta peers of the studies (analysis/peers/peers.hpp), built as its maintainers
# build it: CMAKE_BUILD_TYPE=Release. Debian's libsundials-dev is compiled without optimisation
# (its debian/rules sets CMAKE_C_FLAGS=-fcommon, which replaces the packaging's -O2), which made
# every CVODE run about three times slower than SUNDIALS' own build (docs/performance.md).
#
# tools/install-deps fetches Debian's source package of the installed libsundials-dev into
# STEPLAB_PEER_CACHE (no third-party source lives in this repository). Here, at configure time,
# the upstream tarball in it is unpacked and CVODE and ARKODE alone (their serial vector, dense, band and
# sparse matrices, their solvers and KLU's) built into <build>/peers/sundials as static,
# position-independent libraries: about ten seconds, once per build folder.
#
# Without the source, Debian's libraries are used, with one warning. Either way the target
# steplab_sundials carries the include folder and the libraries, and STEPLAB_CVODE_OPTIMISED
# (1 or 0) and STEPLAB_CVODE_FLAGS say which build it is (recorded in the studies' JSON).
if(DEFINED ENV{XDG_CACHE_HOME})
  set(_steplab_cache "$ENV{XDG_CACHE_HOME}/steplab")
else()
  set(_steplab_cache "$ENV{HOME}/.cache/steplab")
endif()
set(STEPLAB_PEER_CACHE "${_steplab_cache}" CACHE PATH "Where tools/install-deps keeps the peers' source packages")
option(STEPLAB_OPTIMISED_PEERS "Build CVODE from its source, optimised (else Debian's unoptimised build)" ON)

set(_sd_prefix "${CMAKE_BINARY_DIR}/peers/sundials")
set(_sd_lib "${_sd_prefix}/${CMAKE_INSTALL_LIBDIR}")
file(GLOB _sd_tarballs "${STEPLAB_PEER_CACHE}/sundials/sundials_*.orig.tar.*")
if(STEPLAB_OPTIMISED_PEERS AND _sd_tarballs AND NOT EXISTS "${_sd_lib}/libsundials_arkode.a")
  list(GET _sd_tarballs 0 _sd_tarball)
  message(STATUS "steplab: building SUNDIALS CVODE and ARKODE optimised (Release) from ${_sd_tarball}")
  set(_sd_work "${CMAKE_BINARY_DIR}/peers/sundials-build")
  file(REMOVE_RECURSE "${_sd_work}")
  file(MAKE_DIRECTORY "${_sd_work}")
  file(ARCHIVE_EXTRACT INPUT "${_sd_tarball}" DESTINATION "${_sd_work}/src")
  file(GLOB _sd_src LIST_DIRECTORIES true "${_sd_work}/src/sundials-*")
  cmake_host_system_information(RESULT _sd_jobs QUERY NUMBER_OF_LOGICAL_CORES)
  find_path(_sd_klu_include klu.h PATH_SUFFIXES suitesparse)
  find_library(_sd_klu klu)
  set(_sd_klu_args -DENABLE_KLU=OFF)
  if(_sd_klu_include AND _sd_klu)
    get_filename_component(_sd_klu_dir "${_sd_klu}" DIRECTORY)
    set(_sd_klu_args -DENABLE_KLU=ON -DKLU_INCLUDE_DIR=${_sd_klu_include} -DKLU_LIBRARY_DIR=${_sd_klu_dir})
  endif()
  execute_process(
    COMMAND ${CMAKE_COMMAND} -S "${_sd_src}" -B "${_sd_work}/build" -DCMAKE_BUILD_TYPE=Release
            -DCMAKE_INSTALL_PREFIX=${_sd_prefix} -DCMAKE_INSTALL_LIBDIR=${CMAKE_INSTALL_LIBDIR}
            -DBUILD_SHARED_LIBS=OFF -DBUILD_STATIC_LIBS=ON -DCMAKE_POSITION_INDEPENDENT_CODE=ON
            -DBUILD_ARKODE=ON -DBUILD_CVODES=OFF -DBUILD_IDA=OFF -DBUILD_IDAS=OFF -DBUILD_KINSOL=OFF -DBUILD_CVODE=ON
            -DEXAMPLES_ENABLE_C=OFF -DEXAMPLES_ENABLE_CXX=OFF -DEXAMPLES_INSTALL=OFF ${_sd_klu_args}
    COMMAND_ECHO NONE OUTPUT_FILE "${_sd_work}/configure.log" ERROR_FILE "${_sd_work}/configure.log" RESULT_VARIABLE _sd_rc)
  if(_sd_rc EQUAL 0)
    execute_process(COMMAND ${CMAKE_COMMAND} --build "${_sd_work}/build" --target install -j ${_sd_jobs}
                    OUTPUT_FILE "${_sd_work}/build.log" ERROR_FILE "${_sd_work}/build.log" RESULT_VARIABLE _sd_rc)
  endif()
  if(NOT _sd_rc EQUAL 0)
    message(WARNING "steplab: building SUNDIALS from ${_sd_tarball} failed (${_sd_work}/*.log); using Debian's")
    file(REMOVE_RECURSE "${_sd_prefix}")
  else()
    file(REMOVE_RECURSE "${_sd_work}")
  endif()
endif()

add_library(steplab_sundials INTERFACE)
if(STEPLAB_OPTIMISED_PEERS AND EXISTS "${_sd_lib}/libsundials_arkode.a")
  set(STEPLAB_CVODE_OPTIMISED 1)
  set(STEPLAB_CVODE_FLAGS "CMAKE_BUILD_TYPE=Release (-O3 -DNDEBUG)")
  set(STEPLAB_HAVE_KLU 0)
  set(_sd_libs "")
  if(EXISTS "${_sd_lib}/libsundials_sunlinsolklu.a")
    set(STEPLAB_HAVE_KLU 1)
    list(APPEND _sd_libs sundials_sunlinsolklu)
  endif()
  list(APPEND _sd_libs sundials_cvode sundials_arkode)
  # Installed with steplab (lib/steplab/), so that a project built against the package links them.
  foreach(l IN LISTS _sd_libs)
    target_link_libraries(steplab_sundials INTERFACE $<BUILD_INTERFACE:${_sd_lib}/lib${l}.a>
                          $<INSTALL_INTERFACE:$<INSTALL_PREFIX>/${CMAKE_INSTALL_LIBDIR}/steplab/lib${l}.a>)
    install(FILES "${_sd_lib}/lib${l}.a" DESTINATION ${CMAKE_INSTALL_LIBDIR}/steplab)
  endforeach()
  target_include_directories(steplab_sundials INTERFACE $<BUILD_INTERFACE:${_sd_prefix}/include>)
  target_link_libraries(steplab_sundials INTERFACE m)  # static libraries: their own dependency on libm
else()
  message(WARNING "steplab: CVODE from Debian's libsundials-dev, compiled without optimisation: the peers' times are "
                  "not SUNDIALS' (tools/install-deps fetches its source to build it optimised)")
  set(STEPLAB_CVODE_OPTIMISED 0)
  set(STEPLAB_CVODE_FLAGS "-fcommon (Debian's CMAKE_C_FLAGS, no -O)")
  find_path(SUNDIALS_INCLUDE_DIR cvode/cvode.h REQUIRED)
  find_library(SUNDIALS_CVODE_LIBRARY sundials_cvode REQUIRED)
  find_library(SUNDIALS_ARKODE_LIBRARY sundials_arkode REQUIRED)
  find_library(SUNDIALS_KLU_LIBRARY sundials_sunlinsolklu)
  find_library(SUNDIALS_SPARSE_LIBRARY sundials_sunmatrixsparse)
  set(STEPLAB_HAVE_KLU 0)
  if(SUNDIALS_KLU_LIBRARY AND SUNDIALS_SPARSE_LIBRARY)
    set(STEPLAB_HAVE_KLU 1)
    target_link_libraries(steplab_sundials INTERFACE ${SUNDIALS_KLU_LIBRARY} ${SUNDIALS_SPARSE_LIBRARY})
  endif()
  target_link_libraries(steplab_sundials INTERFACE ${SUNDIALS_CVODE_LIBRARY} ${SUNDIALS_ARKODE_LIBRARY})
endif()
if(STEPLAB_HAVE_KLU)
  find_library(KLU_LIBRARY klu REQUIRED)
  find_path(KLU_INCLUDE_DIR klu.h PATH_SUFFIXES suitesparse REQUIRED)
  target_include_directories(steplab_sundials INTERFACE $<BUILD_INTERFACE:${KLU_INCLUDE_DIR}>)
  target_link_libraries(steplab_sundials INTERFACE ${KLU_LIBRARY})
endif()
target_compile_definitions(steplab_sundials INTERFACE STEPLAB_HAVE_KLU=${STEPLAB_HAVE_KLU})
install(TARGETS steplab_sundials EXPORT steplabTargets)
