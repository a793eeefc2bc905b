// sig-dump: print a DS file (header and arrays) or a NOPO mesh, as MODULEF printed its
// structures; --json gives stable keys for scripts.
//
//   sig-dump [--json] FILE
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/stage.hpp"
#include "mesh/nopo.hpp"
#include "post/dump.hpp"

#include <iostream>
#include <string>

int main(int argc, char** argv) {
  return sig::run_stage("sig-dump", [&] {
    // 1. Command line.
    bool json = false;
    std::filesystem::path file;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--json") {
        json = true;
      } else {
        SIG_VERIFY(file.empty() && !arg.starts_with("-"), "usage: sig-dump [--json] FILE");
        file = arg;
      }
    }
    SIG_VERIFY(!file.empty(), "usage: sig-dump [--json] FILE");
    SIG_VERIFY(std::filesystem::exists(file), file.string() << ": no such file");

    // 2. A DS starts with its magic; anything else must be a NOPO mesh.
    if (sig::is_ds_file(file)) {
      const sig::Ds ds = sig::read_ds(file);
      std::cout << (json ? sig::dump_ds_json(ds).dump() + "\n" : sig::dump_ds_text(ds));
      return;
    }
    const sig::NopoFile nopo = sig::read_nopo_file(file);
    const std::string& title = nopo.text.title;
    std::cout << (json ? sig::dump_mesh_json(nopo.mesh, title).dump() + "\n"
                       : sig::dump_mesh_text(nopo.mesh, title));
  });
}
