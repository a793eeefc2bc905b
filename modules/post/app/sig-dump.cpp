// sig-dump: print a DS file (header and arrays) or a NOPO mesh, as MODULEF printed its
// structures; --json gives stable keys for scripts, --values adds the arrays' values to it (the
// one way the report scripts read a DS: postproc/sigreport/ds.py).
//
//   sig-dump [--json [--values | --values=NAME,NAME...]] FILE
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/stage.hpp"
#include "mesh/nopo.hpp"
#include "post/dump.hpp"

#include <iostream>
#include <sstream>
#include <string>

int main(int argc, char** argv) {
  return sig::run_stage("sig-dump", [&] {
    // 1. Command line.
    const char* usage = "usage: sig-dump [--json [--values | --values=NAME,NAME...]] FILE";
    bool json = false;
    bool values_given = false;
    sig::DumpValues values;
    std::filesystem::path file;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--json") {
        json = true;
      } else if (arg == "--values") {
        values_given = values.all = true;
      } else if (arg.starts_with("--values=")) {
        values_given = true;
        std::istringstream names(arg.substr(9));
        for (std::string name; std::getline(names, name, ',');)
          if (!name.empty()) values.names.push_back(name);
        SIG_VERIFY(!values.names.empty(), "--values= needs array names (" << usage << ")");
      } else {
        SIG_VERIFY(file.empty() && !arg.starts_with("-"), usage);
        file = arg;
      }
    }
    SIG_VERIFY(!file.empty(), usage);
    SIG_VERIFY(json || !values_given, "--values needs --json (" << usage << ")");
    SIG_VERIFY(std::filesystem::exists(file), file.string() << ": no such file");

    // 2. A DS starts with its magic; anything else must be a NOPO mesh.
    if (sig::is_ds_file(file)) {
      const sig::Ds ds = sig::read_ds(file);
      // With values the JSON is written on one line: arrays of thousands of numbers.
      std::cout << (json ? sig::dump_ds_json(ds, values).dump(values_given ? -1 : 2) + "\n"
                         : sig::dump_ds_text(ds));
      return;
    }
    SIG_VERIFY(!values_given, file.string() << ": --values is for DS files, not NOPO meshes");
    const sig::NopoFile nopo = sig::read_nopo_file(file);
    const std::string& title = nopo.text.title;
    std::cout << (json ? sig::dump_mesh_json(nopo.mesh, title).dump() + "\n"
                       : sig::dump_mesh_text(nopo.mesh, title));
  });
}
