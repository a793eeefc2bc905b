# Sourced by the scene and benchmark drivers: the repository, the executables, the Python with
# matplotlib, and die() naming the script.
source "$(dirname "${BASH_SOURCE[0]}")/environment.sh"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
python=${PYTHON:-/usr/bin/python3}

die() {
  echo "$(basename "$0"): error: $*" >&2
  exit 1
}
