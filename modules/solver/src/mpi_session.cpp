#include "solver/mpi_session.hpp"

#include "core/error.hpp"

// The C interface alone: OpenMPI's <mpi.h> in C++ pulls in its deprecated C++ bindings, which
// live in a library (libmpi_cxx) MPI::MPI_C does not link.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <system_error>
// gcc says AddressSanitizer by a macro, clang (14) by __has_feature only.
#if defined(__SANITIZE_ADDRESS__)
#define SIG_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SIG_ADDRESS_SANITIZER 1
#endif
#endif
#ifdef SIG_ADDRESS_SANITIZER
#include <sanitizer/lsan_interface.h>
#endif

namespace sig::mpi {

namespace {

/// A singleton's own session folder (empty when OpenMPI's default or the user's serves).
std::filesystem::path& session_base() {
  static std::filesystem::path base;
  return base;
}

void remove_session_folder() {
  if (session_base().empty()) return;
  std::error_code ignored; // a folder left in the temporary area is no error of the run
  std::filesystem::remove_all(session_base(), ignored);
}

void finalize() {
#ifdef SIG_ADDRESS_SANITIZER
  // The leak check at exit would run after MPI_Finalize has unloaded OpenMPI's components, whose
  // frames LeakSanitizer could then not name for tests/lsan-openmpi.supp: check here instead,
  // while they are loaded (the rest of the process has ended its work: this runs at exit).
  __lsan_do_leak_check();
#endif
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
  remove_session_folder();
}

/// Isolated singletons all take OpenMPI 4's job family 0, so concurrent ones (ctest -j, the
/// stages of two chains) race on one session folder, TMPDIR/ompi.HOST.UID/jf.0: one fails its
/// mkdir ("File exists", orte_init failed) or removes the folder under another. Each singleton
/// gets a folder of its own unless the user chose one (OMPI_MCA_orte_tmpdir_base).
void use_own_session_folder() {
  if (std::getenv("OMPI_MCA_orte_tmpdir_base") != nullptr) return;
  std::string pattern = (std::filesystem::temp_directory_path() / "sig-mpi-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) return; // OpenMPI's default then, as before
  session_base() = pattern;
  setenv("OMPI_MCA_orte_tmpdir_base", pattern.c_str(), 1);
}

} // namespace

bool launched() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr;
}

bool started() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  return initialized != 0;
}

void start() {
  if (started()) return;
  if (!launched()) {
    // A singleton of OpenMPI 4 starts an orted daemon and probes every transport unless told
    // not to: measured on the tiny MPI_Init + MPI_Finalize, 0.5 s plain, 0.37 s isolated,
    // 0.16 s isolated with only the self transport (one rank talks to nobody else).
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    use_own_session_folder();
  }
  if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS) {
    remove_session_folder();
    throw Error("MPI: MPI_Init failed");
  }
  std::atexit(finalize);
}

namespace {

/// `query` of MPI_COMM_WORLD (its rank or size), or `alone` for a process mpirun did not start
/// and that has not started MPI.
int of_world(int (*query)(MPI_Comm, int*), int alone) {
  if (!launched() && !started()) return alone;
  start();
  int value = alone;
  query(MPI_COMM_WORLD, &value);
  return value;
}

} // namespace

int rank() {
  return of_world(MPI_Comm_rank, 0);
}

int size() {
  return of_world(MPI_Comm_size, 1);
}

int self_fortran() {
  start();
  return static_cast<int>(MPI_Comm_c2f(MPI_COMM_SELF));
}

int world_fortran() {
  start();
  return static_cast<int>(MPI_Comm_c2f(MPI_COMM_WORLD));
}

void broadcast(double* values, int count) {
  MPI_Bcast(values, count, MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

void broadcast(int* values, int count) {
  MPI_Bcast(values, count, MPI_INT, 0, MPI_COMM_WORLD);
}

std::vector<int> gather(const std::vector<int>& values) {
  // A rank that throws here ends the job (run_stage_on_ranks): the others never wait for it.
  SIG_VERIFY(values.size() <= std::numeric_limits<int>::max(),
             "MPI: a rank's " << values.size() << " values exceed an int's count");
  const int count = static_cast<int>(values.size());
  std::vector<int> counts(rank() == 0 ? static_cast<std::size_t>(size()) : 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> offsets(counts.size(), 0);
  long long total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    SIG_VERIFY(total + counts[r] <= std::numeric_limits<int>::max(),
               "MPI: the ranks' values exceed an int's count on the host");
    offsets[r] = static_cast<int>(total);
    total += counts[r];
  }
  std::vector<int> whole(static_cast<std::size_t>(total));
  MPI_Gatherv(values.data(), count, MPI_INT, whole.data(), counts.data(), offsets.data(), MPI_INT,
              0, MPI_COMM_WORLD);
  return whole;
}

void sum(double* values, int count) {
  MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

void abort(int code) {
  if (started()) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

} // namespace sig::mpi
