// sig-refine: the mark and refine steps of the adaptive loop (drivers/adapt.sh): Dörfler's
// marking of the indicators of sig-estimate (post/dorfler.hpp), then the conforming
// longest-edge bisection of the marked triangles (mesh/bisection.hpp), references and
// sub-domains kept, new nodes of a generator's arcs on the true circle.
//
//   sig-refine DATAFILE [-o OUTDIR] [--theta T] [--shape DECK] [--mesh FILE]
//
// Reads OUTDIR/case.nopo and case.est (checked to belong to the deck and to each other) and
// writes the refined mesh to FILE (default OUTDIR/refined.nopo), for a deck whose MESH card
// says file=FILE. The arcs are those of the MESH card of DECK (default DATAFILE): the adaptive
// loop's later decks read a mesh file, and the first deck's generator knows the circles. A
// refinement beyond the mesh size limit (1e8 nodes) is refused.
#include "post/stage_mains.hpp"

#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "mesh/bisection.hpp"
#include "mesh/mesh_card.hpp"
#include "mesh/nopo.hpp"
#include "post/dorfler.hpp"

#include <iostream>
#include <string>
#include <vector>

namespace {

/// The value of option `name` in argv, removed from it, or `fallback`.
std::string take_option(std::vector<char*>& args, const std::string& name,
                        const std::string& fallback) {
  for (std::size_t i = 1; i < args.size(); ++i)
    if (args[i] == name) {
      SIG_VERIFY(i + 1 < args.size(), name << " needs a value");
      const std::string value = args[i + 1];
      args.erase(args.begin() + static_cast<std::ptrdiff_t>(i),
                 args.begin() + static_cast<std::ptrdiff_t>(i + 2));
      return value;
    }
  return fallback;
}

double parse_theta(const std::string& text) {
  std::size_t used = 0;
  double theta = 0;
  try {
    theta = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  SIG_VERIFY(used == text.size() && theta > 0 && theta <= 1,
             "--theta " << text << ": expected a number in (0, 1]");
  return theta;
}

} // namespace

namespace sig {

int refine_main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-refine",
      .purpose = "Mark and refine: Dörfler's marking of sig-estimate's indicators (the fewest "
                 "largest eta_T carrying theta of eta^2), then the conforming longest-edge "
                 "bisection of the marked triangles (each cut into 4, plus the closure), "
                 "references and sub-domains kept, new nodes of a generator's arcs on the circle.",
      .reads = {"DATAFILE", "OUTDIR/case.nopo", "OUTDIR/case.est (sig-estimate)",
                "DECK of --shape (its MESH card)"},
      .writes = {"FILE of --mesh (default OUTDIR/refined.nopo) and FILE.prov"},
      .cards = sig::stage_cards("refine").cards,
      .usage = "DATAFILE [-o OUTDIR] [--theta T] [--shape DECK] [--mesh FILE]",
      .options = {{"--theta T", "Dörfler's fraction in (0, 1] (default 0.5)"},
                  {"--shape DECK", "the deck whose MESH generator gives the curved boundary "
                                   "(default DATAFILE)"},
                  {"--mesh FILE", "where the refined mesh goes (default OUTDIR/refined.nopo)"}}};
  return sig::run_stage("sig-refine", [&] {
    // 1. Command line: our options first, the stage's own after.
    sig::handle_help_and_version(argc, argv, help);
    std::vector<char*> args(argv, argv + argc);
    const double theta = parse_theta(take_option(args, "--theta", "0.5"));
    const std::string shape = take_option(args, "--shape", "");
    const std::string mesh_file = take_option(args, "--mesh", "");
    const sig::StageArgs stage =
        sig::parse_stage_args(static_cast<int>(args.size()), args.data(), help);

    // 2. The mesh, its indicators and the circles of its curved boundary.
    const sig::Mesh mesh = sig::read_nopo(stage.ds_path("nopo"));
    const sig::Ds est = sig::read_ds(stage.ds_path("est"), "EST");
    const std::vector<double> eta = est.reals("indicator");
    SIG_VERIFY(eta.size() == mesh.cells.size(),
               est.source << ": " << eta.size() << " indicators for " << mesh.num_cells()
                          << " triangles of " << stage.ds_path("nopo").string());
    const sig::Datafile shape_deck =
        shape.empty() ? stage.deck : sig::Datafile::read(std::filesystem::path(shape));
    const std::vector<sig::BoundaryArc> arcs = sig::boundary_arcs(shape_deck.require("MESH"));

    // 3. Mark, refine (timed, the files' reading and writing left out: the adaptive loop's
    //    cost is counted stage by stage), write.
    const sig::Stopwatch clock;
    const std::vector<int> marked = sig::dorfler_marking(eta, theta);
    const sig::Bisection refined = sig::bisect(mesh, marked, arcs);
    const double seconds = clock.seconds();
    const std::filesystem::path out =
        mesh_file.empty() ? stage.outdir / "refined.nopo" : std::filesystem::path(mesh_file);
    sig::write_nopo(out, refined.mesh, sig::NopoVariant::i8r8, stage.deck.title(), "sig-refine");
    std::cout << "sig-refine: marked " << marked.size() << " of " << mesh.num_cells()
              << " triangles (theta " << theta << "), " << refined.bisected_edges
              << " edges bisected: " << refined.mesh.num_nodes() << " nodes, "
              << refined.mesh.num_cells() << " triangles, " << arcs.size() << " arcs -> "
              << out.string() << "; mark and refine " << seconds << " s\n";
  });
}

} // namespace sig
