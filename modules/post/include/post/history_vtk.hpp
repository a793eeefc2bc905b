#pragma once
// A dynamic case for ParaView: the states that sig-march kept in its DS "HIST"
// (integrator/history_io.hpp: output_time, u and v of shape {outputs, ndof}) as one .vtu per
// state and a .pvd collection with the output times, so that ParaView plays the motion.
#include "core/ds.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "post/vtk_writer.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sig {

/// Write OUTDIR/<stem>_NNNN.vtu (NNNN = 0-based state index) for every state of `hist`, with the
/// fields of a static solution (post/solution_fields.hpp: displacement, stress, von Mises,
/// sub-domain) plus the point field velocity (3 components, z = 0), and OUTDIR/<stem>.pvd.
/// Returns the .pvd, then the .vtu files. sig::Error naming the DS when its shapes do not match
/// the mesh or a state holds NaN or inf.
std::vector<std::filesystem::path> write_history_vtk(const std::filesystem::path& outdir,
                                                     const std::string& stem, const Mesh& mesh,
                                                     const MaterialTable& materials, const Ds& hist,
                                                     const VtkText& field_data);

} // namespace sig
