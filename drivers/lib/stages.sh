# Sourced by the drivers (through scene.sh and hertz_deck.sh) and pipeline tests: one-stage runs
# on a deck, the shared DS files of a mesh, the SOLVER parameter of each method, and the check
# that the stages are built.
# Needs $bin (stage executables) and a die() function from the caller.

# require_stages STAGE...: each stage executable sig-STAGE is built, else ${on_missing_stage:-die}
# names the one that is not (the drivers die; the pipeline tests set on_missing_stage=skip).
require_stages() {
  local stage
  for stage; do
    [ -x "$bin/sig-$stage" ] ||
      "${on_missing_stage:-die}" "no executable $bin/sig-$stage (build first, or set SIG_BIN)"
  done
}

# parameter_of METHOD: the parameter a method's value sets on the SOLVER card.
parameter_of() {
  case $1 in
    pdas) echo gamma ;;
    projection) echo c ;;
    alm | penalty) echo r ;;
    *) die "no parameter known for method '$1'" ;;
  esac
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

# build_base DECK DIR WHAT [STAGE...]: the stages (default mesh material contact assemble) on DECK
# in DIR, the DS files the runs of one mesh share; dies naming WHAT when a stage fails.
build_base() {
  local deck=$1 dir=$2 what=$3 stage stages
  shift 3
  stages=("$@")
  [ $# -gt 0 ] || stages=(mesh material contact assemble)
  for stage in "${stages[@]}"; do
    run_stage "$stage" "$deck" "$dir" || die "cannot build $what"
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

# stage_cards STAGE: the cards the stage reads but TITLE, from its --help (one list, the stage's).
stage_cards() {
  "$bin/sig-$1" --help | sed -n 's/^\([A-Z][A-Z0-9]*\)\( (repeatable)\)\{0,1\}:.*/\1/p' |
    grep -v '^TITLE$'
}

# same_cards STAGE DECK1 DECK2: status 0 when both decks hold the same cards of the stage.
same_cards() {
  local cards
  mapfile -t cards < <(stage_cards "$1")
  cmp -s <(deck_cards "$2" "${cards[@]}") <(deck_cards "$3" "${cards[@]}")
}

# variant_ds BASE_DECK DIR DECK: DIR's DS files up to the system for DECK, a variant of BASE_DECK
# (in the folder of its DS files): case.nopo and case.mili link to the base's, and so do case.cont
# and case.tae where DECK keeps the cards they are made of; sig-contact and sig-assemble run on
# DECK where it changes them. A variant of the mesh or the material is refused: every DS of the
# case would change. Status 1 when a stage fails or the variant is refused.
variant_ds() {
  local base_dir stage
  base_dir=$(dirname "$1")
  for stage in mesh material; do
    if ! same_cards "$stage" "$1" "$3"; then
      echo "variant_ds: $3 changes the cards of sig-$stage of $1: build it as a case of its own" >&2
      return 1
    fi
  done
  link_ds "$base_dir" "$2" nopo mili
  if same_cards contact "$1" "$3"; then
    link_ds "$base_dir" "$2" cont
  else
    run_stage contact "$3" "$2" || return 1
  fi
  if same_cards assemble "$1" "$3"; then
    link_ds "$base_dir" "$2" tae
  else
    run_stage assemble "$3" "$2"
  fi
}

# error_json RUN REFERENCE: $out/RUN/error.json, sig-error's ||u - u_ref||_V of the run against
# the reference (folders under $out); a failure goes to the caller's array `failed`.
error_json() {
  "$bin/sig-error" --json "$out/$1" "$out/$2" >"$out/$1/error.json" ||
    { failed+=("$out/$1 (sig-error)"); rm -f "$out/$1/error.json"; }
}
