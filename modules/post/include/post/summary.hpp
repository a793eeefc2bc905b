#pragma once
// summary.json: the facts of one solved case that tables, charts and tests read, under stable
// keys (see build_summary). The Hertz comparison is separate: a scene script decides whether the
// case is Hertz's and calls hertz_json.
#include "core/ds.hpp"
#include "core/json.hpp"
#include "mesh/mesh.hpp"
#include "post/contact_table.hpp"
#include "post/hertz.hpp"

#include <string>
#include <utility>
#include <vector>

namespace sig {

/// Phase -> seconds: every scalar array `time_<phase>` of the given DS, in order; a later DS
/// replaces a phase of an earlier one.
std::vector<std::pair<std::string, double>> gather_times(const std::vector<const Ds*>& sources);

/// Keys, in this order: title, method, converged (bool), failure (why the solver stopped without
/// converging, "" otherwise), iterations, dofs, multipliers,
/// contact_elements, contact_nodes, nodes, triangles, backend, residual_history,
/// increment_history, active_history, times (phase -> seconds; "solve" is the linear or
/// nonlinear solve). multipliers = number of multiplier unknowns: the contact element count for
/// method alm, 0 otherwise. contact_nodes = rows with status contact. Histories are empty lists
/// when the solution has none. A solve with the convexification loop adds convexification:
/// converged, outer_iterations, inner_iterations (per convex solve), displacement_change,
/// force_change, mu_change, status_changes (per convex solve), cycle, failure.
Json build_summary(const std::string& title, const Mesh& mesh, const Ds& solution,
                   const std::vector<ContactRow>& contact,
                   const std::vector<std::pair<std::string, double>>& times);

/// Hertz's values beside ours: keys b, p0, p_max, p_max_rel_error, half_width,
/// half_width_error, l2_rel_error.
Json hertz_json(const HertzData& data, const PressureError& error);

} // namespace sig
