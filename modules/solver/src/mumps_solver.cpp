#include "solver/mumps_solver.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "core/stage.hpp"
#include "solver/mpi_session.hpp"

#include <dmumps_c.h>
#include <metis.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace sig {

namespace {

constexpr int job_init = -1;
constexpr int job_end = -2;
constexpr int job_analyze = 1;
constexpr int job_factorize = 2;
constexpr int job_solve = 3;
constexpr int max_workspace_retries = 6;
// ICNTL(7): AMD up to this many unknowns, MUMPS's automatic choice above (Scotch here: Debian's
// MUMPS has no METIS). On the 2D Newton matrices of the ring (scene 7b) AMD's analysis costs
// 7 ms against Scotch's 50 ms at 25554 unknowns and 31 ms against 135 ms at 100258, for a
// factorization + solve as fast (33 ms; 200 ms for 17 % more flops); nested dissection's
// smaller fill pays beyond a few 1e5 unknowns.
constexpr int amd_max_unknowns = 200000;
// ... and only on rows of a 2D P1 mesh: denser rows (3D) take the automatic choice (nested
// dissection) at any size (nested_dissection_entries_per_row, solver/linear_solver.hpp).
constexpr int ordering_amd = 0;
constexpr int ordering_automatic = 7;

// ICNTL(7) = 1: the pivot order given in PERM_IN.
constexpr int ordering_given = 1;

/// METIS's nested dissection of the graph of the interior (every variable but the Schur ones) of
/// the n x n pattern whose entries are at the 1-based (irn[k], jcn[k]) (either triangle, or
/// both), the Schur variables after it, as MUMPS's PERM_IN (PERM_IN(i) = the position of
/// variable i, 1-based). With a Schur complement MUMPS 5.5 takes AMD whatever ICNTL(7) asks of its
/// own orderings (README, "Ordering"), whose fill on 3D rows is several times nested dissection's.
std::vector<int> nested_dissection_order(int n, const std::vector<int>& irn,
                                         const std::vector<int>& jcn,
                                         const std::vector<int>& schur_dofs) {
  std::vector<int> interior(static_cast<std::size_t>(n), -1); // variable -> interior vertex
  std::vector<char> schur(static_cast<std::size_t>(n), 0);
  for (int d : schur_dofs)
    schur[static_cast<std::size_t>(d)] = 1;
  int vertices = 0;
  for (int i = 0; i < n; ++i)
    if (!schur[static_cast<std::size_t>(i)]) interior[static_cast<std::size_t>(i)] = vertices++;
  // The symmetric adjacency of the interior from whichever triangle the entries cover.
  std::vector<std::vector<idx_t>> adjacency(static_cast<std::size_t>(vertices));
  for (std::size_t k = 0; k < irn.size(); ++k) {
    const int a = interior[static_cast<std::size_t>(irn[k] - 1)];
    const int b = interior[static_cast<std::size_t>(jcn[k] - 1)];
    if (a < 0 || b < 0 || a == b) continue;
    adjacency[static_cast<std::size_t>(a)].push_back(b);
    adjacency[static_cast<std::size_t>(b)].push_back(a);
  }
  std::vector<idx_t> xadj{0}, adjncy;
  for (auto& row : adjacency) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    adjncy.insert(adjncy.end(), row.begin(), row.end());
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
  }
  idx_t nv = vertices;
  std::vector<idx_t> perm(static_cast<std::size_t>(vertices)),
      iperm(static_cast<std::size_t>(vertices));
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  SIG_VERIFY(vertices == 0 || METIS_NodeND(&nv, xadj.data(), adjncy.data(), nullptr, options,
                                           perm.data(), iperm.data()) == METIS_OK,
             "MUMPS: METIS_NodeND failed on " << vertices << " interior variables");
  std::vector<int> position(static_cast<std::size_t>(n));
  int next_schur = vertices;
  for (int i = 0; i < n; ++i) {
    const int v = interior[static_cast<std::size_t>(i)];
    position[static_cast<std::size_t>(i)] =
        1 + (v >= 0 ? static_cast<int>(iperm[static_cast<std::size_t>(v)]) : next_schur++);
  }
  return position;
}

