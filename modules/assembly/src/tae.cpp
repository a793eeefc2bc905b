// The DS "TAE" of sig-assemble (MODULEF's element arrays, here already assembled): the matrices
// in 1-based compressed row storage, as a Fortran or MODULEF reader expects them.
#include "assembly/system.hpp"
#include "assembly/tae_parts.hpp"

#include "core/ds.hpp"
#include "core/ds_stream.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <span>
#include <sstream>

namespace sig {

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

std::vector<double> values_of(const RowMatrix& A) {
  return std::vector<double>(A.valuePtr(), A.valuePtr() + A.nonZeros());
}

/// The values of A as they lie, without a copy of their own (Ds::put copies them once).
std::span<const double> values_in(const RowMatrix& A) {
  return {A.valuePtr(), static_cast<std::size_t>(A.nonZeros())};
}

/// An Int64 array of the indices in [begin, end) plus one, written straight into its payload (a
/// K_col of tens of millions of entries is copied once, not three times).
DsArray one_based(const std::string& name, const int* begin, const int* end) {
  DsArray array;
  array.name = name;
  array.type = DsType::Int64;
  array.shape = {static_cast<std::int64_t>(end - begin)};
  array.bytes.resize(static_cast<std::size_t>(end - begin) * sizeof(std::int64_t));
  char* out = array.bytes.data();
  for (const int* p = begin; p != end; ++p, out += sizeof(std::int64_t)) {
    const std::int64_t value = static_cast<std::int64_t>(*p) + 1;
    std::memcpy(out, &value, sizeof value);
  }
  return array;
}

bool same_pattern(const RowMatrix& A, const RowMatrix& B) {
  return A.rows() == B.rows() && A.nonZeros() == B.nonZeros() &&
         std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.rows() + 1, B.outerIndexPtr()) &&
         std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), B.innerIndexPtr());
}

// "u1 of node 3" for a 0-based dof (2 per node, x then y).
std::string dof_name(Eigen::Index dof) {
  std::ostringstream name;
  name << "u" << dof % 2 + 1 << " of node " << dof / 2 + 1;
  return name.str();
}

// Every matrix a deck makes (stiffness, mass, viscosity, memory) is symmetric; the solvers read
// one triangle of it, so an edited entry off the diagonal would be used on one side only, or not
// at all, without a word. Round-off in the element matrices stays far below 1e-10 of the
// diagonal.
// `owned`, when given, marks the rows A holds (a rank's, read_tae_rows): only the entries whose
// row and column are both held are compared.
void verify_symmetric(const std::filesystem::path& path, const RowMatrix& A, const char* name,
                      const std::vector<char>* owned = nullptr) {
  const RowMatrix At = A.transpose();
  const Eigen::VectorXd diagonal = A.diagonal().cwiseAbs();
  const auto held = [&](Eigen::Index k) { return owned == nullptr || (*owned)[k] != 0; };
  for (Eigen::Index i = 0; i < A.outerSize(); ++i) {
    for (RowMatrix::InnerIterator a(A, i), t(At, i); a || t;) {
      // Walk row i of A and of its transpose together; a missing entry is a zero.
      const Eigen::Index j = !t || (a && a.col() < t.col()) ? a.col() : t.col();
      if (!held(i) || !held(j)) {
        if (a && a.col() == j) ++a;
        if (t && t.col() == j) ++t;
        continue;
      }
      const double aij = a && a.col() == j ? a.value() : 0;
      const double aji = t && t.col() == j ? t.value() : 0;
      const double scale = std::sqrt(diagonal[i] * diagonal[j]);
      SIG_VERIFY(std::abs(aij - aji) <= 1e-10 * scale,
                 path.string() << ": array '" << name
                               << "': the matrix is not symmetric: its entry "
                               << "of row " << dof_name(i) << ", column " << dof_name(j) << " is "
                               << aij << " but that of row " << dof_name(j) << ", column "
                               << dof_name(i) << " is " << aji
                               << ", where every matrix a deck makes is symmetric (the file was "
                                  "edited or written by another program: rerun sig-assemble)");
      if (a && a.col() == j) ++a;
      if (t && t.col() == j) ++t;
    }
  }
}

