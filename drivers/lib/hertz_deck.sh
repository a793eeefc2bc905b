# Sourced by scene7a.sh, friction_hertz.sh and bench-hertz.sh: variants of the Hertz deck (and,
# through lib/stages.sh, one-stage runs).
# Needs $bin (stage executables) and a die() function from the caller.
source "$(dirname "${BASH_SOURCE[0]}")/deck.sh"
source "$(dirname "${BASH_SOURCE[0]}")/stages.sh"

# hertz_deck TEMPLATE DECK N GRADING [METHOD [VALUE]]: the template with MESH N= (and grading=
# unless GRADING is empty) and the SOLVER card's method and parameter replaced; a template with an
# INITIAL u= card (the frictional Hertz deck) gets the rigid start shift of mesh N. METHOD =
# linear gives the contact-free floor problem of the benchmark: Gamma3 held (DIRICHLET ref=3
# uy=0, and ux=0 where the template has friction, the body's only sideways support), no
# FRICTION or INITIAL card, one linear solve. Written by deck_variant (lib/deck.sh): a template
# whose cards moved fails loudly there.
hertz_deck() {
  local template=$1 deck=$2 n=$3 grading=$4 method=${5:-} value=${6:-}
  local edits=(--set "MESH.N=$n")
  [ -z "$grading" ] || edits+=(--set "MESH.grading=$grading")
  if [ "$method" = linear ]; then
    local held=uy=0
    if deck_has "$template" FRICTION; then held="ux=0 uy=0"; fi
    # The COMPARE card (Hertz) needs contact: the floor problem has none.
    edits+=(--drop-card COMPARE --drop-card FRICTION --drop-card INITIAL
      --replace-card CONTACT "DIRICHLET ref=3 $held"
      --drop SOLVER.r --drop SOLVER.gamma --drop SOLVER.c --drop SOLVER.eps --drop SOLVER.maxit
      --set SOLVER.method=linear)
  elif [ -n "$method" ]; then
    edits+=(--drop SOLVER.r --drop SOLVER.gamma --drop SOLVER.c --set "SOLVER.method=$method"
      --set "SOLVER.$(parameter_of "$method")=$value")
  fi
  if [ "$method" != linear ] && deck_value "$template" INITIAL u >/dev/null; then
    local radius
    radius=$(deck_value "$template" MESH R) || die "$template: no R= on the MESH card for the rigid start shift"
    edits+=(--set "INITIAL.u=0,-$(rigid_shift "$radius" "$n")")
  fi
  deck_variant "$template" "$deck" "${edits[@]}"
}

# rigid_shift R N: h^2 / R, h = pi R / N, the rigid start shift that puts the three lowest nodes
# of a half disc of radius R with N arc segments into contact (the frictional Hertz deck's INITIAL
# card). Needs $python.
rigid_shift() {
  "$python" -c "import math, sys; R, n = float(sys.argv[1]), int(sys.argv[2]); print(f'{(math.pi * R / n) ** 2 / R:.6g}')" "$1" "$2"
}