int sym_of(MatrixKind kind) {
  switch (kind) {
  case MatrixKind::spd:
    return 1;
  case MatrixKind::symmetric:
    return 2;
  case MatrixKind::general:
    return 0;
  }
  return 0;
}

bool workspace_shortage(int infog1) {
  return infog1 == -8 || infog1 == -9 || infog1 == -14 || infog1 == -15;
}

std::string error_text(int infog1) {
  switch (infog1) {
  case -6:
    return "structurally singular matrix";
  case -10:
    return "numerically singular matrix";
  case -13:
    return "allocation failed";
  case -8:
  case -9:
  case -14:
  case -15:
    return "workspace too small";
  case -16:
    return "N out of range";
  case -22:
    return "invalid array pointer";
  case -40:
    return "matrix declared positive definite is not";
  default:
    return "see the MUMPS user guide, section 8";
  }
}

// MUMPS's counts of entries overflow a 32-bit INFO as a negative number of millions.
double entry_count(int value) {
  return value < 0 ? -1e6 * value : value;
}

// SIG_MUMPS_ANALYSIS=FILE: the analysis's estimates of the factorization, appended to FILE as one
// tab-separated line, and the stage stopped there (exit 0, nothing written: StageExit passes the
// contact zone's retries, which catch sig::Error). It sizes a benchmark's problem
// (drivers/bench-mpi.sh --analysis-only) without the factorization of a problem that may not fit.
const char* analysis_only_file() {
  const char* file = std::getenv("SIG_MUMPS_ANALYSIS");
  return file != nullptr && *file != '\0' ? file : nullptr;
}

} // namespace

struct MumpsSolver::State {
  DMUMPS_STRUC_C id{};
  MatrixKind kind;
  bool rank_rows = false; ///< every rank of MPI_COMM_WORLD gives its rows (ICNTL(18) = 3)
  std::vector<int> schur_dofs;
  std::vector<int> listvar_schur; ///< 1-based copy handed to MUMPS
  std::vector<int> perm_in;       ///< a given pivot order (ICNTL(7) = 1), 1-based positions
  std::vector<double> schur;      ///< m x m, column-major, filled by the factorization
  std::vector<int> irn, jcn;      ///< 1-based coordinates of the entries passed (lower for SYM > 0)
  std::vector<double> a;
  /// For every entry of `a`, its rank among the Eigen matrix's stored entries, which is its
  /// offset in the value array of the compressed matrix: factorize() refills `a` by a gather, a
  /// pass over the lower triangle alone for SYM > 0.
  std::vector<int> source;
  std::uint64_t pattern = 0; ///< fingerprint of the analyzed pattern
  bool analyzed = false;
  bool factorized = false;
  /// Between reduce() and expand(): MUMPS's right side after the forward elimination, which the
  /// backward substitution continues from, and the reduced right side.
  std::vector<double> reduced_rhs, redrhs;
  MumpsStatistics statistics; ///< of the last factorization

  int& icntl(int i) { return id.icntl[i - 1]; }
  int infog(int i) const { return id.infog[i - 1]; }
  int info(int i) const { return id.info[i - 1]; }