// A matrix from 1-based CSR arrays, checked so that a corrupt TAE is an error, not a crash.
Eigen::SparseMatrix<double> from_csr(const std::filesystem::path& path, std::int64_t n,
                                     const std::vector<std::int64_t>& rowptr,
                                     const std::vector<std::int64_t>& col,
                                     const std::vector<double>& val, const char* name,
                                     const std::vector<char>* owned = nullptr) {
  SIG_VERIFY(static_cast<std::int64_t>(rowptr.size()) == n + 1 && rowptr.front() == 1 &&
                 static_cast<std::int64_t>(col.size()) == rowptr.back() - 1,
             path.string() << ": arrays K_rowptr/K_col do not describe a " << n << " x " << n
                           << " matrix");
  SIG_VERIFY(val.size() == col.size(), path.string()
                                           << ": array '" << name << "' has " << val.size()
                                           << " values for " << col.size() << " entries");
  RowMatrix A(n, n);
  A.resizeNonZeros(static_cast<Eigen::Index>(col.size()));
  for (std::int64_t i = 0; i <= n; ++i) {
    SIG_VERIFY(i == 0 || rowptr[i] >= rowptr[i - 1],
               path.string() << ": array 'K_rowptr' decreases at row " << i);
    A.outerIndexPtr()[i] = static_cast<int>(rowptr[i] - 1);
  }
  for (std::int64_t i = 0; i < n; ++i)
    for (std::int64_t k = rowptr[i]; k < rowptr[i + 1] - 1; ++k)
      SIG_VERIFY(col[k] > col[k - 1], path.string() << ": array 'K_col' is not increasing in row "
                                                    << i + 1 << " (Eigen needs sorted columns)");
  for (std::size_t k = 0; k < col.size(); ++k) {
    SIG_VERIFY(col[k] >= 1 && col[k] <= n,
               path.string() << ": array 'K_col' entry " << k + 1 << " out of range");
    A.innerIndexPtr()[k] = static_cast<int>(col[k] - 1);
    A.valuePtr()[k] = val[k];
  }
  verify_symmetric(path, A, name, owned);
  return Eigen::SparseMatrix<double>(A);
}

void put_moving_loads(Ds& ds, const TimeLoads& loads) {
  if (loads.moving.empty()) return;
  std::vector<double> parameters, x1, weight;
  std::vector<std::int64_t> count, nodes;
  for (const MovingLoad& load : loads.moving) {
    parameters.insert(parameters.end(), {load.F, load.psi, load.c, load.x0});
    count.push_back(static_cast<std::int64_t>(load.points.size()));
    for (const MovingLoadPoint& p : load.points) {
      nodes.insert(nodes.end(), {p.node_a + 1, p.node_b + 1});
      x1.push_back(p.x1);
      weight.insert(weight.end(), {p.weight_a, p.weight_b});
    }
  }
  ds.put("moving_load", parameters);
  ds.put("moving_points", count);
  ds.put("moving_node", nodes);
  ds.put("moving_x1", x1);
  ds.put("moving_weight", weight);
}

