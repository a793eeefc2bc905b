# Sourced by the distrust_*.sh pipeline tests (issue 16): small good cases, and a check that a
# stage refuses a bad input with a non-zero exit, a message holding given fragments (file, line or
# array, field), and every DS file of the case left as it was.
#   SIG_BIN   the stages;  $work a scratch folder;  $name the test's name (messages)
bin=${SIG_BIN:?SIG_BIN is not set}
ds_edit="python3 $(pwd)/tests/pipeline/lib/ds_edit.py"
failures=0
checks=0

fail() {
  echo "FAIL ($name): $*"
  failures=$((failures + 1))
}

# A static case without contact: a 4 x 2 rectangle clamped on the left, pulled down on the right.
static_deck() {
  cat > "$1" <<'EOF'
TITLE distrust: a small clamped block
MESH generator=rectangle lx=4 ly=1 nx=4 ny=2
MATERIAL law=hooke E=200 nu=0.3 plane=stress
DIRICHLET ref=1 ux=0 uy=0
TRACTION ref=4 f=0,-0.01
SOLVER method=linear
OUTPUT vtk=yes
EOF
}

# The Hertz half disc of scene 7a at N = 16: a case with contact (CONT) and a nonlinear solve.
contact_deck() {
  sed -e 's/N=256/N=16/' datafiles/scene7a/hertz.dat > "$1"
}

# A free disc marched in time: a case with a HIST.
dynamic_deck() {
  cat > "$1" <<'EOF'
TITLE distrust: a free disc
MESH generator=disc center=0,15 R=1 N=16
MATERIAL law=hooke E=100 nu=0.35 plane=strain rho=1000
INITIAL v=0,-10
TIME scheme=midpoint T=0.1 k=0.01 output_every=5
SOLVER linear=cholmod
OUTPUT vtk=yes
EOF
}

# chain DECK OUTDIR: the whole chain of the deck, quietly; fails the test if a stage fails.
chain() {
  drivers/chain.sh "$1" -o "$2" > "$2.log" 2>&1 || { fail "the good chain of $1 failed: $(tail -3 "$2.log")"; return 1; }
}

# The checksums of every DS file and result of OUTDIR (links followed).
fingerprints() {
  (cd "$1" && find . -maxdepth 1 \( -type f -o -type l \) ! -name '*.log' -print0 | sort -z |
    xargs -0 -r sha256sum)
}

# expect_refusal WHAT STAGE DECK OUTDIR FRAGMENT...: STAGE on DECK -o OUTDIR must exit non-zero
# with every fragment in its message (case-insensitive) and leave every file of OUTDIR as it was.
expect_refusal() {
  local what=$1 stage=$2 deck=$3 outdir=$4
  shift 4
  checks=$((checks + 1))
  local before after message status=0
  before=$(fingerprints "$outdir")
  message=$("$bin/sig-$stage" "$deck" -o "$outdir" 2>&1) || status=$?
  after=$(fingerprints "$outdir")
  if [ "$status" -eq 0 ]; then
    fail "$what: sig-$stage exited 0: $message"
    return
  fi
  local failed=$failures
  for text in "$@"; do
    grep -qiF -- "$text" <<< "$message" || fail "$what: the message lacks '$text': $message"
  done
  [ "$before" = "$after" ] || fail "$what: sig-$stage changed the files of $outdir: $(diff <(echo "$before") <(echo "$after") | head -4)"
  [ "$failures" -ne "$failed" ] || echo "ok ($name): $what: $(grep -m1 -i 'error' <<< "$message" | cut -c1-160)"
}

finish() {
  [ "$failures" -eq 0 ] || { echo "$name: $failures of $checks checks failed"; exit 1; }
  echo "$name: $checks refusals with exit status, message and the case's files intact"
}