  /// The factorization's statistics: INFOG and RINFOG are the same on every rank; each rank's
  /// INFO and RINFO are summed into its own slot of the per-rank arrays (a gather by sum).
  void record_statistics() {
    MumpsStatistics& st = statistics;
    st.flops = id.rinfog[2];
    st.flops_estimate = id.rinfog[0];
    st.factor_entries = entry_count(infog(29));
    st.factor_space = entry_count(infog(9));
    st.largest_front = infog(11);
    st.tree_nodes = infog(6);
    st.delayed_pivots = infog(13);
    st.memory_max_mb = infog(21);
    st.memory_total_mb = infog(22);
    st.schur_size = double(schur_dofs.size());
    const int ranks = rank_rows ? mpi::size() : 1;
    const auto own = static_cast<std::size_t>(rank_rows ? mpi::rank() : 0);
    constexpr std::size_t fields = 4;
    std::vector<double> gathered(fields * static_cast<std::size_t>(ranks), 0.0);
    double* mine = gathered.data() + fields * own;
    mine[0] = id.rinfo[2];
    mine[1] = entry_count(info(27));
    mine[2] = info(22);
    mine[3] = info(23);
    if (rank_rows) mpi::sum(gathered.data(), static_cast<int>(gathered.size()));
    std::vector<double>* per_rank[fields] = {&st.rank_flops, &st.rank_entries, &st.rank_memory_mb,
                                             &st.rank_pivots};
    for (std::size_t f = 0; f < fields; ++f) {
      per_rank[f]->resize(static_cast<std::size_t>(ranks));
      for (std::size_t r = 0; r < per_rank[f]->size(); ++r)
        (*per_rank[f])[r] = gathered[fields * r + f];
    }
  }

  void call(int job) {
    id.job = job;
    dmumps_c(&id);
  }
  /// The host's `count` values at v on every rank: MUMPS leaves centralized results (the
  /// solution, the Schur complement, the reduced right side) on the host alone.
  void share(double* v, std::size_t count) const {
    if (rank_rows) mpi::broadcast(v, static_cast<int>(count));
  }
  /// One half of a solve split around the Schur problem (ICNTL(26) = phase) on reduced_rhs and
  /// redrhs.
  void schur_solve(int phase, const char* what) {
    id.nrhs = 1;
    id.lrhs = id.n;
    id.rhs = reduced_rhs.data();
    id.redrhs = redrhs.data();
    id.lredrhs = static_cast<int>(redrhs.size());
    icntl(20) = 0;
    icntl(21) = 0;
    icntl(26) = phase;
    call(job_solve);
    id.rhs = nullptr;
    id.redrhs = nullptr;
    icntl(26) = 0;
    verify(what);
    share(phase == 1 ? redrhs.data() : reduced_rhs.data(),
          phase == 1 ? redrhs.size() : reduced_rhs.size());
  }
  /// The analysis's estimates (host's view, every rank's alike) appended to `file`: the order,
  /// the Schur variables, the ordering (INFOG(7)), the seconds, RINFOG(1) flops, INFOG(20)
  /// factor entries, INFOG(5) the largest front, INFOG(6) the tree's nodes, INFOG(16)/INFOG(17)
  /// the in-core MB of the largest rank / of all.
  void append_analysis_estimates(const char* file) const {
    if (rank_rows && mpi::rank() != 0) return;
    std::FILE* out = std::fopen(file, "a");
    SIG_VERIFY(out != nullptr, "SIG_MUMPS_ANALYSIS: cannot append to " << file);
    std::fprintf(out, "%d\t%zu\t%d\t%.3f\t%.17g\t%.17g\t%d\t%d\t%d\t%d\n", id.n, schur_dofs.size(),
                 infog(7), statistics.analysis_seconds, id.rinfog[0], entry_count(infog(20)),
                 infog(5), infog(6), infog(16), infog(17));
    std::fclose(out);
  }
  /// PERM_IN and ICNTL(7) = 1 from METIS's nested dissection of the entries passed (the lower
  /// triangle for SYM > 0). Over the ranks the host orders the whole, each rank's entries
  /// gathered (two ints, 8 bytes an entry on the host, freed before the analysis); MUMPS reads
  /// PERM_IN on the host alone.
  void give_nested_dissection_order() {
    if (rank_rows) {
      std::vector<int> rows = mpi::gather(irn), columns = mpi::gather(jcn);
      if (mpi::rank() == 0) perm_in = nested_dissection_order(id.n, rows, columns, schur_dofs);
    } else {
      perm_in = nested_dissection_order(id.n, irn, jcn, schur_dofs);
    }
    id.perm_in = perm_in.empty() ? nullptr : perm_in.data();
    icntl(7) = ordering_given;
  }
  void verify(const char* phase) const {
    SIG_VERIFY(infog(1) >= 0, "MUMPS: " << phase << " failed: INFOG(1) = " << infog(1)
                                        << ", INFOG(2) = " << infog(2) << " ("
                                        << error_text(infog(1)) << ")");
  }
};