// The ramped and moving loads of a TAE, checked so that a corrupt file is an error naming the
// array.
TimeLoads get_time_loads(const std::filesystem::path& path, const Ds& ds, std::int64_t ndof) {
  TimeLoads loads;
  if (ds.has("f_rate")) {
    const auto rate = ds.reals("f_rate");
    SIG_VERIFY(static_cast<std::int64_t>(rate.size()) == ndof,
               path.string() << ": array 'f_rate' must have ndof = " << ndof << " values");
    loads.rate = Eigen::Map<const Eigen::VectorXd>(rate.data(), ndof);
  }
  if (!ds.has("moving_load")) return loads;
  const auto parameters = ds.reals("moving_load");
  const auto count = ds.ints("moving_points");
  const auto nodes = ds.ints("moving_node");
  const auto x1 = ds.reals("moving_x1");
  const auto weight = ds.reals("moving_weight");
  SIG_VERIFY(parameters.size() == 4 * count.size(),
             path.string() << ": arrays 'moving_load' and 'moving_points' differ in length");
  std::size_t total = 0;
  for (std::int64_t n : count) {
    SIG_VERIFY(n >= 0, path.string() << ": array 'moving_points' has a negative count");
    total += static_cast<std::size_t>(n);
  }
  SIG_VERIFY(nodes.size() == 2 * total && x1.size() == total && weight.size() == 2 * total,
             path.string() << ": arrays 'moving_node', 'moving_x1' and 'moving_weight' do not "
                              "hold the "
                           << total << " points of 'moving_points'");
  std::size_t point = 0;
  for (std::size_t l = 0; l < count.size(); ++l) {
    MovingLoad load{
        parameters[4 * l], parameters[4 * l + 1], parameters[4 * l + 2], parameters[4 * l + 3], {}};
    SIG_VERIFY(load.psi > 0, path.string() << ": array 'moving_load': psi = " << load.psi
                                           << " of load " << l + 1 << " must be > 0");
    for (std::int64_t k = 0; k < count[l]; ++k, ++point) {
      const std::int64_t a = nodes[2 * point], b = nodes[2 * point + 1];
      SIG_VERIFY(a >= 1 && b >= 1 && 2 * a <= ndof && 2 * b <= ndof,
                 path.string() << ": array 'moving_node' entry " << point + 1
                               << " names a node out of range");
      load.points.push_back({static_cast<int>(a - 1), static_cast<int>(b - 1), x1[point],
                             weight[2 * point], weight[2 * point + 1]});
    }
    loads.moving.push_back(std::move(load));
  }
  return loads;
}

/// The Dirichlet conditions of a TAE, checked.
void read_dirichlet(const std::filesystem::path& path, const Ds& ds, std::int64_t n,
                    LinearSystem& system) {
  const auto dofs = ds.ints("dirichlet_dof");
  const auto values = ds.reals("dirichlet_value");
  SIG_VERIFY(dofs.size() == values.size(),
             path.string() << ": arrays 'dirichlet_dof' and 'dirichlet_value' differ in length");
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    SIG_VERIFY(dofs[k] >= 1 && dofs[k] <= n && (k == 0 || dofs[k] > dofs[k - 1]),
               path.string() << ": array 'dirichlet_dof' entry " << k + 1
                             << " out of range or not increasing");
    system.dirichlet_dofs.push_back(static_cast<int>(dofs[k] - 1));
  }
  system.dirichlet_values = Eigen::Map<const Eigen::VectorXd>(values.data(), values.size());
}

} // namespace

namespace {

/// K's 1-based CSR and the values of every matrix on its pattern (M, V, the memory terms).
void put_matrices(Ds& ds, const LinearSystem& system) {
  const RowMatrix K = system.K;
  ds.put(one_based("K_rowptr", K.outerIndexPtr(), K.outerIndexPtr() + K.rows() + 1));
  ds.put(one_based("K_col", K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros()));
  ds.put("K_val", values_in(K));
  if (system.M.size() > 0) {
    const RowMatrix M = system.M;
    SIG_VERIFY(same_pattern(K, M), "write_tae: M does not share the pattern of K");
    ds.put("M_val", values_in(M));
  }
  if (system.V.size() > 0) {
    const RowMatrix V = system.V;
    SIG_VERIFY(same_pattern(K, V), "write_tae: V does not share the pattern of K");
    ds.put("V_val", values_in(V));
  }
  if (!system.memory.empty()) {
    std::vector<double> beta, values;
    for (const MemoryStiffness& term : system.memory) {
      const RowMatrix Km = term.K;
      SIG_VERIFY(same_pattern(K, Km), "write_tae: a memory matrix does not share the pattern of K");
      beta.push_back(term.beta);
      const std::vector<double> v = values_of(Km);
      values.insert(values.end(), v.begin(), v.end());
    }
    ds.put("memory_beta", beta);
    ds.put("memory_val", values,
           {static_cast<std::int64_t>(beta.size()), static_cast<std::int64_t>(K.nonZeros())});
  }
}

/// The vectors of the whole body: loads, lumped mass, Dirichlet conditions, time loads.
void put_vectors(Ds& ds, const LinearSystem& system) {
  const Eigen::VectorXd& rate = system.time_loads.rate;
  if (rate.size() > 0) ds.put("f_rate", std::span<const double>(rate.data(), rate.size()));
  ds.put("M_lumped", std::span<const double>(system.M_lumped.data(), system.M_lumped.size()));
  ds.put("f", std::span<const double>(system.f.data(), system.f.size()));
  ds.put(one_based("dirichlet_dof", system.dirichlet_dofs.data(),
                   system.dirichlet_dofs.data() + system.dirichlet_dofs.size()));
  ds.put("dirichlet_value",
         std::span<const double>(system.dirichlet_values.data(), system.dirichlet_values.size()));
  ds.put_scalar("time_assemble", system.assemble_seconds);
  put_moving_loads(ds, system.time_loads);
}

} // namespace

