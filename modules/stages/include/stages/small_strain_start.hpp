#pragma once
// The first iterate of a static large-deformation solve (thesis (3.11) step (i), "choix de x0",
// which the thesis leaves open): the small-strain solution of the first load step's problem, the
// same Dirichlet data, loads and contact elements with the bulk's tangent at rest (the
// linearization of the hyperelastic law there), solved exactly by PDAS on the condensed contact
// problem (stages/static_solve.hpp: one sparse factorization and a small dense problem).
//
// Why: from rest, the first Newton step of a large imposed displacement is the same linear
// solve with only the nodes touching at rest on the obstacle, and pushes a wide arc of the
// contact boundary through it. The active set that follows holds that arc, and the contact
// patches it leaves roll to their final place by a node or two per iteration (scene 7b at
// N = 256: 20 of PDAS's 23 steps). The small-strain solution has its contact patches where the
// linearized problem puts them, near the large-deformation ones, and no node through the wall.
// Its contact forces are the first multipliers: a node it holds on the obstacle has q_n = 0 up
// to round-off there, and its force, not the sign of that round-off, then decides the first
// test. The branches start empty, so each method's own first test decides the active set.
#include "solver/contact_method.hpp"
#include "stages/finite_strain_bulk.hpp"

#include <string>

namespace sig {

struct StartRecord {
  bool used = false;          ///< a small-strain start was asked for
  bool converged = false;     ///< the small-strain solve converged (else: started from rest; a
                              ///< converged start may still fall back: fraction 0)
  int iterations = 0;         ///< its contact Newton iterations on the condensed problem
  double fraction = 0;        ///< theta of FiniteStrainBulk::start_from: 1 = the whole solution
  double seconds = 0;         ///< wall time of the start (factorization, condensation, solve)
  std::string note;           ///< why the solve started from rest, if it did
  Eigen::VectorXd multiplier; ///< the small-strain contact forces per node, x fraction (or empty)
  /// "rest" (none asked for), "small-strain", or "rest (fallback)" when it failed: the name in
  /// case.b, sig-solve's line and the benchmark's JSON.
  std::string name() const;
};

/// Moves `bulk` (static, at rest) to the small-strain solution of `problem` at load factor
/// `load_factor`, its contact solved with `parameters` (the method replaced by pdas, the one
/// whose count does not depend on its parameter) on `backend`. A small-strain solve that fails
/// or does not converge leaves the bulk at rest and says why in the record.
StartRecord start_from_small_strain(FiniteStrainBulk& bulk, const FiniteStrainProblem& problem,
                                    double load_factor, ContactSolverParameters parameters,
                                    const std::string& backend);

} // namespace sig
