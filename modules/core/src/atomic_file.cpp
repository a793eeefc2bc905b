#include "atomic_file.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/phase_times.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <unistd.h>

namespace sig {

namespace {
constexpr const char* temporary_marker = ".tmp.";

std::string reason() {
  return std::strerror(errno);
}

// The rename is durable only once the folder entry is on disk too.
void sync_folder(const std::filesystem::path& folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return; // best effort: the data itself is already synced
  ::fsync(fd);
  ::close(fd);
}

// defer_file_syncs: a process's choice, made once by its main before it writes.
bool& syncs_deferred() {
  static bool deferred = false;
  return deferred;
}
} // namespace

void defer_file_syncs() {
  syncs_deferred() = true;
}

void sync_deferred_files(const std::filesystem::path& folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY);
  SIG_VERIFY(fd >= 0, folder.string() << ": cannot open to sync its files: " << reason());
  const bool synced = ::syncfs(fd) == 0;
  const std::string why = reason();
  ::close(fd);
  SIG_VERIFY(synced, folder.string() << ": cannot sync its file system: " << why);
}

// Hidden, in the same folder (rename stays within one file system), unique per process.
std::filesystem::path temporary_path(const std::filesystem::path& target) {
  SIG_VERIFY(!target.filename().empty(), target.string() << ": not a file name");
  std::string name = ".";
  name.append(target.filename().string())
      .append(temporary_marker)
      .append(std::to_string(::getpid()));
  return target.parent_path() / name;
}

std::vector<std::string> remove_stale_temporaries(const std::filesystem::path& folder) {
  std::vector<std::string> removed;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    const auto marker = name.rfind(temporary_marker);
    if (name.empty() || name[0] != '.' || marker == std::string::npos) continue;
    const std::string digits = name.substr(marker + std::strlen(temporary_marker));
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const auto pid = static_cast<pid_t>(std::stol(digits));
    // ESRCH: no such process. EPERM means it runs (under another user): keep its file.
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    if (std::filesystem::remove_all(entry.path(), ignored) > 0) removed.push_back(name);
  }
  return removed;
}

void stop_point_for_tests(const std::filesystem::path& target) {
  const char* name = std::getenv("SIG_STOP_WRITING");
  if (name == nullptr || target.filename() != name) return;
  std::fflush(nullptr); // the half-written temporary is in the file when the test looks
  ::raise(SIGSTOP);
}

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporary_path(target_)), unfinished_(temporary_) {
  file_ = std::fopen(temporary_.c_str(), "wb");
  SIG_VERIFY(file_ != nullptr, target_.string() << ": cannot create temporary file "
                                                << temporary_.string() << ": " << reason());
}

AtomicFile::~AtomicFile() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFile::write(const void* data, std::size_t size) {
  SIG_VERIFY(file_ != nullptr, target_.string() << ": write after commit");
  if (size == 0) return;
  SIG_VERIFY(std::fwrite(data, 1, size, file_) == size, target_.string()
                                                            << ": write failed: " << reason());
  if (!stopped_) {
    stopped_ = true;
    stop_point_for_tests(target_);
  }
}

void AtomicFile::commit(const std::function<void()>& before_rename) {
  SIG_VERIFY(file_ != nullptr, target_.string() << ": committed twice");
  const bool flushed =
      std::fflush(file_) == 0 && (syncs_deferred() || ::fsync(::fileno(file_)) == 0);
  const int saved_errno = errno;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  std::error_code ignored;
  if (!flushed || !closed) {
    errno = flushed ? errno : saved_errno;
    const std::string why = reason();
    std::filesystem::remove(temporary_, ignored);
    throw Error(target_.string() + ": cannot flush " + temporary_.string() + ": " + why);
  }
  if (before_rename) {
    try {
      before_rename();
    } catch (...) {
      std::filesystem::remove(temporary_, ignored);
      throw;
    }
  }
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const std::string why = reason();
    std::filesystem::remove(temporary_, ignored);
    throw Error(target_.string() + ": cannot rename " + temporary_.string() +
                " into place: " + why);
  }
  if (!syncs_deferred()) sync_folder(target_.parent_path());
}

void write_file_atomically(const std::filesystem::path& path, const std::string& contents) {
  const PhaseTimer timer("write");
  AtomicFile file(path);
  file.write(contents.data(), contents.size());
  file.commit();
}

} // namespace sig