void write_tae(const std::filesystem::path& path, const LinearSystem& system,
               const std::string& title) {
  Ds ds("TAE", title, "sig-assemble");
  ds.put_int("ndof", system.num_dofs());
  put_matrices(ds, system);
  put_vectors(ds, system);
  write_ds(path, ds);
}

LinearSystem read_tae(const std::filesystem::path& path) {
  const Ds ds = read_ds(path, "TAE");
  SIG_VERIFY(!ds.has("parts"), path.string()
                                   << ": the index of an assembly on " << ds.integer("parts")
                                   << " ranks, its matrices in the parts "
                                   << tae_part_path(path, 0).string()
                                   << " ...: run this stage as mpirun -np " << ds.integer("parts")
                                   << ", or rerun sig-assemble in one process");
  const std::int64_t n = ds.integer("ndof");
  SIG_VERIFY(n >= 0, path.string() << ": negative ndof");
  const auto rowptr = ds.ints("K_rowptr");
  const auto col = ds.ints("K_col");
  LinearSystem system;
  system.K = from_csr(path, n, rowptr, col, ds.reals("K_val"), "K_val");
  if (ds.has("M_val")) system.M = from_csr(path, n, rowptr, col, ds.reals("M_val"), "M_val");
  if (ds.has("V_val")) system.V = from_csr(path, n, rowptr, col, ds.reals("V_val"), "V_val");
  if (ds.has("memory_beta")) {
    const auto beta = ds.reals("memory_beta");
    const auto values = ds.reals("memory_val");
    const std::size_t nnz = col.size();
    SIG_VERIFY(values.size() == beta.size() * nnz,
               path.string() << ": array 'memory_val' holds " << values.size() << " values for "
                             << beta.size() << " terms of " << nnz << " entries");
    for (std::size_t j = 0; j < beta.size(); ++j) {
      SIG_VERIFY(beta[j] > 0, path.string() << ": array 'memory_beta' entry " << j + 1 << " = "
                                            << beta[j] << " is not > 0");
      const std::vector<double> v(values.begin() + j * nnz, values.begin() + (j + 1) * nnz);
      system.memory.push_back({beta[j], from_csr(path, n, rowptr, col, v, "memory_val")});
    }
  }
  const auto lumped = ds.reals("M_lumped");
  const auto f = ds.reals("f");
  SIG_VERIFY(static_cast<std::int64_t>(lumped.size()) == n &&
                 static_cast<std::int64_t>(f.size()) == n,
             path.string() << ": arrays 'M_lumped' and 'f' must have ndof = " << n << " values");
  system.M_lumped = Eigen::Map<const Eigen::VectorXd>(lumped.data(), n);
  system.f = Eigen::Map<const Eigen::VectorXd>(f.data(), n);
  read_dirichlet(path, ds, n, system);
  if (ds.has("time_assemble")) system.assemble_seconds = ds.scalar("time_assemble");
  system.time_loads = get_time_loads(path, ds, n);
  return system;
}

