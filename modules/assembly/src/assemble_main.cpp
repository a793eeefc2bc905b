// sig-assemble DATAFILE [-o OUTDIR]: MODULEF's THENEW/ELASCT + assembly. Reads the mesh
// OUTDIR/case.nopo, the laws OUTDIR/case.mili and the DIRICHLET, TRACTION, PRESSURE and
// BODYFORCE cards; writes the stiffness, mass, loads and Dirichlet dofs to OUTDIR/case.tae.
#include "assembly/stage_main.hpp"

#include "assembly/loads.hpp"
#include "assembly/system.hpp"
#include "core/datafile.hpp"
#include "core/log.hpp"
#include "core/phase_times.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nopo.hpp"

#include <cstdio>

namespace sig {

int assemble_main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-assemble",
      .purpose = "Assembly stage (MODULEF's THENEW/ELASCT and assembly): P1 stiffness and mass "
                 "matrices, load vectors and Dirichlet dofs of the case.",
      .reads = {"DATAFILE", "OUTDIR/case.nopo (sig-mesh)", "OUTDIR/case.mili (sig-material)"},
      .writes = {"OUTDIR/case.tae (dof numbering, K, M, loads, Dirichlet dofs and values)"},
      .cards = sig::stage_cards("assemble").cards};
  return sig::run_stage("sig-assemble", [&] {
    // 1. Command line and inputs.
    const sig::StageArgs args = sig::parse_stage_args(argc, argv, help);
    const sig::Datafile& datafile = args.deck;
    const sig::Mesh mesh = sig::read_nopo(args.ds_path("nopo"));
    const sig::MaterialTable table = sig::read_mili(args.ds_path("mili"));
    // A hyperelastic law is solved in large deformation by sig-solve (it reads the laws from the
    // MILI), which needs from here only the Dirichlet dofs and loads: K, the linearization at
    // u = 0, is then unused.
    bool finite_strain = false;
    for (const sig::SubdomainMaterial& entry : table.entries)
      finite_strain = finite_strain || entry.hyperelastic != nullptr;
    // The large-deformation solve and march hold their loads constant (sig-solve refuses ramp=
    // as any static solve): a ramped load would be dropped without a word.
    if (const sig::Card* ramped = sig::ramped_load_card(datafile); ramped && finite_strain)
      ramped->fail("ramp", "a hyperelastic body (large deformation) holds its loads constant in "
                           "time: remove ramp= (ramped loads serve the linear and the "
                           "viscoelastic marches)");

    // 2. Pattern, stiffness, mass, loads, Dirichlet dofs.
    const sig::LinearSystem system = [&] {
      const sig::PhaseTimer timer("assemble");
      return sig::assemble_system(mesh, table, datafile);
    }();

    // 3. Write the TAE and report its size.
    sig::write_tae(args.ds_path("tae"), system, datafile.title());
    std::printf("dofs %d  nnz %ld  dirichlet %zu  mass %s  assembly %.3f s%s\n", system.num_dofs(),
                static_cast<long>(system.K.nonZeros()), system.dirichlet_dofs.size(),
                system.M.size() > 0 ? "consistent" : "none", system.assemble_seconds,
                finite_strain ? "  (finite strain: K unused)" : "");
    sig::log_info("wrote " + args.ds_path("tae").string());
  });
}

} // namespace sig
