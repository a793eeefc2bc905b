#pragma once
// The TAE of a distributed assembly (`mpirun -np P sig-assemble`, P >= 2): each rank writes the
// rows of its METIS part (stages/rank_rows.hpp) to its own part, OUTDIR/case.tae.r<K> (K = 0 ..
// P - 1, DS kind TAEP), and rank 0 writes the index, OUTDIR/case.tae (kind TAE): no matrix, the
// vectors of the whole body (what sig-post reads of a TAE) and the number of parts. No process
// holds the whole matrix, and a rank of the solve or the march reads its part alone.
//
// A part carries its stamp: its rank, the number of ranks and the run (an identifier the
// assembly draws once and every part and the index share); the index carries the number of
// parts and the run. A reader refuses, naming the file, a part of another run or of another
// number of ranks, a missing part, and a job of another size than the index's; the mesh and the
// materials are checked as for any DS, on the index (core/provenance.hpp). One process writes
// and reads the whole TAE as ever (assembly/system.hpp).
//
//   part   part_rank, part_ranks, part_run (Text), then the arrays of a TAE: ndof, K_rowptr
//          (ndof + 1: the rows of other ranks empty), K_col, K_val (and M_val, V_val,
//          memory_beta, memory_val: the same rows) and the vectors of the whole body
//   index  ndof, parts, part_run, files (the parts' names, one a line), f_rate, M_lumped, f,
//          dirichlet_dof, dirichlet_value, time_assemble, moving_*
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sig {

struct LinearSystem;

/// What binds the parts of one distributed assembly.
struct TaeParts {
  int ranks = 1;   ///< the number of parts
  std::string run; ///< drawn once by the assembly, in every part and in the index
};

/// OUTDIR/case.tae.r<rank> of OUTDIR/case.tae.
std::filesystem::path tae_part_path(const std::filesystem::path& tae, int rank);

/// The part of `rank`: `rows`, the system of its rows (assemble_system with owned rows), beside
/// the index `tae`. `before_rename` runs once the part is whole under its temporary name
/// (write_ds): there a rank waits for the others, so that no part is renamed into place unless
/// every rank has written its own.
void write_tae_part(const std::filesystem::path& tae, int rank, const TaeParts& parts,
                    const LinearSystem& rows, const std::string& title,
                    const std::function<void()>& before_rename = {});

/// The index `tae` of the parts: `system`'s vectors (its matrices are not written).
void write_tae_index(const std::filesystem::path& tae, const TaeParts& parts,
                     const LinearSystem& system, const std::string& title);

/// Remove the parts of rank `first` and above beside `tae` (those of an earlier assembly on more
/// ranks, or all of them, first = 0, once one process wrote the whole TAE): a case holds the
/// parts its index names, no others.
void remove_tae_parts(const std::filesystem::path& tae, int first);

/// Of a TAE, its parts when it is an index, none when it holds the whole system.
std::optional<TaeParts> read_tae_index(const std::filesystem::path& tae);

/// The system of this rank as read_tae_rows gives it of a whole TAE, from the part of `rank`
/// beside the index `tae` whose parts are `parts`; sig::Error naming the file when this job's
/// `ranks` are not the index's, the part is missing or stamped by another run, rank or number
/// of ranks, or its rows are not `owned`.
LinearSystem read_tae_part(const std::filesystem::path& tae, const TaeParts& parts, int rank,
                           int ranks, const std::vector<char>& owned, bool march);

} // namespace sig
