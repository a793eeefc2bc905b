#pragma once
// What MUMPS reports of its last factorization: the work and memory of the elimination over all
// ranks (INFOG, RINFOG) and each rank's share (INFO, RINFO), recorded in case.b and
// summary.json for a measure of a distributed solve (drivers/bench-mpi.sh).
#include <vector>

namespace sig {

struct MumpsStatistics {
  double flops = 0;           ///< RINFOG(3): flops of the elimination, all ranks
  double flops_estimate = 0;  ///< RINFOG(1): the analysis's estimate of them
  double factor_entries = 0;  ///< INFOG(29): entries of the factors, all ranks
  double factor_space = 0;    ///< INFOG(9): reals allocated for the factors, all ranks
  double largest_front = 0;   ///< INFOG(11): order of the largest frontal matrix
  double tree_nodes = 0;      ///< INFOG(6): nodes (fronts) of the elimination tree
  double delayed_pivots = 0;  ///< INFOG(13): eliminations postponed for stability
  double memory_max_mb = 0;   ///< INFOG(21): memory the factorization used on its largest rank
  double memory_total_mb = 0; ///< INFOG(22): ... summed over the ranks
  double schur_size = 0;      ///< order of the Schur complement (ICNTL(19)): the contact unknowns
  /// Wall seconds of the last analysis (ordering and symbolic factorization, on the host: the
  /// graph gathered there), a part of every factorization time the stages report.
  double analysis_seconds = 0;
  /// Per rank, rank 0 (the host, which holds the Schur complement) first: RINFO(3) flops,
  /// INFO(27) factor entries, INFO(22) MB used, INFO(23) pivots eliminated.
  std::vector<double> rank_flops, rank_entries, rank_memory_mb, rank_pivots;
};

} // namespace sig