namespace {

/// The entries of K_col, K_val (or M_val, V_val), in file order, kept when their row is owned;
/// memory_val holds one such array per memory term, one after the other.
template <class T> class RowEntries {
public:
  RowEntries(const std::vector<std::int64_t>& rowptr, const std::vector<char>& owned)
      : rowptr_(rowptr), owned_(owned) {}
  void take(const char* piece, std::size_t size) {
    const auto n = static_cast<std::int64_t>(rowptr_.size()) - 1;
    const std::int64_t nnz = rowptr_.back() - 1;
    for (std::size_t b = 0; b < size; b += sizeof(T), ++taken_) {
      const std::int64_t entry = nnz > 0 ? taken_ % nnz : taken_;
      if (entry == 0) row_ = 0; // the next matrix's first entry
      while (row_ < n && entry >= rowptr_[row_ + 1] - 1)
        ++row_;
      if (row_ < n && owned_[static_cast<std::size_t>(row_)] != 0) {
        T value;
        std::memcpy(&value, piece + b, sizeof value);
        kept_.push_back(value);
      }
    }
  }
  std::int64_t entries() const { return taken_; }
  std::vector<T>& kept() { return kept_; }

private:
  const std::vector<std::int64_t>& rowptr_;
  const std::vector<char>& owned_;
  std::int64_t taken_ = 0, row_ = 0;
  std::vector<T> kept_;
};

/// The arrays of a TAE read_tae_rows streams (the matrices' entries), and those it keeps whole.
bool streamed_row_array(const std::string& name) {
  return name == "K_rowptr" || name == "K_col" || name == "K_val" || name == "M_val" ||
         name == "V_val" || name == "memory_val";
}

bool whole_row_array(const std::string& name) {
  return name == "ndof" || name == "f" || name == "dirichlet_dof" || name == "dirichlet_value" ||
         name == "M_lumped" || name == "f_rate" || name == "memory_beta" ||
         name.starts_with("moving_");
}

/// The values of `whole` on the rows `owned` marks, zero on the others.
Eigen::VectorXd on_rows(const std::vector<double>& whole, const std::vector<char>& owned) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(owned.size()));
  for (std::size_t i = 0; i < owned.size(); ++i)
    if (owned[i]) v[static_cast<Eigen::Index>(i)] = whole[i];
  return v;
}

