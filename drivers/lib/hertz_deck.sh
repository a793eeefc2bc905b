# Sourced by scene7a.sh, friction_hertz.sh and bench-hertz.sh: variants of the Hertz deck and
# one-stage runs.
# Needs $bin (stage executables) and a die() function from the caller.

# The parameter a method's value sets on the SOLVER card.
parameter_of() {
  case $1 in
    pdas) echo gamma ;;
    projection) echo c ;;
    alm | penalty) echo r ;;
    *) die "no parameter known for method '$1'" ;;
  esac
}

# hertz_deck TEMPLATE DECK N GRADING [METHOD [VALUE]]: the template with MESH N= (and grading=
# unless GRADING is empty) and the SOLVER card's method and parameter replaced; a template with an
# INITIAL u= card (the frictional Hertz deck) gets the rigid start shift of mesh N. METHOD =
# linear gives the contact-free floor problem of the benchmark: Gamma3 held (DIRICHLET ref=3
# uy=0, and ux=0 where the template has friction, the body's only sideways support), no
# FRICTION or INITIAL card, one linear solve. The result is checked, so a template whose cards
# moved fails loudly here.
hertz_deck() {
  local template=$1 deck=$2 n=$3 grading=$4 method=${5:-} value=${6:-} name=
  local edits=(-e "/^[[:space:]]*MESH[[:space:]]/ s/([[:space:]])N=[^[:space:]]+/\1N=$n/")
  [ -z "$grading" ] || edits+=(-e "/^[[:space:]]*MESH[[:space:]]/ s/([[:space:]])grading=[^[:space:]]+/\1grading=$grading/")
  local initial=0 held=uy=0
  grep -qiE '^[[:space:]]*INITIAL[[:space:]](.*[[:space:]])?u=' "$template" && initial=1
  grep -qiE '^[[:space:]]*FRICTION[[:space:]]' "$template" && held="ux=0 uy=0"
  if [ "$method" = linear ]; then
    # The COMPARE card (Hertz) needs contact: the floor problem has none.
    edits+=(-e "/^[[:space:]]*(COMPARE|FRICTION|INITIAL)[[:space:]]/ d"
      -e "/^[[:space:]]*CONTACT[[:space:]]/ c\\
DIRICHLET ref=3 $held"
      -e "/^[[:space:]]*SOLVER[[:space:]]/ {
        s/[[:space:]](r|gamma|c|eps|maxit)=[^[:space:]]+//g
        s/([[:space:]])method=[^[:space:]]+/\1method=linear/
      }")
  elif [ -n "$method" ]; then
    name=$(parameter_of "$method")
    edits+=(-e "/^[[:space:]]*SOLVER[[:space:]]/ {
      s/[[:space:]](r|gamma|c)=[^[:space:]]+//g
      s/([[:space:]])method=[^[:space:]]+/\1method=$method $name=$value/
    }")
  fi
  local shift=
  if [ $initial -eq 1 ] && [ "$method" != linear ]; then
    local radius
    radius=$(sed -nE '/^[[:space:]]*MESH[[:space:]]/ s/.*[[:space:]]R=([^[:space:]]+).*/\1/p' "$template")
    [ -n "$radius" ] || die "$template: no R= on the MESH card for the rigid start shift"
    shift=$(rigid_shift "$radius" "$n")
    edits+=(-e "/^[[:space:]]*INITIAL[[:space:]]/ s/([[:space:]])u=[^[:space:]]+/\1u=0,-$shift/")
  fi
  sed -E "${edits[@]}" "$template" >"$deck"
  grep -qE "^[[:space:]]*MESH[[:space:]].*[[:space:]]N=$n([[:space:]]|$)" "$deck" ||
    die "$template: no MESH card with N= to replace"
  if [ -n "$grading" ]; then
    grep -qE "^[[:space:]]*MESH[[:space:]].*[[:space:]]grading=$grading([[:space:]]|$)" "$deck" ||
      die "$template: no MESH card with grading= to replace"
  fi
  if [ -n "$shift" ]; then
    grep -qE "^[[:space:]]*INITIAL[[:space:]](.*[[:space:]])?u=0,-$shift([[:space:]]|$)" "$deck" ||
      die "$template: no INITIAL u= to set the rigid shift on"
  fi
  if [ "$method" = linear ]; then
    ! grep -qiE '^[[:space:]]*(CONTACT|FRICTION|INITIAL)' "$deck" &&
      grep -qE "^DIRICHLET ref=3 $held$" "$deck" && grep -qE 'method=linear' "$deck" ||
      die "$template: cannot turn the deck into the linear floor problem"
  elif [ -n "$method" ]; then
    grep -qE "^[[:space:]]*SOLVER[[:space:]].*method=$method $name=$value([[:space:]]|$)" "$deck" ||
      die "$template: no SOLVER card with method= to replace"
  fi
}

# rigid_shift R N: h^2 / R, h = pi R / N, the rigid start shift that puts the three lowest nodes
# of a half disc of radius R with N arc segments into contact (the frictional Hertz deck's INITIAL
# card). Needs $python.
rigid_shift() {
  "$python" -c "import math, sys; R, n = float(sys.argv[1]), int(sys.argv[2]); print(f'{(math.pi * R / n) ** 2 / R:.6g}')" "$1" "$2"
}

# run_stage STAGE DECK DIR: one stage, its output kept in DIR/<stage>.log and shown on failure.
run_stage() {
  local stage=$1 deck=$2 dir=$3
  if ! "$bin/sig-$stage" "$deck" -o "$dir" >"$dir/$stage.log" 2>&1; then
    cat "$dir/$stage.log" >&2
    echo "sig-$stage failed for $deck (log: $dir/$stage.log)" >&2
    return 1
  fi
}

# build_base DECK DIR WHAT: sig-mesh, sig-material, sig-contact and sig-assemble of DECK in DIR,
# the DS files the runs of one mesh share; dies naming WHAT when a stage fails.
build_base() {
  local stage
  for stage in mesh material contact assemble; do
    run_stage "$stage" "$1" "$2" || die "cannot build $3"
  done
}

# link_ds FROM DIR DS...: DIR/case.<DS> links to FROM/case.<DS> (FROM relative to DIR, or
# absolute), so that a run reuses the DS files of an earlier stage.
link_ds() {
  local from=$1 dir=$2 ds
  shift 2
  for ds; do
    ln -s "$from/case.$ds" "$dir/case.$ds"
  done
}