MumpsSolver::MumpsSolver(MatrixKind kind, std::vector<int> schur_dofs, bool rank_rows)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.kind = kind;
  s.rank_rows = rank_rows;
  s.schur_dofs = std::move(schur_dofs);
  SIG_VERIFY(std::is_sorted(s.schur_dofs.begin(), s.schur_dofs.end()) &&
                 std::adjacent_find(s.schur_dofs.begin(), s.schur_dofs.end()) == s.schur_dofs.end(),
             "MUMPS: Schur variables must be sorted and distinct");
  s.id.par = 1;
  s.id.sym = sym_of(kind);
  // Every rank of the job, each giving its rows; else this process alone, whether a plain one
  // (an MPI singleton) or one rank of an mpirun job whose every rank solves its own system.
  s.id.comm_fortran = rank_rows ? mpi::world_fortran() : mpi::self_fortran();
  s.call(job_init);
  s.verify("initialization");
  // Failures come back as exceptions with INFOG(1); nothing is printed.
  s.icntl(1) = -1;
  s.icntl(2) = -1;
  s.icntl(3) = -1;
  s.icntl(4) = 0;
}

MumpsSolver::~MumpsSolver() {
  state_->call(job_end);
}

void MumpsSolver::analyze(const Eigen::SparseMatrix<double>& A) {
  SIG_VERIFY(A.rows() == A.cols(),
             "MUMPS: matrix is " << A.rows() << " x " << A.cols() << ", not square");
  State& s = *state_;
  s.analyzed = false;
  s.factorized = false;
  const bool lower_only = s.id.sym != 0;
  s.irn.clear();
  s.jcn.clear();
  s.a.clear();
  s.source.clear();
  int k = 0;
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it, ++k) {
      if (lower_only && it.row() < j) continue;
      s.source.push_back(k);
      s.irn.push_back(static_cast<int>(it.row()) + 1);
      s.jcn.push_back(j + 1);
      s.a.push_back(it.value());
    }
  s.id.n = static_cast<int>(A.rows());
  // The entries of the whole matrix, for the choice of ordering: a rank holds only its rows'.
  double entries = double(A.nonZeros());
  if (s.rank_rows) {
    // Distributed assembled input: MUMPS sums what the ranks give, (i, j) and (j, i) alike for
    // SYM > 0, so each entry of the lower triangle comes from the one rank holding its row.
    s.icntl(18) = 3;
    s.id.nnz_loc = static_cast<MUMPS_INT8>(s.a.size());
    s.id.irn_loc = s.irn.data();
    s.id.jcn_loc = s.jcn.data();
    s.id.a_loc = s.a.data();
    mpi::sum(&entries, 1);
  } else {
    s.id.nnz = static_cast<MUMPS_INT8>(s.a.size());
    s.id.irn = s.irn.data();
    s.id.jcn = s.jcn.data();
    s.id.a = s.a.data();
  }

  const int m = static_cast<int>(s.schur_dofs.size());
  if (m > 0) {
    SIG_VERIFY(s.schur_dofs.back() < A.rows(),
               "MUMPS: Schur variable " << s.schur_dofs.back() << " out of range");
    s.listvar_schur.resize(s.schur_dofs.size());
    std::transform(s.schur_dofs.begin(), s.schur_dofs.end(), s.listvar_schur.begin(),
                   [](int d) { return d + 1; });
    // ICNTL(19) = 3 on a 1 x 1 process grid: the Schur complement returned centralized, by
    // columns, in a user array (the MUMPS guide's recommended centralized form). Over several
    // ranks that grid's process need not be the host: ICNTL(19) = 1 returns it on the host, by
    // rows (schur_complement() mirrors its lower triangle).
    s.icntl(19) = s.rank_rows ? 1 : 3;
    s.id.size_schur = m;
    s.id.listvar_schur = s.listvar_schur.data();
    s.id.nprow = 1;
    s.id.npcol = 1;
    s.id.mblock = 100;
    s.id.nblock = 100;
  }
  const bool rows_3d = entries > nested_dissection_entries_per_row * double(A.rows());
  const bool amd = A.rows() <= amd_max_unknowns && !rows_3d;
  s.icntl(7) = amd ? ordering_amd : ordering_automatic;
  // With a Schur complement, on 3D rows: METIS's nested dissection given as PERM_IN (MUMPS would
  // take AMD), the same order in one process and over the ranks. On 2D rows AMD stays, even
  // beyond amd_max_unknowns: on the 2D Hertz of 1.5e6 unknowns METIS's order cut the flops by 3
  // but took 10 s to compute, and the factorize phase took 33 s against AMD's 23 s (README,
  // "Ordering"); on the 3D ball of 1e5 unknowns it takes 0.7 s and saves 17 s.
  if (rows_3d && m > 0) s.give_nested_dissection_order();
  const Stopwatch clock;
  s.call(job_analyze);
  s.statistics.analysis_seconds = clock.seconds();
  s.verify("analysis");
  if (const char* file = analysis_only_file()) {
    s.append_analysis_estimates(file);
    log_info(std::string("MUMPS: stopped after the analysis, as SIG_MUMPS_ANALYSIS asks "
                         "(estimates in ") +
             file + ")");
    throw StageExit{0};
  }
  s.pattern = pattern_fingerprint(A);
  s.analyzed = true;
}

