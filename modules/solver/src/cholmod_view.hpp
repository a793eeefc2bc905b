#pragma once
// What the CHOLMOD adapters share (cholmod_solver.cpp, cholmod_split.cpp,
// cholmod_simplicial.cpp): a compressed Eigen matrix seen as a CHOLMOD matrix whose lower
// triangle is read, and a factor with the workspace of its repeated solves.
#include <Eigen/SparseCore>

#include "core/error.hpp"

#include <cholmod.h>

#include <utility>

namespace sig {

/// A view of a compressed Eigen matrix as a CHOLMOD matrix whose lower triangle is read
/// (stype < 0): CHOLMOD ignores the upper part, so symmetric matrices are passed full. CHOLMOD
/// reads through the pointers without writing (analyze, factorize).
inline cholmod_sparse view_lower(const Eigen::SparseMatrix<double>& A) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(A.rows());
  s.ncol = static_cast<size_t>(A.cols());
  s.nzmax = static_cast<size_t>(A.nonZeros());
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<double*>(A.valuePtr());
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

/// A factor and the workspace of its solves, kept from one solve to the next: cholmod_solve2
/// then allocates nothing. The right side goes into b (n x 1, allocated by allocate()); solve()
/// leaves the solution there.
struct CholmodFactor {
  cholmod_common c{};
  cholmod_factor* L = nullptr;
  cholmod_dense* b = nullptr; ///< the right side, then the solution
  cholmod_dense* x = nullptr; ///< solve2's result, swapped with b
  cholmod_dense* y = nullptr; ///< solve2's workspace
  cholmod_dense* e = nullptr;

  CholmodFactor() {
    cholmod_start(&c);
    c.print = 0;
  }
  ~CholmodFactor() {
    for (cholmod_dense** d : {&b, &x, &y, &e})
      cholmod_free_dense(d, &c);
    if (L) cholmod_free_factor(&L, &c);
    cholmod_finish(&c);
  }
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  /// b, n x 1, for the factor L.
  void allocate() {
    b = cholmod_allocate_dense(L->n, 1, L->n, CHOLMOD_REAL, &c);
    SIG_VERIFY(b, "CHOLMOD: out of memory");
  }
  double* values() { return static_cast<double*>(b->x); }
  /// b := the solution of system `sys` (CHOLMOD_A, CHOLMOD_L, CHOLMOD_Lt, ...) with right side b.
  void solve(int sys) {
    const int ok = cholmod_solve2(sys, L, b, nullptr, &x, nullptr, &y, &e, &c);
    SIG_VERIFY(ok && x, "CHOLMOD: solve failed: status " << c.status);
    std::swap(b, x);
  }
};

} // namespace sig
