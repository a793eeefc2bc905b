#pragma once
// What the CHOLMOD adapters share (cholmod_solver.cpp, cholmod_split.cpp): a compressed Eigen
// matrix seen as a CHOLMOD matrix whose lower triangle is read.
#include <Eigen/SparseCore>

#include <cholmod.h>

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

} // namespace sig