void MumpsSolver::factorize(const Eigen::SparseMatrix<double>& A) {
  State& s = *state_;
  if (!s.analyzed || s.pattern != pattern_fingerprint(A)) analyze(A);
  s.factorized = false;
  // An uncompressed matrix (no caller of ours passes one) is compressed in a copy first.
  Eigen::SparseMatrix<double> compressed;
  if (!A.isCompressed()) {
    compressed = A;
    compressed.makeCompressed();
  }
  const double* values = A.isCompressed() ? A.valuePtr() : compressed.valuePtr();
  for (std::size_t i = 0; i < s.source.size(); ++i)
    s.a[i] = values[s.source[i]];
  (s.rank_rows ? s.id.a_loc : s.id.a) = s.a.data();

  const int m = static_cast<int>(s.schur_dofs.size());
  if (m > 0) {
    s.schur.assign(static_cast<size_t>(m) * static_cast<size_t>(m), 0.0);
    s.id.schur = s.schur.data();
    s.id.schur_lld = m;
  }
  s.call(job_factorize);
  for (int retry = 0; retry < max_workspace_retries && workspace_shortage(s.infog(1)); ++retry) {
    // The analysis underestimated the frontal workspace (delayed pivots): relax and retry.
    s.icntl(14) = std::max(2 * s.icntl(14), 40);
    s.call(job_factorize);
  }
  if (s.infog(1) == -10) // numerically singular
    throw FactorizationFailure("MUMPS: numeric factorization failed: INFOG(1) = -10 (" +
                               error_text(-10) + ")");
  s.verify("numeric factorization");
  // SYM = 1 factorizes LDL^T without pivoting: a matrix that is not positive definite may
  // still factorize, and only the count of negative pivots tells.
  if (s.kind == MatrixKind::spd && s.infog(12) > 0)
    throw FactorizationFailure("MUMPS: matrix declared positive definite is not: INFOG(12) = " +
                               std::to_string(s.infog(12)) + " negative pivots");
  if (m > 0) s.share(s.schur.data(), s.schur.size());
  s.record_statistics();
  s.factorized = true;
}

Eigen::VectorXd MumpsSolver::solve(const Eigen::VectorXd& b) const {
  // In place in the copy returned: through solve(MatrixXd) b was copied into a matrix, again
  // for MUMPS to overwrite, and the solution out of it, three vectors per Newton iteration.
  Eigen::VectorXd x = b;
  solve_in_place(x.data(), static_cast<int>(x.rows()), 1);
  return x;
}

