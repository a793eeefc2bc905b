// sig-contact DATAFILE [-o OUTDIR]
// Reads the CONTACT and FRICTION cards and OUTDIR/case.nopo, builds the node-to-rigid contact
// elements (thesis Remark 3.1: a Gamma3 node + a Lagrange node each) and writes OUTDIR/case.cont.
// Without a CONTACT card there is no contact: nothing is written (a case.cont left by an earlier
// run of the same case is removed so later stages cannot pick it up) and the stage exits 0.
#include "contact/stage_main.hpp"

#include "contact/contact_elements.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "mesh/nopo.hpp"

#include <filesystem>
#include <iostream>

namespace sig {

int contact_main(int argc, char** argv) {
  const sig::StageHelp help{.name = "sig-contact",
                            .purpose = "Contact stage: builds the node-to-rigid contact elements "
                                       "(a Gamma3 node and a Lagrange node "
                                       "each, thesis Remark 3.1) of the CONTACT card: normal, "
                                       "tangent, initial gap, nodal weight "
                                       "and laws per node. Without a CONTACT card it writes "
                                       "nothing (and removes a case.cont of an "
                                       "earlier run).",
                            .reads = {"DATAFILE", "OUTDIR/case.nopo (sig-mesh)"},
                            .writes = {"OUTDIR/case.cont (contact elements)"},
                            .cards = sig::stage_cards("contact").cards};
  return sig::run_stage("sig-contact", [&] {
    // 1. Arguments, datafile and mesh.
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, help);
    const sig::Datafile& datafile = args.deck;
    const std::filesystem::path cont_path = args.ds_path("cont");

    // 2. Contact elements from the CONTACT card, if any.
    const sig::Mesh mesh = sig::read_nopo(args.ds_path("nopo"));
    const std::optional<sig::ContactElements> elements = sig::contact_from_cards(datafile, mesh);
    if (!elements) {
      std::cout << "sig-contact: no CONTACT card in " << args.datafile.string()
                << ": no contact, nothing written\n";
      if (std::filesystem::remove(cont_path))
        std::cout << "sig-contact: removed " << cont_path.string() << " of an earlier run\n";
      return;
    }

    // 3. Write the CONT DS and summarize; warn of an obstacle facing Gamma3 from inside.
    sig::write_cont(cont_path, *elements, datafile.title());
    const sig::ContactElements& e = *elements;
    if (const std::vector<int> away = sig::nodes_facing_away(mesh, e);
        2 * away.size() > e.node.size()) {
      const int i = away.front();
      sig::log_warning(std::to_string(away.size()) + " of " + std::to_string(e.size()) +
                       " contact nodes face the obstacle from inside the body (node " +
                       std::to_string(e.node[i] + 1) + " at " +
                       sig::coordinates(mesh.nodes[e.node[i]]) + ": the obstacle's normal " +
                       sig::coordinates(e.normal[i]) +
                       " points along the body's outward normal there); the CONTACT card's "
                       "normal= must point out of the obstacle, towards the body");
    }
    std::cout << "sig-contact: " << e.size() << " contact elements on reference " << e.ref << " ("
              << sig::describe(e.law.front()) << "; obstacle " << e.obstacle.kind << ")\n"
              << "  Lagrange nodes " << e.lagrange_node.front() + 1 << ".."
              << e.lagrange_node.back() + 1 << " after " << e.num_nodes << " mesh nodes\n"
              << "  gap min " << e.gap.minCoeff() << " max " << e.gap.maxCoeff() << "\n"
              << (e.dim == 3 ? "  total weight (Gamma3 area) "
                             : "  total weight (Gamma3 length x thickness) ")
              << e.weight.sum() << "\n"
              << "  wrote " << cont_path.string() << "\n";
  });
}

} // namespace sig
