#pragma once
// A load-stepped (large-deformation) case for ParaView: the state of every converged load step
// that sig-solve kept in case.b (stages/finite_strain_stage.hpp: step_load, step_u and, with
// contact, step_multiplier and step_status) as one .vtu each, in a .pvd whose pseudo-time is the
// load factor, so that ParaView plays the ring being crushed step by step (scene 7b).
#include "core/ds.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "post/vtk_writer.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sig {

/// True if `solution` (DS "B") holds per-load-step states (array step_u).
bool has_load_step_states(const Ds& solution);

/// Number of stored load-step states: the rows of step_u. sig::Error naming the DS when step_u
/// is not {rows, 2 x nodes} or has more rows than step_load.
std::size_t load_step_count(const Ds& solution, const Mesh& mesh);

/// Write OUTDIR/<stem>_NNNN.vtu for load step NNNN + 1 with the fields of a static solution
/// (post/solution_fields.hpp; contact pressure and status on Gamma3 when `cont` is given) and
/// the field data `field_data` + load_step + load_factor, and OUTDIR/<stem>.pvd with time = load
/// factor. Returns the .pvd, then the .vtu files. sig::Error naming the DS when shapes do not
/// match the mesh or the contact elements, or a state holds NaN or inf.
std::vector<std::filesystem::path>
write_load_step_vtk(const std::filesystem::path& outdir, const std::string& stem, const Mesh& mesh,
                    const MaterialTable& materials, const Ds& solution, const Ds* cont,
                    const VtkText& field_data, VtkCompression compression = VtkCompression::zlib);

} // namespace sig
