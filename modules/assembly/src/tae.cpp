// The DS "TAE" of sig-assemble (MODULEF's element arrays, here already assembled): the matrices
// in 1-based compressed row storage, as a Fortran or MODULEF reader expects them.
#include "assembly/system.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"

#include <algorithm>
#include <cstdint>
#include <span>

namespace sig {

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

std::vector<double> values_of(const RowMatrix& A) {
  return std::vector<double>(A.valuePtr(), A.valuePtr() + A.nonZeros());
}

std::vector<std::int64_t> one_based(const int* begin, const int* end) {
  std::vector<std::int64_t> v(begin, end);
  for (auto& x : v)
    ++x;
  return v;
}

bool same_pattern(const RowMatrix& A, const RowMatrix& B) {
  return A.rows() == B.rows() && A.nonZeros() == B.nonZeros() &&
         std::equal(A.outerIndexPtr(), A.outerIndexPtr() + A.rows() + 1, B.outerIndexPtr()) &&
         std::equal(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros(), B.innerIndexPtr());
}

// A matrix from 1-based CSR arrays, checked so that a corrupt TAE is an error, not a crash.
Eigen::SparseMatrix<double> from_csr(const std::filesystem::path& path, std::int64_t n,
                                     const std::vector<std::int64_t>& rowptr,
                                     const std::vector<std::int64_t>& col,
                                     const std::vector<double>& val, const char* name) {
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
  return Eigen::SparseMatrix<double>(A);
}

} // namespace

void write_tae(const std::filesystem::path& path, const LinearSystem& system,
               const std::string& title) {
  const RowMatrix K = system.K;
  Ds ds("TAE", title, "sig-assemble");
  ds.put_int("ndof", system.num_dofs());
  ds.put("K_rowptr", one_based(K.outerIndexPtr(), K.outerIndexPtr() + K.rows() + 1));
  ds.put("K_col", one_based(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros()));
  ds.put("K_val", values_of(K));
  if (system.M.size() > 0) {
    const RowMatrix M = system.M;
    SIG_VERIFY(same_pattern(K, M), "write_tae: M does not share the pattern of K");
    ds.put("M_val", values_of(M));
  }
  if (system.V.size() > 0) {
    const RowMatrix V = system.V;
    SIG_VERIFY(same_pattern(K, V), "write_tae: V does not share the pattern of K");
    ds.put("V_val", values_of(V));
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
  if (system.has_ramp())
    ds.put("f_rate", std::span<const double>(system.f_rate.data(), system.f_rate.size()));
  ds.put("M_lumped", std::span<const double>(system.M_lumped.data(), system.M_lumped.size()));
  ds.put("f", std::span<const double>(system.f.data(), system.f.size()));
  ds.put("dirichlet_dof", one_based(system.dirichlet_dofs.data(),
                                    system.dirichlet_dofs.data() + system.dirichlet_dofs.size()));
  ds.put("dirichlet_value",
         std::span<const double>(system.dirichlet_values.data(), system.dirichlet_values.size()));
  ds.put_scalar("time_assemble", system.assemble_seconds);
  write_ds(path, ds);
}

LinearSystem read_tae(const std::filesystem::path& path) {
  const Ds ds = read_ds(path, "TAE");
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
  system.f_rate = Eigen::VectorXd::Zero(n);
  if (ds.has("f_rate")) {
    const auto rate = ds.reals("f_rate");
    SIG_VERIFY(static_cast<std::int64_t>(rate.size()) == n,
               path.string() << ": array 'f_rate' must have ndof = " << n << " values");
    system.f_rate = Eigen::Map<const Eigen::VectorXd>(rate.data(), n);
  }
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
  if (ds.has("time_assemble")) system.assemble_seconds = ds.scalar("time_assemble");
  return system;
}

} // namespace sig
