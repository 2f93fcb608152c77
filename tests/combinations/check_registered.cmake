# CTest check `parameterizations_registered` (cmake -DSOURCE_DIR=... -P check_registered.cmake):
# every type that a header of parameterizations/ declares a RotationParameterization (the
# `static_assert(RotationParameterization<T>);` each one ends with) must be listed in
# ROTBEAM_FOR_EACH_PARAMETERIZATION and its header included in parameterizations/registry.hpp.
# Forgetting either leaves the parameterization out of every formulation, case and study without
# any compile error, hence this check.
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "check_registered.cmake: pass -DSOURCE_DIR=<the rotbeam source tree>")
endif()
set(registry_file "${SOURCE_DIR}/parameterizations/registry.hpp")
file(READ "${registry_file}" registry)
# The list: the #define line and its backslash-continued lines.
string(REGEX MATCH "#define ROTBEAM_FOR_EACH_PARAMETERIZATION\\(X\\)([^\n]*\\\\\n)*[^\n]*" list
       "${registry}")
if(NOT list)
  message(FATAL_ERROR "${registry_file}: no ROTBEAM_FOR_EACH_PARAMETERIZATION(X) definition")
endif()
# A variant of a listed parameterization (chosen by a case key, not a parameterization of its
# own) is named in registry.hpp's "// Variants: Type (...)" comment and skipped here.
string(REGEX MATCH "// Variants: ([A-Za-z0-9_]+)" variant_line "${registry}")
set(variant "${CMAKE_MATCH_1}")
file(GLOB headers RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/parameterizations/*.hpp")
set(found 0)
set(missing "")
foreach(header ${headers})
  file(STRINGS "${SOURCE_DIR}/${header}" asserts
       REGEX "^[ \t]*static_assert\\((param::)?RotationParameterization<[A-Za-z0-9_]+>\\);")
  foreach(line ${asserts})
    string(REGEX REPLACE ".*RotationParameterization<([A-Za-z0-9_]+)>.*" "\\1" type "${line}")
    if(type STREQUAL variant)
      continue()
    endif()
    math(EXPR found "${found} + 1")
    if(NOT list MATCHES "X\\(${type}\\)")
      string(APPEND missing "\n  ${header}: ${type} is not listed in "
             "ROTBEAM_FOR_EACH_PARAMETERIZATION (add `X(${type})`, parameterizations/registry.hpp)")
    endif()
    string(FIND "${registry}" "#include \"${header}\"" at)
    if(at EQUAL -1)
      string(APPEND missing "\n  ${header}: not included by parameterizations/registry.hpp "
             "(add `#include \"${header}\"`)")
    endif()
  endforeach()
endforeach()
if(found EQUAL 0)
  message(FATAL_ERROR "no `static_assert(RotationParameterization<T>);` found under "
                      "${SOURCE_DIR}/parameterizations: the check would pass on anything")
endif()
if(missing)
  message(FATAL_ERROR "parameterizations that satisfy the concept but are not registered:${missing}")
endif()
message(STATUS "${found} parameterizations, all registered")
