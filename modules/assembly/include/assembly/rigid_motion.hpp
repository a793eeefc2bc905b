#pragma once
// The rigid motions of a 2D body (two translations, one rotation) that its Dirichlet dofs leave
// free. A static problem without contact has no solution then (K_ff is singular), and the
// linear solver's "not positive definite" tells the user nothing: this names the motions.
#include "mesh/mesh.hpp"

#include <string>
#include <vector>

namespace sig {

/// "" if the Dirichlet dofs (0-based, 2 per node: x then y) hold every rigid motion of `mesh`,
/// else the free motions in words, e.g. "the translation along x1 and the rotation about
/// (0, 10)".
std::string free_rigid_motions(const Mesh& mesh, const std::vector<int>& dirichlet_dofs);

/// Throw sig::InputError naming `deck` and the free motions if the Dirichlet dofs leave any:
/// for a static problem that nothing else (no contact) holds.
void verify_rigid_motions_held(const Mesh& mesh, const std::vector<int>& dirichlet_dofs,
                               const std::string& deck);

} // namespace sig
