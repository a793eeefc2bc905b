#include "stages/rank_rows.hpp"

#include "assembly/dirichlet.hpp"
#include "assembly/system.hpp"
#include "assembly/tae_parts.hpp"
#include "core/datafile.hpp"
#include "core/error.hpp"
#include "core/stage.hpp"
#include "mesh/mesh.hpp"
#include "solver/mpi_session.hpp"

#include <metis.h>

#include <algorithm>
#include <optional>

namespace sig {

std::vector<char> rows_of_rank(const Mesh& mesh) {
  const int ranks = mpi::size();
  SIG_VERIFY(mesh.num_cells() >= ranks && mesh.num_nodes() >= ranks,
             "a mesh of " << mesh.num_cells() << " " << mesh.cell_name() << "s and "
                          << mesh.num_nodes() << " nodes cannot be shared by " << ranks
                          << " ranks: run mpirun with at most "
                          << std::min(mesh.num_cells(), mesh.num_nodes()) << " ranks");
  std::vector<int> part(static_cast<std::size_t>(mesh.num_nodes()), 0);
  if (ranks > 1) {
    if (mpi::rank() == 0) {
      idx_t cells = mesh.num_cells(), nodes = mesh.num_nodes(), parts = ranks, cut = 0;
      std::vector<idx_t> first{0}, node;
      for (const Simplex& cell : mesh.cells) {
        node.insert(node.end(), cell.begin(), cell.end());
        first.push_back(static_cast<idx_t>(node.size()));
      }
      std::vector<idx_t> cell_part(static_cast<std::size_t>(cells)), node_part(part.size());
      idx_t options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      const int status =
          METIS_PartMeshNodal(&cells, &nodes, first.data(), node.data(), nullptr, nullptr, &parts,
                              nullptr, options, &cut, cell_part.data(), node_part.data());
      SIG_VERIFY(status == METIS_OK,
                 "METIS_PartMeshNodal failed (status " << status << ") on " << ranks << " parts");
      part.assign(node_part.begin(), node_part.end());
    }
    mpi::broadcast(part.data(), static_cast<int>(part.size()));
  }
  const int d = mesh.dim, me = mpi::rank();
  std::vector<char> owned(static_cast<std::size_t>(d) * part.size(), 0);
  for (std::size_t node = 0; node < part.size(); ++node)
    for (int c = 0; c < d; ++c)
      owned[static_cast<std::size_t>(d) * node + static_cast<std::size_t>(c)] = part[node] == me;
  return owned;
}

LinearSystem read_tae_of_rank(const std::filesystem::path& path, const Mesh& mesh, bool march) {
  if (!mpi::launched()) return read_tae(path);
  const std::vector<char> owned = rows_of_rank(mesh);
  if (const std::optional<TaeParts> parts = read_tae_index(path))
    return read_tae_part(path, *parts, mpi::rank(), mpi::size(), owned, march);
  return read_tae_rows(path, owned, march);
}

ReducedSystem reduce_on_ranks(const LinearSystem& system,
                              const std::vector<int>& imposed_elsewhere) {
  ReducedSystem reduced = reduce(system, imposed_elsewhere);
  if (system.rank_rows) mpi::sum(reduced.f.data(), static_cast<int>(reduced.f.size()));
  return reduced;
}

void require_mumps_under_mpirun(const Datafile& datafile, const std::string& backend) {
  if (backend == "mumps") return;
  const std::string why = "a stage under mpirun factorizes with MUMPS over its ranks: set SOLVER "
                          "linear=mumps (not " +
                          backend + ")";
  if (const Card* solver = datafile.find("SOLVER")) solver->fail("linear", why);
  throw InputError(datafile.path, 0, "linear", why);
}

std::string solver_words(const std::string& backend, const std::string& ordering, int ranks) {
  return backend + (ordering.empty() ? "" : ", ordering " + ordering) +
         (mpi::launched() ? ", " + std::to_string(ranks) + (ranks == 1 ? " rank" : " ranks") : "");
}

int run_stage_on_ranks(const std::string& stage, const std::function<void()>& body) {
  const bool distributed = mpi::launched();
  const int code = run_stage(stage, [&] {
    if (distributed) mpi::start();
    body();
  });
  if (code != 0 && distributed) mpi::abort(code);
  return code;
}

bool writes_outputs() {
  if (!mpi::launched()) return true;
  double done = 1;
  mpi::sum(&done, 1);
  return mpi::rank() == 0;
}

} // namespace sig