/// read_tae_rows of a TAE (`part` false) or of a rank's part of one (true: kind TAEP, not an
/// input of the case of its own, every entry on a row of `owned` and every such row there).
LinearSystem read_rows(const std::filesystem::path& path, const std::vector<char>& owned,
                       bool march, bool part) {
  std::vector<std::int64_t> rowptr; // whole (ndof + 1 indices): the structure, not the values
  RowEntries<std::int64_t> col(rowptr, owned);
  std::map<std::string, RowEntries<double>> values; // K_val, and M_val ... for a march
  const auto take = [&](const DsArray& array, const char* piece, std::size_t size) {
    if (array.name == "K_rowptr") {
      SIG_VERIFY(array.type == DsType::Int64, path.string() << ": array 'K_rowptr' is not Int64");
      const std::size_t at = rowptr.size();
      rowptr.resize(at + size / sizeof(std::int64_t));
      std::memcpy(rowptr.data() + at, piece, size);
      return;
    }
    // K_rowptr precedes them (write_tae): the rows of their entries are known as they come.
    SIG_VERIFY(rowptr.size() == owned.size() + 1,
               path.string() << ": array 'K_rowptr' (" << rowptr.size() << " values) must come "
                             << "before '" << array.name
                             << "' and hold ndof + 1 = " << owned.size() + 1 << " values");
    if (array.name == "K_col") {
      SIG_VERIFY(array.type == DsType::Int64, path.string() << ": array 'K_col' is not Int64");
      col.take(piece, size);
    } else {
      SIG_VERIFY(array.type == DsType::Float64,
                 path.string() << ": array '" << array.name << "' is not Float64");
      values.try_emplace(array.name, rowptr, owned).first->second.take(piece, size);
    }
  };
  const auto streamed = [march](const std::string& name) {
    return streamed_row_array(name) && (march || name.starts_with("K_"));
  };
  const auto wanted = [march](const std::string& name) {
    return whole_row_array(name) &&
           (march || name == "ndof" || name == "f" || name.starts_with("dirichlet_"));
  };
  const Ds ds = part ? read_ds_record_streamed(path, "TAEP", wanted, streamed, take)
                     : read_ds_streamed(path, "TAE", wanted, streamed, take);
  const std::int64_t n = ds.integer("ndof");
  SIG_VERIFY(n == static_cast<std::int64_t>(owned.size()),
             path.string() << ": ndof = " << n << ", the partition has " << owned.size()
                           << " rows (a TAE of another mesh?)");
  SIG_VERIFY(static_cast<std::int64_t>(rowptr.size()) == n + 1 && rowptr.front() == 1 &&
                 col.entries() == rowptr.back() - 1 && values.contains("K_val") &&
                 values.at("K_val").entries() == col.entries(),
             path.string() << ": arrays K_rowptr/K_col/K_val do not describe a " << n << " x " << n
                           << " matrix");
  // This rank's rows in the file's CSR form, the others empty; from_csr checks them.
  std::vector<std::int64_t> local_rowptr(static_cast<std::size_t>(n) + 1, 1);
  for (std::int64_t i = 0; i < n; ++i) {
    SIG_VERIFY(rowptr[i + 1] >= rowptr[i], path.string()
                                               << ": array 'K_rowptr' decreases at row " << i + 1);
    const std::int64_t count = owned[static_cast<std::size_t>(i)] ? rowptr[i + 1] - rowptr[i] : 0;
    local_rowptr[i + 1] = local_rowptr[i] + count;
  }
  if (part) {
    bool every_row = true;
    for (std::int64_t i = 0; i < n; ++i)
      every_row = every_row && (!owned[static_cast<std::size_t>(i)] || rowptr[i + 1] > rowptr[i]);
    SIG_VERIFY(every_row && static_cast<std::int64_t>(col.kept().size()) == col.entries(),
               path.string() << ": its rows are not this rank's rows of the mesh's partition (a "
                                "part of another partition: rerun sig-assemble under mpirun)");
  }
  // Every matrix of the file on K's pattern: its rows' entries, checked as K's.
  const auto rows_of = [&](const char* name, std::vector<double> kept) {
    SIG_VERIFY(values.at(name).entries() == col.entries(),
               path.string() << ": array '" << name << "' holds " << values.at(name).entries()
                             << " values for the " << col.entries() << " entries of K");
    return from_csr(path, n, local_rowptr, col.kept(), kept, name, &owned);
  };
  LinearSystem system;
  system.rank_rows = true;
  system.K = rows_of("K_val", std::move(values.at("K_val").kept()));
  // The pattern made symmetric with explicit zeros at the transposed places of the rows held:
  // the frames of the contact nodes turn K in place on a symmetric pattern
  // (solver/nodal_frames.hpp), and a row not held stays zero through them. The other matrices
  // of a march enter its step matrix beside K, on K's pattern.
  const Eigen::SparseMatrix<double> transposed = system.K.transpose();
  system.K = system.K + 0.0 * transposed;
  const auto f = ds.reals("f");
  SIG_VERIFY(static_cast<std::int64_t>(f.size()) == n,
             path.string() << ": array 'f' must have ndof = " << n << " values");
  system.f = on_rows(f, owned);
  system.M_lumped = Eigen::VectorXd::Zero(n);
  read_dirichlet(path, ds, n, system);
  if (!march) return system;
  if (values.contains("M_val")) system.M = rows_of("M_val", std::move(values.at("M_val").kept()));
  if (values.contains("V_val")) system.V = rows_of("V_val", std::move(values.at("V_val").kept()));
  if (ds.has("memory_beta")) {
    const auto beta = ds.reals("memory_beta");
    SIG_VERIFY(values.contains("memory_val") &&
                   values.at("memory_val").entries() ==
                       static_cast<std::int64_t>(beta.size()) * col.entries(),
               path.string() << ": array 'memory_val' does not hold " << beta.size() << " terms of "
                             << col.entries() << " entries");
    const std::vector<double>& kept = values.at("memory_val").kept();
    const auto local = static_cast<std::ptrdiff_t>(col.kept().size());
    for (std::size_t j = 0; j < beta.size(); ++j) {
      SIG_VERIFY(beta[j] > 0, path.string() << ": array 'memory_beta' entry " << j + 1 << " = "
                                            << beta[j] << " is not > 0");
      const auto first = kept.begin() + static_cast<std::ptrdiff_t>(j) * local;
      system.memory.push_back(
          {beta[j], from_csr(path, n, local_rowptr, col.kept(),
                             std::vector<double>(first, first + local), "memory_val", &owned)});
    }
  }
  const auto lumped = ds.reals("M_lumped");
  SIG_VERIFY(static_cast<std::int64_t>(lumped.size()) == n,
             path.string() << ": array 'M_lumped' must have ndof = " << n << " values");
  system.M_lumped = on_rows(lumped, owned);
  system.time_loads = get_time_loads(path, ds, n);
  return system;
}

} // namespace

