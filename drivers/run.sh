#!/usr/bin/env bash
# drivers/run.sh [--all]: install what is missing, build, run the default scene (Hertz contact,
# scene 7a, quick variant), write the index of what it ran (out/index.html and out/index.md,
# postproc/scene_index.py) and say where the report, the ParaView files and the index are.
# --all: every scene's quick variant instead (drivers/scenes.sh) and the index of them all.
set -euo pipefail
source "$(dirname "$0")/lib/environment.sh"
help_from_header "$@"
case ${1:-} in
  "" | --all) ;;
  *)
    echo "usage: drivers/run.sh [--all]" >&2
    exit 2
    ;;
esac
source "$(dirname "$0")/setup.sh"
cd "$SIG_ROOT"
if [ "${1:-}" = --all ]; then
  exec "$SIG_ROOT/drivers/scenes.sh" -o "$SIG_ROOT/out"
fi
status=0
"$SIG_ROOT/drivers/scenes.sh" --tee -o "$SIG_ROOT/out" scene7a || status=$?
echo
echo "Report:          $SIG_ROOT/out/scene7a/report.md"
echo "ParaView files:  $(ls "$SIG_ROOT"/out/scene7a/N256/pdas_1e2/*.pvd 2>/dev/null | head -1)"
echo "                 (all runs: ls out/scene7a/N*/*/*.pvd; open with: paraview FILE.pvd)"
echo "Index:           $SIG_ROOT/out/index.html"
exit $status
