# Sourced by the distrust_*.sh pipeline tests (issue 16): small good cases, and a check that a
# stage refuses a bad input with a non-zero exit, a message holding given fragments (file, line or
# array, field), and every DS file of the case left as it was. On top of lib/common.sh ($work,
# $bin, fail).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ds_edit="python3 $root/tests/pipeline/lib/ds_edit.py"

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
MESH generator=disc centre=0,15 R=1 N=16
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
  local what=$1 stage=$2 outdir=$4 before after failed=$failures
  before=$(fingerprints "$outdir")
  refused "$@"
  after=$(fingerprints "$outdir")
  [ "$before" = "$after" ] || fail "$what: sig-$stage changed the files of $outdir: $(diff <(echo "$before") <(echo "$after") | head -4)"
  [ "$failures" -ne "$failed" ] || echo "ok ($test_name): $what: $(grep -m1 -i 'error' <<< "$refusal" | cut -c1-160)"
}

# distrust_finish: exit 1 naming the failed checks, or say how many refusals held.
distrust_finish() {
  finish "$checks refusals with exit status, message and the case's files intact"
}
