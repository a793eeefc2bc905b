#pragma once
// The process's MPI, for MUMPS (Debian's libmumps-dev is built on OpenMPI). A stage started by
// mpirun is one rank of a job; any other process is a plain one, which starts MPI as a singleton
// only when it builds a MUMPS solver: the stages that never factorize with MUMPS never touch MPI.
// MPI is finalized once, at exit. The header keeps <mpi.h> out of its users.
#include <vector>

namespace sig::mpi {

/// The process was started by mpirun (OpenMPI's OMPI_COMM_WORLD_SIZE in its environment).
bool launched();
/// MPI_Init, once. A singleton gets first the environment that makes its start cheap (no
/// daemon, only the self transport; a value the user set is kept): 0.16 s against 0.5 s.
void start();
/// Whether start() has run.
bool started();
/// The rank of this process in MPI_COMM_WORLD and the number of ranks: 0 and 1 for a process
/// mpirun did not start; a launched one starts MPI to ask.
int rank();
int size();
/// Fortran handles of MPI_COMM_SELF and MPI_COMM_WORLD (MUMPS's COMM_FORTRAN); they start MPI.
int self_fortran();
int world_fortran();
/// Rank 0's `count` values, on every rank (MPI_Bcast over MPI_COMM_WORLD).
void broadcast(double* values, int count);
void broadcast(int* values, int count);
/// Every rank's `values` one after the other in rank order, on rank 0 (MPI_Gatherv over
/// MPI_COMM_WORLD); empty on the others. sig::Error when the whole exceeds an int's count.
std::vector<int> gather(const std::vector<int>& values);
/// The sum over the ranks of each of the `count` values, on every rank (MPI_Allreduce).
void sum(double* values, int count);
/// Ends every rank of the job with `code` (MPI_Abort): a rank that fails while the others wait
/// in a collective call must not leave them waiting. exit(code) when MPI is not started.
[[noreturn]] void abort(int code);

} // namespace sig::mpi