LinearSystem read_tae_rows(const std::filesystem::path& path, const std::vector<char>& owned,
                           bool march) {
  return read_rows(path, owned, march, /*part=*/false);
}

std::filesystem::path tae_part_path(const std::filesystem::path& tae, int rank) {
  return tae.string() + ".r" + std::to_string(rank);
}

void write_tae_part(const std::filesystem::path& tae, int rank, const TaeParts& parts,
                    const LinearSystem& rows, const std::string& title,
                    const std::function<void()>& before_rename) {
  Ds ds("TAEP", title, "sig-assemble");
  ds.put_int("part_rank", rank);
  ds.put_int("part_ranks", parts.ranks);
  ds.put_text("part_run", parts.run);
  ds.put_int("ndof", rows.num_dofs());
  put_matrices(ds, rows);
  put_vectors(ds, rows);
  write_ds(tae_part_path(tae, rank), ds, before_rename);
}

void write_tae_index(const std::filesystem::path& tae, const TaeParts& parts,
                     const LinearSystem& system, const std::string& title) {
  Ds ds("TAE", title, "sig-assemble");
  ds.put_int("ndof", system.num_dofs());
  ds.put_int("parts", parts.ranks);
  ds.put_text("part_run", parts.run);
  // The parts by name: a case whose part is gone is stale (core/stale.hpp).
  std::string files;
  for (int rank = 0; rank < parts.ranks; ++rank)
    files += tae_part_path(tae, rank).filename().string() + "\n";
  ds.put_text("files", files);
  put_vectors(ds, system);
  write_ds(tae, ds);
}

void remove_tae_parts(const std::filesystem::path& tae, int first) {
  const std::string prefix = tae.filename().string() + ".r";
  const std::filesystem::path folder = tae.parent_path().empty() ? "." : tae.parent_path();
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(prefix) || name.size() == prefix.size()) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 6) continue;
    if (std::stoi(digits) >= first) std::filesystem::remove(entry.path());
  }
}

std::optional<TaeParts> read_tae_index(const std::filesystem::path& tae) {
  const Ds ds = read_ds(
      tae, "TAE", [](const std::string& name) { return name == "parts" || name == "part_run"; });
  if (!ds.has("parts")) return std::nullopt;
  const std::int64_t ranks = ds.integer("parts");
  SIG_VERIFY(ranks >= 2 && ranks <= std::numeric_limits<int>::max(),
             tae.string() << ": array 'parts' = " << ranks << " is not a number of ranks >= 2");
  return TaeParts{static_cast<int>(ranks), ds.text("part_run")};
}

LinearSystem read_tae_part(const std::filesystem::path& tae, const TaeParts& parts, int rank,
                           int ranks, const std::vector<char>& owned, bool march) {
  const std::string rerun = "rerun mpirun -np " + std::to_string(ranks) + " sig-assemble";
  SIG_VERIFY(parts.ranks == ranks, tae.string() << ": the index of an assembly on " << parts.ranks
                                                << " ranks, and this job has " << ranks
                                                << ": run it as mpirun -np " << parts.ranks
                                                << ", or " << rerun);
  const std::filesystem::path path = tae_part_path(tae, rank);
  SIG_VERIFY(std::filesystem::exists(path), path.string() << ": missing, the part of rank " << rank
                                                          << " of the assembly " << tae.string()
                                                          << " indexes: " << rerun);
  // The stamp first: a part of another assembly is named as such, not by its rows.
  const Ds stamp = read_ds_record(
      path, "TAEP", [](const std::string& name) { return name.starts_with("part_"); });
  const std::int64_t its_rank = stamp.integer("part_rank"), its_ranks = stamp.integer("part_ranks");
  const std::string its_run = stamp.text("part_run");
  SIG_VERIFY(its_rank == rank && its_ranks == ranks && its_run == parts.run,
             path.string() << ": the part of rank " << its_rank << " of " << its_ranks
                           << " of the assembly " << its_run << ", but " << tae.string()
                           << " indexes the assembly " << parts.run << " on " << parts.ranks
                           << " ranks (a part of another run): " << rerun);
  return read_rows(path, owned, march, /*part=*/true);
}

} // namespace sig
