#include "assembly/singular_matrix.hpp"

#include "assembly/rigid_motion.hpp"
#include "assembly/system.hpp"
#include "assembly/tae_parts.hpp"
#include "mesh/nopo.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace sig {

namespace {

// A double resolves about 16 digits: a matrix whose diagonal spans more than this keeps none
// of its smallest pivots.
constexpr double kMaxDiagonalSpan = 1e15;

std::string dof_name(int dof) {
  std::ostringstream name;
  name << "u" << dof % 2 + 1 << " of node " << dof / 2 + 1;
  return name.str();
}

/// What no deck's MATERIAL cards make: a diagonal entry <= 0 or an asymmetric matrix, or a
/// diagonal that spans more than a double resolves; "" if none of these.
std::string matrix_defect(const Eigen::SparseMatrix<double>& A, const std::string& array,
                          const std::vector<bool>& imposed) {
  double low = std::numeric_limits<double>::infinity(), high = 0;
  int low_dof = -1, high_dof = -1;
  for (int i = 0; i < A.rows(); ++i) {
    if (imposed[i]) continue;
    const double d = A.coeff(i, i);
    std::ostringstream what;
    if (!(d > 0)) {
      what << "array '" << array << "': the diagonal entry of " << dof_name(i) << " is " << d
           << ", where every stiffness and mass a deck makes is positive";
      return what.str();
    }
    if (d < low) low = d, low_dof = i;
    if (d > high) high = d, high_dof = i;
  }
  const Eigen::SparseMatrix<double> difference = A - Eigen::SparseMatrix<double>(A.transpose());
  const double asymmetry = difference.nonZeros() ? difference.coeffs().cwiseAbs().maxCoeff() : 0;
  if (asymmetry > 1e-12 * A.coeffs().cwiseAbs().maxCoeff()) {
    std::ostringstream what;
    what << "array '" << array << "' is not symmetric (entries differing by " << asymmetry
         << " from their mirror), where every stiffness and mass a deck makes is";
    return what.str();
  }
  if (low_dof >= 0 && high > kMaxDiagonalSpan * low) {
    std::ostringstream what;
    what << "array '" << array << "': its diagonal spans " << low << " (" << dof_name(low_dof)
         << ") to " << high << " (" << dof_name(high_dof) << "), more than the " << kMaxDiagonalSpan
         << " a double resolves: parts whose stiffnesses (MATERIAL E=, the mesh sizes) differ that "
            "much cannot be solved together";
    return what.str();
  }
  return "";
}

} // namespace

std::string explain_failed_factorization(const Mesh& mesh, const LinearSystem& system,
                                         const Holds& held, const FailedFactorization& failed) {
  const std::string library = " (" + failed.library + ")";
  const std::vector<FreePart> parts = free_parts(mesh, held.holds);
  if (!parts.empty()) {
    const FreePart& free = parts.front();
    const std::string part = describe(free) + " (" + held.holders + ")";
    if (failed.inertia) {
      double mass = 0;
      for (int n : free.nodes)
        if (system.M.rows() > 2 * n) mass += system.M.coeff(2 * n, 2 * n);
      if (mass == 0)
        return part +
               ", and it has no mass either (MATERIAL rho=0 on its sub-domains): give it "
               "a density or hold it with a DIRICHLET card" +
               library;
      return part +
             ": only its mass holds it, and its mass is too small against its stiffness "
             "over one time step for the step matrix to keep it; raise MATERIAL rho=, "
             "shorten TIME k=, or hold it with a DIRICHLET card" +
             library;
    }
    return part +
           ", so its stiffness is singular; add DIRICHLET cards (ux=, uy=) on references "
           "that hold " +
           (free.whole_body ? "the body" : "that part") + library;
  }
  std::vector<bool> imposed(static_cast<std::size_t>(system.K.rows()), false);
  for (int dof : system.dirichlet_dofs)
    imposed[dof] = true;
  const std::string matrices = failed.tae + "'s matrices are not ones this deck's cards make";
  for (const auto& [A, array] : {std::pair{&system.K, "K_val"}, std::pair{&system.M, "M_val"}}) {
    if (A->rows() != system.K.rows() || (array[0] == 'M' && !failed.inertia)) continue;
    if (const std::string defect = matrix_defect(*A, array, imposed); !defect.empty())
      return failed.tae + ": " + defect + " (every part of the body is held: " + held.holders +
             "); rerun sig-assemble, or check the MATERIAL cards" + library;
  }
  return "every part of the body is held (" + held.holders + "), yet " +
         (failed.inertia ? "the step matrix" : "the stiffness") +
         " is not positive definite: " + matrices +
         " (edited, or written by another program?): rerun sig-assemble" + library;
}

std::string explain_failed_factorization(const std::filesystem::path& outdir, const Holds* held,
                                         bool inertia, const std::string& library) {
  const std::filesystem::path tae = outdir / "case.tae";
  // The parts of a distributed assembly are each rank's own: the diagnosis needs the whole.
  if (const std::optional<TaeParts> parts = read_tae_index(tae))
    return "the factorization over the " + std::to_string(parts->ranks) +
           " parts of a distributed assembly failed (" + library + ")" +
           ": run sig-assemble and this stage in one process to have the cause named";
  const LinearSystem system = read_tae(tae);
  return explain_failed_factorization(read_nopo(outdir / "case.nopo"), system,
                                      held ? *held : holds_of(system.dirichlet_dofs),
                                      {tae.string(), inertia, library});
}

} // namespace sig
