#include "core/input_file.hpp"

#include "core/error.hpp"

namespace sig {

std::string not_a_regular_file(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  switch (status.type()) {
  case std::filesystem::file_type::regular:
    return "";
  case std::filesystem::file_type::not_found:
    return "it does not exist";
  case std::filesystem::file_type::directory:
    return "it is a folder, not a regular file";
  case std::filesystem::file_type::character:
    return "it is a character device, not a regular file";
  case std::filesystem::file_type::block:
    return "it is a block device, not a regular file";
  case std::filesystem::file_type::fifo:
    return "it is a FIFO, not a regular file";
  case std::filesystem::file_type::socket:
    return "it is a socket, not a regular file";
  default:
    return error ? "it cannot be examined: " + error.message() : "it is not a regular file";
  }
}

void verify_regular_file(const std::filesystem::path& path, const std::string& what) {
  const std::string why = not_a_regular_file(path);
  SIG_VERIFY(why.empty(), path.string() << ": cannot read the " << what << ": " << why);
}

} // namespace sig
