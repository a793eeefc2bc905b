#pragma once
// A dynamic case for ParaView: the states that sig-march kept in its DS "HIST"
// (stages/history_io.hpp: output_time, u and v of shape {outputs, ndof}) as one .vtu per
// state and a .pvd collection with the output times, so that ParaView plays the motion. A march
// with contact also left contact_node (1-based mesh nodes of Gamma3, p values) and pressure
// (shape {outputs, p}), with friction tangential_pressure: each state then shows the contact
// pressure of Fig 8.2 and the tangential traction. A march in velocity adds per step the
// statuses and forces: each state then also shows normal_status (0 free, 1 RNI, 2 CUV),
// friction_status (0 none, 1 S=, 2 S+, 3 S-) and, without tangential_pressure (frictionless, or a
// case.hist written before the one layout), force_t / weight as tangential_pressure.
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
/// sub-domain) plus the point field velocity (3 components, z = 0) and, when `hist` has the
/// arrays contact_node and pressure, the point field contact_pressure (0 off Gamma3), and
/// OUTDIR/<stem>.pvd. Returns the .pvd, then the .vtu files. sig::Error naming the DS when its
/// shapes do not match the mesh, a contact node is not a mesh node, or a state holds NaN or inf.
std::vector<std::filesystem::path>
write_history_vtk(const std::filesystem::path& outdir, const std::string& stem, const Mesh& mesh,
                  const MaterialTable& materials, const Ds& hist, const VtkText& field_data,
                  VtkCompression compression = VtkCompression::zlib);

} // namespace sig
