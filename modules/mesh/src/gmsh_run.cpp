#include "gmsh_run.hpp"

#include "core/error.hpp"
#include "core/phase_times.hpp"
#include "core/temporary_folder.hpp"
#include "mesh/gmsh.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sig {
namespace {

// gmsh with its output to `log`, in a process group of its own that dies with us (a killed
// sig-mesh leaves no gmsh running) and that a stopped stage kills (Unfinished). Returns the
// wait status.
int run_gmsh(const std::vector<std::string>& arguments, const std::filesystem::path& log) {
  std::vector<char*> argv;
  for (const std::string& a : arguments)
    argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t parent = ::getpid();
  const pid_t child = ::fork();
  SIG_VERIFY(child >= 0, "cannot start gmsh: " << std::strerror(errno));
  if (child == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127); // the parent died before prctl
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  const Unfinished running(child);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0)
    SIG_VERIFY(errno == EINTR, "waiting for gmsh: " << std::strerror(errno));
  return status;
}

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
                    const std::vector<std::pair<std::string, double>>& numbers, int dim) {
  const TemporaryFolder folder("gmsh");
  const auto geo = folder.path() / (name + ".geo");
  const auto msh = folder.path() / (name + ".msh");
  const auto log = folder.path() / "gmsh.log";
  {
    std::ofstream out(geo);
    out << script;
    SIG_VERIFY(out, "cannot write " << geo.string());
  }
  const char* binary = std::getenv("SIG_GMSH");
  std::vector<std::string> arguments{binary ? binary : "gmsh",
                                     geo.string(),
                                     dim == 3 ? "-3" : "-2",
                                     "-format",
                                     "msh41",
                                     "-nt",
                                     "1",
                                     "-v",
                                     "2"};
  for (const auto& [key, value] : numbers) {
    std::ostringstream text;
    text << std::setprecision(17) << value;
    arguments.insert(arguments.end(), {"-setnumber", key, text.str()});
  }
  arguments.insert(arguments.end(), {"-o", msh.string()});
  const int status = [&] {
    const PhaseTimer timer("gmsh"); // gmsh's own mesh generation
    return run_gmsh(arguments, log);
  }();

  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string command;
  for (const std::string& a : arguments)
    command.append(command.empty() ? "" : " ").append(shell_quote(a));
  SIG_VERIFY(WIFEXITED(status) && WEXITSTATUS(status) == 0 &&
                 text.find("Error") == std::string::npos && std::filesystem::exists(msh),
             "gmsh failed on " << name << ".geo (status " << status << ", command: " << command
                               << ")" << last_lines(log, 8));
  const PhaseTimer timer("read");
  return read_gmsh(msh, MeshCheck::skip); // each generator checks the mesh it makes of it
}

} // namespace sig
