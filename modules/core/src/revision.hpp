#pragma once
// The version and git revision of the build, compiled from revision.cpp, which the build writes
// (cmake/SigRevision.cmake) whenever `git describe` changes.
#include <string>

namespace sig {

std::string build_version();  ///< project(VERSION) of CMakeLists.txt
std::string build_revision(); ///< `git describe --always --dirty` at build time, or "unknown"

} // namespace sig
