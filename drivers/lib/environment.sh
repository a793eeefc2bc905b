# Sourced by every driver. One BLAS thread unless the caller says otherwise: OpenBLAS's threads
# spin-wait, and on a shared 2-core machine they slowed the N = 512 floor solve of
# bench-hertz.sh from 0.20 s to 0.45-0.64 s (measured under load, 3 runs each).
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}
# An installed tree (cmake --install: drivers in share/signorini/, stages in bin/) says where its
# stages are; in the source tree they are in build/bin (or $SIG_BIN).
if [ -f "$(dirname "${BASH_SOURCE[0]}")/installed.sh" ]; then
  source "$(dirname "${BASH_SOURCE[0]}")/installed.sh"
fi

# help_from_header "$@": a driver given -h or --help as its first argument prints its header
# comment (what it does, its usage) and exits 0, before any set-up, build or run.
help_from_header() {
  case ${1:-} in
    -h | --help)
      sed -n '2,/^[^#]/{/^#/s/^# \{0,1\}//p;}' "$0"
      exit 0
      ;;
  esac
}

# mpirun_ranks P COMMAND...: COMMAND as the P ranks of an mpirun job (README "Distributed
# solve"). As root it sets OpenMPI's allow-run-as-root variables; --oversubscribe lets P exceed
# the cores (one BLAS thread per rank, above), and then a rank that waits in MPI yields its core
# (OMPI_MCA_mpi_yield_when_idle, unless the caller set it): a march's many small collective calls
# took over 60 s busy-polling, against 2.4 s yielding, for scene 5's strip (64 steps) as 4 ranks
# on 2 cores.
mpirun_ranks() {
  local np=$1
  shift
  if [ "$(id -u)" -eq 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  fi
  if [ "$np" -gt "$(nproc)" ]; then
    export OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-1}
  fi
  mpirun --oversubscribe -np "$np" "$@"
}
