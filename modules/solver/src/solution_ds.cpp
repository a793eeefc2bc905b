#include "solver/solution_ds.hpp"

#include "core/ds.hpp"
#include "core/error.hpp"

#include <cmath>

namespace sig {

void write_solution(const std::filesystem::path& path, const StaticSolution& solution,
                    const std::string& method, const std::string& backend,
                    const std::string& title) {
  // A NaN here would flow silently into every report: refuse it where it is made.
  for (Eigen::Index i = 0; i < solution.u.size(); ++i)
    SIG_VERIFY(std::isfinite(solution.u[i]), path.string()
                                                 << ": array 'u' would hold " << solution.u[i]
                                                 << " at dof " << i + 1 << "; nothing written");
  Ds ds("B", title, "sig-solve");
  ds.put("u", std::span<const double>(solution.u.data(), solution.u.size()));
  ds.put_text("method", method);
  ds.put_text("linear", backend);
  ds.put_int("converged", solution.converged ? 1 : 0);
  ds.put_int("iterations", static_cast<std::int64_t>(solution.history.size()));
  ds.put_int("dofs", solution.unknowns);
  ds.put_text("failure", solution.failure);
  if (solution.multiplier.size() > 0) {
    ds.put("multiplier",
           std::span<const double>(solution.multiplier.data(), solution.multiplier.size()));
    std::vector<std::int64_t> status(solution.active.begin(), solution.active.end());
    ds.put("status", std::span<const std::int64_t>(status));
    std::vector<std::int64_t> active;
    std::vector<double> residual, increment, step_norm;
    for (const auto& h : solution.history) {
      active.push_back(h.active);
      residual.push_back(h.residual);
      increment.push_back(h.increment);
      step_norm.push_back(h.step);
    }
    ds.put("history_active", std::span<const std::int64_t>(active));
    ds.put("history_residual", std::span<const double>(residual));
    ds.put("history_increment", std::span<const double>(increment));
    ds.put("history_step_norm", std::span<const double>(step_norm));
  }
  for (const auto& [phase, seconds] : solution.seconds)
    ds.put_scalar("time_" + phase, seconds);
  write_ds(path, ds);
}

} // namespace sig
