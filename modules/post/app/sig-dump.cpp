// sig-dump: print a DS file (header and arrays) or a NOPO mesh, as MODULEF printed its
// structures; --json gives stable keys for scripts, --values adds the arrays' values to it (the
// one way the report scripts read a DS: postproc/sigreport/ds.py). --cards prints the card
// schema, --cards-markdown the same as the Markdown card reference (datafiles/CARDS.md), --chain
// the stages a datafile's chain runs and --stale those of them whose files in a case folder are
// not up to date for the datafile (drivers/chain.sh).
//
//   sig-dump [--json [--values | --values=NAME,NAME...]] FILE
//   sig-dump --cards [CARD...]
//   sig-dump --cards-markdown
//   sig-dump --chain DATAFILE
//   sig-dump --stale DATAFILE OUTDIR
#include "core/card_help.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/stage.hpp"
#include "core/stale.hpp"
#include "mesh/nopo.hpp"
#include "post/dump.hpp"

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-dump",
      .purpose = "Prints any DS file of the stages (header and arrays; NOPO meshes too) as MODULEF "
                 "printed its structures, or the cards of the datafiles with their fields, help "
                 "texts and defaults.",
      .reads = {"FILE: a DS file (case.mili, case.cont, case.tae, case.b, case.hist, ...) or a "
                "NOPO mesh (with --json --values: its coordinates, triangles and edges)"},
      .writes = {"standard output"},
      .cards = {},
      .usage = "[--json [--values | --values=NAME,NAME...]] FILE | --cards [CARD...] | "
               "--cards-markdown | --chain DATAFILE | --stale DATAFILE OUTDIR",
      .options = {{"--json", "stable keys for scripts (JSON) instead of text"},
                  {"--values", "with --json: the values of every array too (one line)"},
                  {"--values=A,B", "with --json: the values of the arrays named"},
                  {"--cards", "every card with a one-line help; --cards CARD...: those cards' "
                              "fields, help texts and defaults"},
                  {"--cards-markdown", "every card, field, default and range as the Markdown card "
                                       "reference (datafiles/CARDS.md)"},
                  {"--chain", "the stages the datafile's chain runs, one per line, as the "
                              "stages read the deck (drivers/chain.sh)"},
                  {"--stale", "the stages of the datafile's chain to rerun for the case in "
                              "OUTDIR, one per line as 'STAGE: why' (a file missing, made "
                              "from other card values or other inputs; drivers/chain.sh runs "
                              "these only); nothing when the case is up to date"}}};
  return sig::run_stage("sig-dump", [&] {
    // 1. Command line.
    sig::handle_help_and_version(argc, argv, help);
    const std::string usage = "usage: sig-dump " + help.usage;
    bool json = false, cards = false, cards_markdown = false, chain = false, stale = false;
    bool values_given = false;
    sig::DumpValues values;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--json") {
        json = true;
      } else if (arg == "--cards") {
        cards = true;
      } else if (arg == "--cards-markdown") {
        cards_markdown = true;
      } else if (arg == "--chain") {
        chain = true;
      } else if (arg == "--stale") {
        stale = true;
      } else if (arg == "--values") {
        values_given = values.all = true;
      } else if (arg.starts_with("--values=")) {
        values_given = true;
        std::istringstream list(arg.substr(9));
        for (std::string name; std::getline(list, name, ',');)
          if (!name.empty()) values.names.push_back(name);
        SIG_VERIFY(!values.names.empty(), "--values= needs array names (" << usage << ")");
      } else {
        SIG_VERIFY(!arg.starts_with("-"), usage);
        names.push_back(arg);
      }
    }

    // 2. The card schema: all cards, or the named ones; or all as Markdown.
    if (cards_markdown) {
      SIG_VERIFY(!cards && !json && !values_given && !chain && !stale && names.empty(), usage);
      std::cout << sig::card_reference_markdown();
      return;
    }
    if (cards) {
      SIG_VERIFY(!json && !values_given && !chain && !stale, usage);
      if (names.empty())
        std::cout << "Cards of the datafiles (sig-dump --cards CARD):\n" << sig::card_index();
      for (const std::string& name : names) {
        const sig::CardSpec* spec = sig::find_card_spec(name);
        SIG_VERIFY(spec != nullptr, "no card " << name << "; the cards are:\n"
                                               << sig::card_index());
        std::cout << sig::card_help(*spec);
      }
      return;
    }
    if (stale) {
      SIG_VERIFY(!json && !values_given && !chain && names.size() == 2, usage);
      const auto nopo_fingerprint = [](const std::filesystem::path& path) {
        return sig::read_nopo_file(path).fingerprint;
      };
      for (const sig::StaleStage& s :
           sig::stale_stages(sig::Datafile::read(names[0]), names[1], nopo_fingerprint))
        std::cout << s.stage << ": " << s.why << "\n";
      return;
    }
    SIG_VERIFY(names.size() == 1, usage);
    if (chain) {
      SIG_VERIFY(!json && !values_given, usage);
      for (const std::string& stage : sig::stage_chain(sig::Datafile::read(names.front())))
        std::cout << stage << "\n";
      return;
    }
    const std::filesystem::path file = names.front();
    SIG_VERIFY(json || !values_given, "--values needs --json (" << usage << ")");
    SIG_VERIFY(std::filesystem::exists(file), file.string() << ": no such file");

    // 3. A DS starts with its magic; anything else must be a NOPO mesh.
    if (sig::is_ds_file(file)) {
      const sig::Ds ds = sig::read_ds(file);
      // With values the JSON is written on one line: arrays of thousands of numbers.
      std::cout << (json ? sig::dump_ds_json(ds, values).dump(values_given ? -1 : 2) + "\n"
                         : sig::dump_ds_text(ds));
      return;
    }
    // A NOPO mesh: --values prints the mesh itself (coordinates, triangles, edges).
    SIG_VERIFY(values.names.empty(), file.string() << ": --values=NAMES is for DS files; a NOPO "
                                                      "mesh takes --values (the whole mesh)");
    const sig::NopoFile nopo = sig::read_nopo_file(file);
    const std::string& title = nopo.text.title;
    std::cout
        << (json ? sig::dump_mesh_json(nopo.mesh, title, values.all).dump(values_given ? -1 : 2) +
                       "\n"
                 : sig::dump_mesh_text(nopo.mesh, title));
  });
}
