#!/usr/bin/env bash
# drivers/scenes.sh [--tee] [-o OUTDIR] [NAME...]: every scene's quick variant, one after the
# other, then the index of them all, OUTDIR/index.md and OUTDIR/index.html
# (postproc/scene_index.py: each scene's checks, key table, charts, links to its report, its
# ParaView files and its notes, datafiles/<scene>/README.md).
#
# The scenes are the drivers drivers/scene[0-9]*.sh and drivers/friction_hertz.sh: a new scene's
# driver drivers/sceneX.sh (with --quick and -o, lib/scene.sh's parse_quick_out) is picked up
# without editing this file. NAME... runs those only (e.g. scene7a friction_hertz). Each runs as
#   drivers/NAME.sh --quick -o OUTDIR/NAME        (its output in OUTDIR/NAME.log; with --tee on the
#                                                 terminal too: drivers/run.sh's default scene)
# A driver that fails does not stop the others: the index shows it as a FAIL, as it does a scene
# whose report wrote no scene.json, and the script exits 1.
#
# Environment: SIG_BIN (stage executables), PYTHON; SIG_SCENE_DRIVERS (the folder of the scene
# drivers, default drivers/; the pipeline test points it at canned ones).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/scene.sh"

usage() {
  cat <<EOF
usage: drivers/scenes.sh [--tee] [-o OUTDIR] [NAME...]
  -o OUTDIR   results folder (default out): OUTDIR/NAME/ per scene, OUTDIR/index.md, index.html
  --tee       each driver's output on the terminal too, not only in OUTDIR/NAME.log
  NAME...     these scenes only (default: every drivers/scene[0-9]*.sh and friction_hertz.sh)
  -h, --help  this message
EOF
}

out=out
tee=0
names=()
parse_options -o=out --tee:tee=1 @names -- "$@"

driver_dir=${SIG_SCENE_DRIVERS:-$root/drivers}
drivers=()
if [ ${#names[@]} -eq 0 ]; then
  for driver in "$driver_dir"/scene[0-9]*.sh "$driver_dir"/friction_hertz.sh; do
    [ -f "$driver" ] && drivers+=("$driver")
  done
else
  for name in "${names[@]}"; do
    [ -f "$driver_dir/$name.sh" ] || die "no scene driver $driver_dir/$name.sh"
    drivers+=("$driver_dir/$name.sh")
  done
fi
[ ${#drivers[@]} -gt 0 ] || die "no scene driver in $driver_dir"

mkdir -p "$out"
out=$(cd "$out" && pwd)
runs=$out/runs.tsv
: >"$runs"
echo "scenes.sh: ${#drivers[@]} scenes, quick variants, into $out"
progress_begin ${#drivers[@]}
for driver in "${drivers[@]}"; do
  name=$(basename "$driver" .sh)
  command="drivers/$name.sh --quick -o $out/$name"
  echo "scenes.sh: $command (log: $out/$name.log)"
  t0=$SECONDS
  status=0
  if [ "$tee" = 1 ]; then
    bash "$driver" --quick -o "$out/$name" 2>&1 | tee "$out/$name.log" || status=$?
  else
    bash "$driver" --quick -o "$out/$name" >"$out/$name.log" 2>&1 || status=$?
  fi
  printf '%s\t%s\t%s\t%s\t%s\n' "$name" "$command" "$status" "$((SECONDS - t0))" "$name.log" >>"$runs"
  if [ $status -ne 0 ]; then
    [ "$tee" = 1 ] || tail -n 5 "$out/$name.log" | sed 's/^/    /'
    progress_step "$name FAILED (exit $status)"
  else
    progress_step "$name"
  fi
done

status=0
"$python" "$root/postproc/scene_index.py" "$out" --runs "$runs" || status=$?
echo
echo "Index: $out/index.html"
echo "       $out/index.md"
exit $status
