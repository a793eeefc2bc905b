#include "gmsh_run.hpp"

#include "core/error.hpp"
#include "mesh/gmsh.hpp"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <unistd.h>

namespace sig {
namespace {

/// A fresh folder under the system temporary folder, removed with its contents at scope exit.
class TemporaryFolder {
public:
  TemporaryFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "sig-gmsh-XXXXXX").string();
    SIG_VERIFY(mkdtemp(pattern.data()) != nullptr, "cannot create a temporary folder " << pattern);
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

private:
  std::filesystem::path path_;
};

std::string shell_quote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s)
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string last_lines(const std::filesystem::path& path, int count) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  std::string tail;
  for (std::size_t k = lines.size() > static_cast<std::size_t>(count) ? lines.size() - count : 0;
       k < lines.size(); ++k)
    tail += "\n  " + lines[k];
  return tail;
}

} // namespace

Mesh mesh_with_gmsh(const std::string& name, const std::string& script,
                    const std::vector<std::pair<std::string, double>>& numbers) {
  const TemporaryFolder folder;
  const auto geo = folder.path() / (name + ".geo");
  const auto msh = folder.path() / (name + ".msh");
  const auto log = folder.path() / "gmsh.log";
  {
    std::ofstream out(geo);
    out << script;
    SIG_VERIFY(out, "cannot write " << geo.string());
  }
  const char* binary = std::getenv("SIG_GMSH");
  std::ostringstream command;
  command << std::setprecision(17) << (binary ? binary : "gmsh") << " " << shell_quote(geo)
          << " -2 -format msh41 -nt 1 -v 2";
  for (const auto& [key, value] : numbers)
    command << " -setnumber " << key << " " << value;
  command << " -o " << shell_quote(msh) << " > " << shell_quote(log) << " 2>&1";
  const int status = std::system(command.str().c_str());

  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  SIG_VERIFY(status == 0 && text.find("Error") == std::string::npos && std::filesystem::exists(msh),
             "gmsh failed on " << name << ".geo (status " << status
                               << ", command: " << command.str() << ")" << last_lines(log, 8));
  return read_gmsh(msh);
}

} // namespace sig
