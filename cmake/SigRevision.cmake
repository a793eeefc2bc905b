# cmake -DSOURCE_DIR= -DOUTPUT= -DVERSION= -P SigRevision.cmake: write OUTPUT, the C++ source of
# sig::build_version() and sig::build_revision() (modules/core/src/revision.hpp), from
# `git describe`. Run at every build; the file is rewritten only when the revision changed, so
# an unchanged tree rebuilds nothing.
execute_process(COMMAND git -C ${SOURCE_DIR} describe --always --dirty --abbrev=12
  OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE failed)
if(failed OR NOT revision)
  set(revision unknown)
endif()
file(CONFIGURE OUTPUT ${OUTPUT} CONTENT "// Written by cmake/SigRevision.cmake at build time.
#include \"revision.hpp\"

namespace sig {
std::string build_version() { return \"${VERSION}\"; }
std::string build_revision() { return \"${revision}\"; }
} // namespace sig
")
