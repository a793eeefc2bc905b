#include "core/stage.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/provenance.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <exception>
#include <iostream>

namespace sig {

namespace {
// Stages are named "mesh" or "sig-mesh" by their mains; messages always say "sig-mesh".
std::string program_name(const std::string& stage) {
  return stage.rfind("sig-", 0) == 0 ? stage : "sig-" + stage;
}
} // namespace

std::filesystem::path StageArgs::ds_path(const std::string& extension) const {
  return outdir / ("case." + extension);
}

StageArgs parse_stage_args(int argc, char** argv, const std::string& stage) {
  const std::string usage = "usage: " + program_name(stage) + " DATAFILE [-o OUTDIR]";
  StageArgs args;
  bool have_outdir = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o") {
      SIG_VERIFY(i + 1 < argc && !have_outdir, usage);
      args.outdir = argv[++i];
      have_outdir = true;
    } else {
      SIG_VERIFY(!arg.empty() && arg[0] != '-' && args.datafile.empty(), usage);
      args.datafile = arg;
    }
  }
  SIG_VERIFY(!args.datafile.empty(), usage);
  if (!have_outdir) args.outdir = std::filesystem::path("out") / args.datafile.stem();
  SIG_VERIFY(!args.outdir.empty(), usage);
  std::error_code error;
  std::filesystem::create_directories(args.outdir, error);
  SIG_VERIFY(!error, args.outdir.string() << ": cannot create output folder: " << error.message());
  // What a killed stage left: its temporaries would otherwise pile up in OUTDIR forever.
  for (const std::string& name : remove_stale_temporaries(args.outdir))
    log_info("removed " + (args.outdir / name).string() + ", left by a stage that was killed");
  open_case(args.outdir);
  return args;
}

int run_stage(const std::string& stage, const std::function<void()>& body) {
  int status = 1;
  close_case();
  try {
    body();
    // What the stage printed is a result too (sig-dump > file): a failed write is an error.
    std::cout.flush();
    errno = 0;
    SIG_VERIFY(std::cout.good() && std::fflush(stdout) == 0 && !std::ferror(stdout),
               "cannot write to the standard output"
                   << (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()));
    status = 0;
  } catch (const std::exception& e) {
    std::cerr << program_name(stage) << ": error: " << e.what() << std::endl;
  } catch (...) {
    std::cerr << program_name(stage) << ": error: unknown exception" << std::endl;
  }
  close_case();
  return status;
}

std::string ds_date() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[16];
  std::strftime(text, sizeof text, "%y/%m/%d", &local);
  return text;
}

} // namespace sig
