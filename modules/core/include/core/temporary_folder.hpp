#pragma once
// A scratch folder for a library's files (gmsh's .geo and .msh), removed with its contents when
// it goes out of scope, or when the stage is stopped from outside (core/stage_guard.hpp). Inside
// a stage it is the hidden ".NAME.tmp.PID" in the case's folder, named as the atomic writes'
// temporaries: a killed stage's scratch is removed by the next stage (remove_stale_temporaries)
// and $TMPDIR is never needed. Outside a stage (the unit tests) it is made in the system's
// temporary folder.
#include "core/stage_guard.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace sig {

class TemporaryFolder {
public:
  explicit TemporaryFolder(const std::string& name);
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
  std::unique_ptr<Unfinished> unfinished_;
};

} // namespace sig
