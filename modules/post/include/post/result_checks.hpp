#pragma once
// What sig-post re-checks in the results it reads, beyond their checksums (core/ds.hpp checks
// those, and every Float64 value for NaN and inf): the counts and codes in their ranges and the
// arrays of the sizes the others say, so that a case.b or case.hist edited by hand, written by
// another program or of another mesh is refused before a picture is drawn from it. Errors name
// the file and the array. The ranges a deck states (TIME k=, T=, output_every=) come from the one
// table of core/ranges.hpp.
#include "core/ds.hpp"
#include "mesh/mesh.hpp"

namespace sig {

/// DS B of sig-solve (stages/solution_ds.hpp): converged in {0, 1}, iterations >= 0, dofs
/// between the mesh's dofs and those plus two per contact element, u of the mesh's size and,
/// when converged, within 1e6 of its diameters (core/ranges.hpp displacement_range), the
/// statuses of every contact element among their codes, the histories of one length with counts
/// of contact nodes in 0..m.
void verify_solution_ds(const Ds& b, const Mesh& mesh);

/// DS HIST of sig-march (stages/history_io.hpp): k, T, output_every in the TIME card's
/// ranges, steps = T / k, ndof the mesh's dofs, u and v of shape {outputs, ndof}, u of a converged
/// march within 1e6 of the mesh's diameters, output_step
/// increasing within the steps done and output_time = time[output_step], the per-step arrays
/// (energies of an elastodynamic march; those of a march in velocity) of one length (steps + 1,
/// fewer if the march stopped), converged in {0, 1}.
void verify_history_ds(const Ds& hist, const Mesh& mesh);

} // namespace sig
