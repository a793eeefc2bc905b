#pragma once
// The rows of the stiffness matrix that one rank of `mpirun -np P sig-solve` holds: the mesh's
// nodes partitioned by METIS (on the node graph, METIS_PartMeshNodal), every dof of a node with
// its node, so that the frames of a contact node turn rows of one rank.
#include <vector>

namespace sig {

struct Mesh;

/// Per dof (d per node, d node + component) whether this rank (solver/mpi_session.hpp) holds its
/// row. Rank 0 partitions, the others receive its partition: every rank sees the same one.
/// sig::Error when the mesh has fewer cells or nodes than there are ranks.
std::vector<char> rows_of_rank(const Mesh& mesh);

} // namespace sig
