# Sourced by the pipeline tests (ctest runs them from the source tree with SIG_BIN set): the
# repository, the stages, the Python, a scratch folder $work removed on exit, and the three ways a
# test reports: fail (counted, the test goes on), die (nothing further can be checked) and skip
# (exit 77: this machine lacks a tool the test needs, never a feature of ours).
#   $test_name  the test's name in its messages: the script's file name without .sh
test_name=$(basename "$0" .sh)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
python=${PYTHON:-/usr/bin/python3}
# The Python parts of the tests import pipeline_checks (check, finish) from here.
export PYTHONPATH=$root/tests/pipeline/lib${PYTHONPATH:+:$PYTHONPATH}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
checks=0

fail() {
  echo "FAIL ($test_name): $*"
  failures=$((failures + 1))
}

die() {
  echo "FAIL ($test_name): $*" >&2
  exit 1
}

skip() {
  echo "$test_name: skipped, $*"
  exit 77
}

# require_stages STAGE... (from the drivers' stages.sh): skip unless each sig-STAGE is built.
on_missing_stage=skip
source "$root/drivers/lib/stages.sh"

# require_command NAME [WHY]: skip unless NAME is on the PATH.
require_command() {
  command -v "$1" >/dev/null || skip "no $1${2:+ ($2)}"
}

# require_python MODULE...: skip unless $python imports each MODULE.
require_python() {
  local module
  for module; do
    "$python" -c "import $module" 2>/dev/null || skip "$python cannot import $module"
  done
}

# refused WHAT STAGE DECK OUTDIR FRAGMENT...: sig-STAGE on DECK -o OUTDIR exits non-zero with
# every fragment in its message (case-insensitive); a failed check otherwise. Counts one check;
# the message is in $refusal for the caller's own checks.
refused() {
  local what=$1 stage=$2 deck=$3 outdir=$4 text status=0
  shift 4
  checks=$((checks + 1))
  refusal=$("$bin/sig-$stage" "$deck" -o "$outdir" 2>&1) || status=$?
  if [ "$status" -eq 0 ]; then
    fail "$what: sig-$stage exited 0: $refusal"
    return
  fi
  for text in "$@"; do
    grep -qiF -- "$text" <<<"$refusal" || fail "$what: the message lacks '$text': $refusal"
  done
}

# quick_driver SCENE: drivers/SCENE.sh --quick -o $work/SCENE, its log's tail and death if it fails.
quick_driver() {
  SIG_BIN=$bin "$root/drivers/$1.sh" --quick -o "$work/$1" >"$work/driver.log" 2>&1 ||
    { tail -40 "$work/driver.log"; die "drivers/$1.sh --quick failed"; }
}

# finish SUMMARY: exit 1 naming the failed checks, or print SUMMARY.
finish() {
  [ "$failures" -eq 0 ] || { echo "$test_name: $failures of $checks checks failed"; exit 1; }
  echo "$test_name: $*"
}
