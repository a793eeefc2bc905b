# Sourced by the scene drivers (after scene.sh) for their adapted convergence studies (issue 29,
# scenes 4, 5, 6 and 7a): the loop with its overkill references and errors, the finest uniform
# mesh's chain timed as the loop's steps are, and the errors against the overkill. They use $out,
# $bin, $root, die, progress_step, run_stage and error_json of scene.sh, and the caller's array
# `failed`.

# logged LOG COMMAND...: COMMAND's output appended to LOG, shown and fatal when it fails.
logged() {
  local log=$1
  shift
  "$@" >>"$log" 2>&1 || { cat "$log" >&2; die "$(basename "$1") failed (log: $log)"; }
}

# overkill_references ADAPTED STEPS SHAPE TEMPLATE: ADAPTED/overkill1 and overkill2, the last
# mesh of drivers/adapt.sh's loop in ADAPTED (STEPS steps) refined uniformly once and twice
# (sig-refine --theta 1; new nodes on the arcs of SHAPE's MESH card), each solved or marched by
# drivers/chain.sh on TEMPLATE with its MESH card replaced (TEMPLATE may also refine what the mesh
# does not: scene 5's overkill marches with a finer time step) and estimated by sig-estimate.
# The adapted meshes nest, each refining the one before: overkill2 is finer everywhere than
# every one of them.
overkill_references() {
  local adapted=$1 steps=$2 shape=$3 template=$4 level name
  local from_dir=$adapted/step$((steps - 1)) from_deck=$adapted/step$((steps - 1)).dat
  [ "$steps" -gt 1 ] || from_deck=$shape
  for level in 1 2; do
    name=overkill$level
    logged "$adapted/$name.log" "$bin/sig-refine" "$from_deck" -o "$from_dir" --theta 1 \
      --shape "$shape" --mesh "$adapted/$name.nopo"
    awk -v mesh="MESH file=$name.nopo" 'toupper($1) == "MESH" { print mesh; next } { print }' \
      "$template" >"$adapted/$name.dat"
    mkdir -p "$adapted/$name"
    logged "$adapted/$name.log" "$root/drivers/chain.sh" "$adapted/$name.dat" -o "$adapted/$name"
    logged "$adapted/$name.log" "$bin/sig-estimate" "$adapted/$name.dat" -o "$adapted/$name"
    from_dir=$adapted/$name from_deck=$adapted/$name.dat
    progress_step "${adapted#"$out"/}/$name"
  done
}

# adapted_study ADAPTED DECK STEPS: drivers/adapt.sh on DECK into ADAPTED (a folder under $out;
# STEPS steps, Dörfler theta 0.5), its overkill references (overkill_references, on DECK), and
# the error of every step and of overkill1 against overkill2 (error.json).
adapted_study() {
  local adapted=$1 deck=$2 steps=$3 k
  local name=${adapted#"$out"/}
  "$root/drivers/adapt.sh" "$deck" -o "$adapted" --steps "$steps" --theta 0.5 \
    >"$adapted/adapt.log" 2>&1 || { tail -20 "$adapted/adapt.log" >&2; die "adapt.sh failed"; }
  progress_step "$name ($steps steps)"
  overkill_references "$adapted" "$steps" "$deck" "$deck"
  for ((k = 0; k < steps; k++)); do
    error_json "$name/step$k" "$name/overkill2"
  done
  error_json "$name/overkill1" "$name/overkill2"
}

# timed_chain DECK DIR: drivers/chain.sh on DECK into DIR (the finest uniform mesh judged, a
# process a stage), its wall clock, start-ups included, in DIR/chain_wall.txt; then the same chain
# the loop's way into DIR/one_process (sig-adapt --steps 1: one process, files synced once, its
# estimate included; elapsed_s of its loop.csv), shown beside.
timed_chain() {
  local deck=$1 dir=$2 t0 us
  mkdir -p "$dir"
  t0=${EPOCHREALTIME/./}
  logged "$dir.log" "$root/drivers/chain.sh" "$deck" -o "$dir"
  us=$((${EPOCHREALTIME/./} - t0))
  printf '%d.%06d\n' $((us / 1000000)) $((us % 1000000)) >"$dir/chain_wall.txt"
  logged "$dir.log" "$bin/sig-adapt" "$deck" -o "$dir/one_process" --steps 1 \
    --clock-start "${EPOCHREALTIME/./}"
}

# adapted_errors FOLDER STEPS LADDER REFERENCE DECK N...: the errors of an adapted study (folders
# under $out): FOLDER/step<k> (k < STEPS) and FOLDER/overkill1 against FOLDER/overkill2
# (error.json); the uniform reference REFERENCE's own estimate (sig-estimate on its deck DECK);
# each uniform run LADDER<N> against overkill2 beside its own (error_overkill.json: shown, the
# overkill is not finer than the uniform meshes everywhere). Failures go to `failed`.
adapted_errors() {
  local folder=$1 steps=$2 ladder=$3 reference=$4 deck=$5 k n
  shift 5
  for ((k = 0; k < steps; k++)); do
    [ ! -d "$out/$folder/step$k" ] || error_json "$folder/step$k" "$folder/overkill2"
  done
  error_json "$folder/overkill1" "$folder/overkill2"
  run_stage estimate "$out/$reference/$deck" "$out/$reference" ||
    failed+=("$out/$reference (sig-estimate)")
  for n in "$@"; do
    "$bin/sig-error" --json "$out/$ladder$n" "$out/$folder/overkill2" \
      >"$out/$ladder$n/error_overkill.json" ||
      {
        failed+=("$out/$ladder$n (sig-error against the overkill)")
        rm -f "$out/$ladder$n/error_overkill.json"
      }
  done
}
