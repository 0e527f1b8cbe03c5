# Hairer's RADAU5 (Radau IIA of order 5, its own step-size control and collocation output), the
# implicit Runge-Kutta peer of the studies (analysis/peers/radau5.hpp). Its Fortran source is in
# deSolve (Debian's source package r-cran-desolve: src/radau5.f, src/radau5a.f, Hairer's 2004
# BSD notice; deSolve only rewrote its WRITE statements as calls to R's printing, which
# analysis/peers/radau5.cpp answers). tools/install-deps fetches the package into
# STEPLAB_PEER_CACHE/radau5; here, at configure time, the two files are unpacked and compiled by
# gfortran with the flags Debian's R builds deSolve with (-O2, -fPIC) into <build>/peers/radau5/
# libradau5.a: a few seconds, once per build folder.
#
# Without gfortran or the source: one warning, no RADAU5 (asking for the peer by name exits 2).
# STEPLAB_HAVE_RADAU5 (1 or 0) says which; the target steplab_radau5 carries the library.
set(_r5_dir "${CMAKE_BINARY_DIR}/peers/radau5")
set(_r5_lib "${_r5_dir}/libradau5.a")
set(STEPLAB_RADAU5_FLAGS "gfortran -O2 -fPIC")
file(GLOB _r5_tarballs "${STEPLAB_PEER_CACHE}/radau5/r-cran-desolve_*.orig.tar.*")
find_program(STEPLAB_GFORTRAN NAMES gfortran)
if(_r5_tarballs AND STEPLAB_GFORTRAN AND NOT EXISTS "${_r5_lib}")
  list(GET _r5_tarballs 0 _r5_tarball)
  message(STATUS "steplab: building RADAU5 (${STEPLAB_RADAU5_FLAGS}) from ${_r5_tarball}")
  file(REMOVE_RECURSE "${_r5_dir}")
  file(MAKE_DIRECTORY "${_r5_dir}")
  file(ARCHIVE_EXTRACT INPUT "${_r5_tarball}" DESTINATION "${_r5_dir}" PATTERNS deSolve/src/radau5.f deSolve/src/radau5a.f)
  execute_process(COMMAND ${STEPLAB_GFORTRAN} -O2 -fPIC -w -c deSolve/src/radau5.f deSolve/src/radau5a.f
                  WORKING_DIRECTORY "${_r5_dir}" OUTPUT_FILE "${_r5_dir}/build.log" ERROR_FILE "${_r5_dir}/build.log"
                  RESULT_VARIABLE _r5_rc)
  if(_r5_rc EQUAL 0)
    execute_process(COMMAND ${CMAKE_AR} rcs "${_r5_lib}" radau5.o radau5a.o WORKING_DIRECTORY "${_r5_dir}"
                    RESULT_VARIABLE _r5_rc)
  endif()
  if(NOT _r5_rc EQUAL 0)
    message(WARNING "steplab: compiling RADAU5 from ${_r5_tarball} failed (${_r5_dir}/build.log): no RADAU5 peer")
    file(REMOVE "${_r5_lib}")
  endif()
endif()

add_library(steplab_radau5 INTERFACE)
if(EXISTS "${_r5_lib}")
  set(STEPLAB_HAVE_RADAU5 1)
  list(GET _r5_tarballs 0 _r5_tarball)
  string(REGEX MATCH "desolve_([0-9.]+)\\.orig" _r5_match "${_r5_tarball}")
  set(STEPLAB_RADAU5_SOURCE "radau5.f of deSolve ${CMAKE_MATCH_1} (Debian's r-cran-desolve)")
  target_link_libraries(steplab_radau5 INTERFACE $<BUILD_INTERFACE:${_r5_lib}>
                        $<INSTALL_INTERFACE:$<INSTALL_PREFIX>/${CMAKE_INSTALL_LIBDIR}/steplab/libradau5.a> m)
  install(FILES "${_r5_lib}" DESTINATION ${CMAKE_INSTALL_LIBDIR}/steplab)
else()
  set(STEPLAB_HAVE_RADAU5 0)
  set(STEPLAB_RADAU5_SOURCE "")
  message(WARNING "steplab: no RADAU5 peer (it needs gfortran and Debian's source of r-cran-desolve: tools/install-deps)")
endif()
target_compile_definitions(steplab_radau5 INTERFACE STEPLAB_HAVE_RADAU5=${STEPLAB_HAVE_RADAU5})
install(TARGETS steplab_radau5 EXPORT steplabTargets)
