# Sourced by the scene and benchmark drivers: the repository, the executables, the Python with
# matplotlib, and die() naming the script.
source "$(dirname "${BASH_SOURCE[0]}")/environment.sh"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
# The reports read DS files through this build's sig-dump (postproc/sigreport/ds.py).
export SIG_BIN=$bin
python=${PYTHON:-/usr/bin/python3}
source "$(dirname "${BASH_SOURCE[0]}")/deck.sh"

die() {
  echo "$(basename "$0"): error: $*" >&2
  exit 1
}

# require_stages STAGE...: each stage executable sig-STAGE is built.
require_stages() {
  local stage
  for stage; do
    [ -x "$bin/sig-$stage" ] || die "no executable $bin/sig-$stage (build first, or set SIG_BIN)"
  done
}

# require_charts: the Python of the reports has matplotlib and numpy.
require_charts() {
  "$python" -c 'import matplotlib, numpy' 2>/dev/null ||
    die "$python lacks matplotlib or numpy (Debian: python3-matplotlib python3-numpy)"
}

# parse_quick_out DEFAULT_OUTDIR "$@": a scene driver's options --quick and -o OUTDIR, and -h,
# --help (the driver's usage); sets quick (0 or 1) and out.
parse_quick_out() {
  out=$1
  shift
  quick=0
  while [ $# -gt 0 ]; do
    case $1 in
      --quick) quick=1 ;;
      -o)
        [ $# -ge 2 ] || die "-o needs a folder"
        out=$2
        shift
        ;;
      -h | --help)
        usage
        exit 0
        ;;
      *)
        usage >&2
        die "unknown argument '$1'"
        ;;
    esac
    shift
  done
}

# record_seconds START: append the wall seconds of the runs since START ($SECONDS then) to
# command.txt, the "seconds" of the scene index entry (out/<scene>/scene.json).
record_seconds() {
  echo "seconds: $((SECONDS - $1))" >>"$out/command.txt"
}

# provenance: the lines of a scene's command.txt that say how it was made (the driver's
# $invocation, $out and $template; the date, host, revision and executables).
provenance() {
  echo "command: $invocation"
  echo "outdir: $out"
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "host: $(uname -n), $(nproc) cores"
  echo "revision: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "SIG_BIN: $bin"
  echo "template: $template"
}
