#pragma once
// A file written under a temporary name in the target's folder and renamed over the target only
// when complete and synced: readers see the old file or the new one, never half of one.
#include "core/stage_guard.hpp"

#include <cstdio>
#include <filesystem>
#include <functional>

namespace sig {

class AtomicFile {
public:
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  /// Without commit() (an exception on the way) the temporary file is removed.
  ~AtomicFile();

  void write(const void* data, std::size_t size);
  /// Flush, fsync (unless deferred: core/ds.hpp), close and rename over the target.
  /// `before_rename`, when given, runs with the temporary complete and closed; if it throws, the
  /// temporary is removed and the target left as it was (a rank of an mpirun job waits there
  /// for the others to have written theirs).
  void commit(const std::function<void()>& before_rename = {});

private:
  std::filesystem::path target_, temporary_;
  Unfinished unfinished_; ///< removes the temporary if the stage is stopped from outside
  std::FILE* file_ = nullptr;
  bool stopped_ = false; ///< stop_point_for_tests passed (once, at the first write)
};

} // namespace sig
