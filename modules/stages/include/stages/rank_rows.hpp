#pragma once
// The rows of the stiffness matrix that one rank of `mpirun -np P sig-solve` (or sig-march)
// holds: the mesh's nodes partitioned by METIS (on the node graph, METIS_PartMeshNodal), every
// dof of a node with its node, so that the frames of a contact node turn rows of one rank; and
// what a distributed stage does with them beside the factorization.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sig {

class Datafile;
struct LinearSystem;
struct Mesh;
struct ReducedSystem;

/// Per dof (d per node, d node + component) whether this rank (solver/mpi_session.hpp) holds its
/// row. Rank 0 partitions, the others receive its partition: every rank sees the same one.
/// sig::Error when the mesh has fewer cells or nodes than there are ranks.
std::vector<char> rows_of_rank(const Mesh& mesh);

/// The TAE at `path` as this process holds it: whole (read_tae) in a process mpirun did not
/// start; a rank's rows of the mesh's partition (rows_of_rank) in one it did, streamed off a
/// whole TAE (read_tae_rows) or read from the rank's part when `path` is the index of a
/// distributed assembly (read_tae_part, assembly/tae_parts.hpp).
/// `march`: with the march's matrices and time loads (read_tae_rows).
LinearSystem read_tae_of_rank(const std::filesystem::path& path, const Mesh& mesh,
                              bool march = false);

/// reduce(system, imposed_elsewhere) (assembly/dirichlet.hpp) with its load f_f - K_fd u_d whole
/// on every rank: where the system holds a rank's rows (read_tae_rows) each rank's part is that
/// of its rows, summed over the ranks (a collective call).
ReducedSystem reduce_on_ranks(const LinearSystem& system,
                              const std::vector<int>& imposed_elsewhere = {});

/// An InputError on the SOLVER card's linear= (or the deck) unless `backend` is mumps: a stage
/// under mpirun factorizes with MUMPS over its ranks.
void require_mumps_under_mpirun(const Datafile& datafile, const std::string& backend);

/// "mumps, ordering amd, 2 ranks" for a stage's log line: the backend, MUMPS's ordering where it
/// has one, and under mpirun the ranks.
std::string solver_words(const std::string& backend, const std::string& ordering, int ranks);

/// run_stage (core/stage.hpp) for a stage that may run as a rank of an mpirun job: there MPI
/// starts before `body`, so that a failure in it can end the job, and a non-zero exit ends every
/// rank (MPI_Abort: the others may wait in a collective call of MUMPS).
int run_stage_on_ranks(const std::string& stage, const std::function<void()>& body);

/// Whether this process writes the stage's files: the host (rank 0) of an mpirun job once every
/// rank has come here (a collective call: a rank that failed has aborted the job before, so the
/// host never renames a file into place while another rank fails), or a process alone.
bool writes_outputs();

} // namespace sig
