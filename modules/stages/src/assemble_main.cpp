// sig-assemble DATAFILE [-o OUTDIR]: MODULEF's THENEW/ELASCT + assembly. Reads the mesh
// OUTDIR/case.nopo, the laws OUTDIR/case.mili and the DIRICHLET, TRACTION, PRESSURE and
// BODYFORCE cards; writes the stiffness, mass, loads and Dirichlet dofs to OUTDIR/case.tae.
// As P >= 2 ranks of mpirun each rank assembles the rows of its METIS part into its part
// OUTDIR/case.tae.r<rank>, and rank 0 writes the index OUTDIR/case.tae (assembly/tae_parts.hpp).
#include "stages/stage_mains.hpp"

#include "assembly/loads.hpp"
#include "assembly/system.hpp"
#include "assembly/tae_parts.hpp"
#include "core/datafile.hpp"
#include "core/log.hpp"
#include "core/phase_times.hpp"
#include "core/stage.hpp"
#include "core/stage_cards.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "mesh/nopo.hpp"
#include "solver/mpi_session.hpp"
#include "stages/rank_rows.hpp"

#include <cstdio>
#include <random>

namespace sig {

namespace {

/// The parts of this job's assembly: its ranks and a run rank 0 draws for all of them.
TaeParts parts_of_job() {
  int words[4] = {0, 0, 0, 0};
  if (mpi::rank() == 0) {
    std::random_device device;
    for (int& word : words)
      word = static_cast<int>(device() & 0x7fffffff);
  }
  mpi::broadcast(words, 4);
  char run[40];
  std::snprintf(run, sizeof run, "%08x%08x%08x%08x", words[0], words[1], words[2], words[3]);
  return {mpi::size(), run};
}

} // namespace

int assemble_main(int argc, char** argv) {
  const sig::StageHelp help{
      .name = "sig-assemble",
      .purpose = "Assembly stage (MODULEF's THENEW/ELASCT and assembly): P1 stiffness and mass "
                 "matrices, load vectors and Dirichlet dofs of the case.",
      .reads = {"DATAFILE", "OUTDIR/case.nopo (sig-mesh)", "OUTDIR/case.mili (sig-material)"},
      .writes = {"OUTDIR/case.tae (dof numbering, K, M, loads, Dirichlet dofs and values)",
                 "under mpirun -np P >= 2: OUTDIR/case.tae.r0 .. r<P-1> (each rank's rows of K, "
                 "M, its METIS part) and OUTDIR/case.tae their index (no matrix)"},
      .cards = sig::stage_cards("assemble").cards};
  return sig::run_stage_on_ranks("sig-assemble", [&] {
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

    // 2. Pattern, stiffness, mass, loads, Dirichlet dofs: under mpirun of the rows of this
    // rank's part (refused when the mesh has fewer cells than ranks).
    const bool parted = sig::mpi::launched() && sig::mpi::size() > 1;
    const std::vector<char> owned = parted ? sig::rows_of_rank(mesh) : std::vector<char>{};
    const sig::LinearSystem system = [&] {
      const sig::PhaseTimer timer("assemble");
      return sig::assemble_system(mesh, table, datafile, parted ? &owned : nullptr);
    }();

    // 3. Write the TAE, or this rank's part and, once every rank has written its own, the
    // index; report the size.
    const std::filesystem::path tae = args.ds_path("tae");
    double nnz = static_cast<double>(system.K.nonZeros());
    std::string parts_words;
    if (parted) {
      const sig::TaeParts parts = sig::parts_of_job();
      // Renamed into place once every rank's part is whole: a rank that dies before leaves the
      // case's parts as they were.
      sig::write_tae_part(tae, sig::mpi::rank(), parts, system, datafile.title(),
                          [&] { sig::mpi::sum(&nnz, 1); });
      if (!sig::writes_outputs()) return;
      sig::write_tae_index(tae, parts, system, datafile.title());
      sig::remove_tae_parts(tae, parts.ranks);
      parts_words = "  parts " + std::to_string(parts.ranks);
    } else {
      sig::write_tae(tae, system, datafile.title());
      sig::remove_tae_parts(tae, 0);
    }
    std::printf("dofs %d  nnz %ld  dirichlet %zu  mass %s  assembly %.3f s%s%s\n",
                system.num_dofs(), static_cast<long>(nnz), system.dirichlet_dofs.size(),
                system.M.size() > 0 ? "consistent" : "none", system.assemble_seconds,
                parts_words.c_str(), finite_strain ? "  (finite strain: K unused)" : "");
    sig::log_info("wrote " + tae.string() +
                  (parted ? " and its parts " + tae.filename().string() + ".r0 .. r" +
                                std::to_string(sig::mpi::size() - 1)
                          : ""));
  });
}

} // namespace sig
