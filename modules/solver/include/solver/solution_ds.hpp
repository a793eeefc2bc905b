#pragma once
// DS "B", the solution of sig-solve (MODULEF's B: global vectors). Arrays: u (2 dofs per node,
// interleaved), method, linear (backend), converged, iterations, dofs, failure; for contact
// cases multiplier, status (1 contact, 0 free), history_active, history_residual,
// history_increment, history_step_norm (E_k = ||x(k+1) - x(k)||); scalars time_<phase> in seconds.
#include "solver/static_solve.hpp"

#include <filesystem>

namespace sig {

void write_solution(const std::filesystem::path& path, const StaticSolution& solution,
                    const std::string& method, const std::string& backend,
                    const std::string& title);

} // namespace sig
