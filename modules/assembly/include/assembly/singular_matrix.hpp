#pragma once
// Why a stage's matrix failed to factorize, in the deck's words. The linear solver says "not
// positive definite" or "singular" (solver/linear_solver.hpp, FactorizationFailure); the stage
// that catches it knows the mesh, the dofs it held and the matrices of case.tae, and this names
// the cause:
//  - a part of the body that nothing holds (rigid_motion.hpp); in a march with inertia, a part
//    that only its mass holds, too light against its stiffness over one time step;
//  - every part held: a stiffness or mass with a diagonal entry <= 0 or not symmetric, which no
//    deck makes (case.tae edited or written by another program), or one whose diagonal spans more
//    than a double resolves (stiffnesses 1e15 apart);
//  - else matrices that are not positive definite all the same, which the deck's cards do not
//    make either.
#include "assembly/rigid_motion.hpp"
#include "assembly/system.hpp"
#include "mesh/mesh.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sig {

struct FailedFactorization {
  std::string tae;      ///< the file the matrices came from
  bool inertia = false; ///< the matrix was a march's step matrix, the mass in it
  std::string library;  ///< the linear solver's message
};

/// The cause of the failure, in words that name the deck's cards or the file's array; `held` as
/// the stage held the body.
std::string explain_failed_factorization(const Mesh& mesh, const LinearSystem& system,
                                         const Holds& held, const FailedFactorization& failed);

/// The same from the case's files in `outdir` (case.nopo, case.tae), the body held by `held`, or
/// by the Dirichlet dofs of case.tae if null: what a stage hands explain_factorization_failures
/// (core/stage.hpp), which calls it once the stage's own copies of them are gone.
std::string explain_failed_factorization(const std::filesystem::path& outdir, const Holds* held,
                                         bool inertia, const std::string& library);

} // namespace sig
