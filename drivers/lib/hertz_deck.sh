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
# unless GRADING is empty) and the SOLVER card's method and parameter replaced. METHOD = linear
# gives the contact-free floor problem of the benchmark: Gamma3 held (DIRICHLET ref=3 uy=0), one
# linear solve. The result is checked, so a template whose cards moved fails loudly here.
hertz_deck() {
  local template=$1 deck=$2 n=$3 grading=$4 method=${5:-} value=${6:-} name=
  local edits=(-e "/^[[:space:]]*MESH[[:space:]]/ s/([[:space:]])N=[^[:space:]]+/\1N=$n/")
  [ -z "$grading" ] || edits+=(-e "/^[[:space:]]*MESH[[:space:]]/ s/([[:space:]])grading=[^[:space:]]+/\1grading=$grading/")
  if [ "$method" = linear ]; then
    # The COMPARE card (Hertz) needs contact: the floor problem has none.
    edits+=(-e "/^[[:space:]]*COMPARE[[:space:]]/ d" -e "/^[[:space:]]*CONTACT[[:space:]]/ c\\
DIRICHLET ref=3 uy=0"
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
  sed -E "${edits[@]}" "$template" >"$deck"
  grep -qE "^[[:space:]]*MESH[[:space:]].*[[:space:]]N=$n([[:space:]]|$)" "$deck" ||
    die "$template: no MESH card with N= to replace"
  if [ -n "$grading" ]; then
    grep -qE "^[[:space:]]*MESH[[:space:]].*[[:space:]]grading=$grading([[:space:]]|$)" "$deck" ||
      die "$template: no MESH card with grading= to replace"
  fi
  if [ "$method" = linear ]; then
    ! grep -qiE '^[[:space:]]*CONTACT' "$deck" && grep -qE 'method=linear' "$deck" ||
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
