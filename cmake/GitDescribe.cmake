# Script mode (cmake -P), run by the build before every build of rotbeam_core: writes OUT, the
# definition of rotbeam::kGitDescribe (core/version.hpp), from `git describe --always --dirty
# --tags` of SOURCE_DIR, or FALLBACK outside a git checkout. OUT is rewritten only when the text
# changes, so an unchanged commit recompiles and relinks nothing; a new commit (or a clean tree
# becoming dirty) recompiles this one file and relinks what links rotbeam_core.
set(describe "${FALLBACK}")
find_package(Git QUIET)
if(GIT_FOUND AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" describe --always --dirty --tags
                  WORKING_DIRECTORY "${SOURCE_DIR}"
                  OUTPUT_VARIABLE out OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(out)
    set(describe "${out}")
  endif()
endif()
set(text "// Generated at build time by cmake/GitDescribe.cmake: the commit this build was made from.
#include \"core/version.hpp\"
namespace rotbeam {
const char* const kGitDescribe = \"${describe}\";
}  // namespace rotbeam
")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
