# Static archives of the compiled dependencies (SUNDIALS, KLU, GSL, yaml-cpp), for
# ROTBEAM_STATIC_DEPS. Why: with the shared libraries every start of `rotbeam` spends ~5 ms of CPU
# in the kernel and the dynamic loader (17 shared objects, ~2 800 relocations) before any beam
# work; the fully static program starts in 1.8 ms (docs/performance.md). Debian's -dev packages
# ship every one of these archives; the imported targets of the packages' own CMake configs do
# not offer a usable static variant (SUNDIALS' *_static targets link shared siblings), so the
# archives are found by name.
#
# rotbeam_find_static_archives(OUT) sets OUT to the archives in link order (a library before the
# ones it uses), or to an empty list when one is missing (the build then links dynamically).
function(rotbeam_find_static_archives out)
  set(names
    sundials_kinsol sundials_ida sundials_sunlinsolklu sundials_sunmatrixsparse
    sundials_nvecserial
    klu amd colamd btf suitesparseconfig
    gsl gslcblas
    yaml-cpp)
  set(archives "")
  foreach(name IN LISTS names)
    find_library(ROTBEAM_ARCHIVE_${name} NAMES lib${name}.a)
    if(NOT ROTBEAM_ARCHIVE_${name})
      message(STATUS "rotbeam: lib${name}.a not found; linking the dependencies dynamically")
      set(${out} "" PARENT_SCOPE)
      return()
    endif()
    list(APPEND archives ${ROTBEAM_ARCHIVE_${name}})
  endforeach()
  set(${out} ${archives} m PARENT_SCOPE)
endfunction()