Eigen::MatrixXd MumpsSolver::solve(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X = B;
  solve_in_place(X.data(), static_cast<int>(X.rows()), static_cast<int>(X.cols()));
  return X;
}

void MumpsSolver::solve_in_place(double* x, int rows, int columns) const {
  State& s = *state_;
  SIG_VERIFY(s.factorized, "MUMPS: solve before a successful factorize");
  SIG_VERIFY(rows == s.id.n, "MUMPS: right side has " << rows << " rows, matrix " << s.id.n);
  if (columns == 0) return;
  s.id.nrhs = columns;
  s.id.lrhs = s.id.n;
  s.id.rhs = x;    // MUMPS overwrites the right sides with the solutions
  s.icntl(20) = 0; // dense right sides
  s.icntl(21) = 0; // centralized solution
  s.icntl(26) = 0; // with a Schur complement: interior problem only, x_c = 0
  s.call(job_solve);
  s.id.rhs = nullptr;
  s.verify("solve");
  s.share(x, static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
}

Eigen::VectorXd MumpsSolver::reduce(const Eigen::VectorXd& b) const {
  State& s = *state_;
  const int m = static_cast<int>(s.schur_dofs.size());
  SIG_VERIFY(s.factorized && m > 0, "MUMPS: reduce needs a factorization with Schur variables");
  SIG_VERIFY(b.size() == s.id.n,
             "MUMPS: right side has " << b.size() << " rows, matrix " << s.id.n);
  s.reduced_rhs.assign(b.data(), b.data() + b.size());
  s.redrhs.assign(static_cast<std::size_t>(m), 0.0);
  s.schur_solve(1, "reduction (ICNTL(26) = 1)"); // the reduced right side comes out in REDRHS
  return Eigen::Map<const Eigen::VectorXd>(s.redrhs.data(), m);
}

Eigen::VectorXd MumpsSolver::expand(const Eigen::VectorXd& x_schur) const {
  State& s = *state_;
  const int m = static_cast<int>(s.schur_dofs.size());
  SIG_VERIFY(!s.reduced_rhs.empty() && x_schur.size() == m,
             "MUMPS: expand needs a reduce() before it and " << m << " Schur values");
  std::copy(x_schur.data(), x_schur.data() + m, s.redrhs.begin());
  s.schur_solve(2, "expansion (ICNTL(26) = 2)"); // backward from the Schur variables' values
  Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(s.reduced_rhs.data(), s.id.n);
  s.reduced_rhs.clear(); // one expansion per reduction
  return x;
}

std::string MumpsSolver::ordering() const {
  if (!state_->analyzed) return "";
  switch (state_->infog(7)) {
  case 0:
    return "amd";
  case 1: // the order given in PERM_IN: ours is METIS's nested dissection
    return "metis";
  case 2:
    return "amf";
  case 3:
    return "scotch";
  case 4:
    return "pord";
  case 5:
    return "metis";
  case 6:
    return "qamd";
  default:
    return "other";
  }
}

const MumpsStatistics& MumpsSolver::statistics() const {
  SIG_VERIFY(state_->factorized, "MUMPS: no statistics before a successful factorize");
  return state_->statistics;
}

Eigen::MatrixXd MumpsSolver::schur_complement() const {
  const State& s = *state_;
  SIG_VERIFY(s.factorized && !s.schur_dofs.empty(),
             "MUMPS: no Schur complement (no Schur variables, or not factorized)");
  const int m = static_cast<int>(s.schur_dofs.size());
  Eigen::MatrixXd S = Eigen::Map<const Eigen::MatrixXd>(s.schur.data(), m, m);
  // ICNTL(19) = 3 returns both triangles (= 2 only the lower one, = 1 the lower by rows, read
  // here by columns as the upper); mirroring one makes S exactly symmetric whatever rounding did
  // to the other.
  if (s.rank_rows) S.transposeInPlace();
  if (s.id.sym != 0) S.triangularView<Eigen::StrictlyUpper>() = S.transpose();
  return S;
}

} // namespace sig
