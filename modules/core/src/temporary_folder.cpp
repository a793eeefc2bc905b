#include "core/temporary_folder.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/provenance.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace sig {

namespace {

// The system's temporary folder, with what is wrong with it in words ($TMPDIR naming a file or
// nothing) instead of the library's "filesystem error: temp_directory_path".
std::filesystem::path system_temporary_folder() {
  std::error_code error;
  std::filesystem::path folder = std::filesystem::temp_directory_path(error);
  if (error) {
    const char* tmpdir = std::getenv("TMPDIR");
    SIG_VERIFY(false, "no temporary folder: " << error.message()
                                              << (tmpdir ? std::string(" (TMPDIR=") + tmpdir +
                                                               " is not a folder one can write)"
                                                         : std::string()));
  }
  return folder;
}

} // namespace

TemporaryFolder::TemporaryFolder(const std::string& name) {
  const std::filesystem::path folder = case_folder();
  if (!folder.empty()) {
    path_ = temporary_path(folder / name);
    std::error_code error;
    std::filesystem::remove_all(path_, error); // a folder of an earlier process with our pid
    SIG_VERIFY(std::filesystem::create_directory(path_, error) && !error,
               path_.string() << ": cannot create a scratch folder: " << error.message());
  } else {
    std::string pattern = (system_temporary_folder() / ("sig-" + name + "-XXXXXX")).string();
    SIG_VERIFY(::mkdtemp(pattern.data()) != nullptr,
               pattern << ": cannot create a scratch folder: " << std::strerror(errno));
    path_ = pattern;
  }
  unfinished_ = std::make_unique<Unfinished>(path_);
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

} // namespace sig
