#pragma once
// Inputs are regular files. A device (/dev/zero), a FIFO or a folder given as a datafile, a mesh
// or a DS would be read without end, or mean nothing: each reader refuses it first.
#include <filesystem>
#include <string>

namespace sig {

/// "" if `path` (links followed) is a regular file, else what it is instead: "is a character
/// device, not a regular file", "does not exist", ...
std::string not_a_regular_file(const std::filesystem::path& path);

/// Throw sig::Error "PATH: cannot read the WHAT: it is a character device, not a regular file"
/// unless `path` is a regular file.
void verify_regular_file(const std::filesystem::path& path, const std::string& what);

} // namespace sig
