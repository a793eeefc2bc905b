#!/usr/bin/env bash
# drivers/run.sh: install what is missing, build, run the default scene (Hertz contact, scene 7a,
# quick variant) and say where its report and ParaView files are.
set -euo pipefail
source "$(dirname "$0")/setup.sh"
cd "$SIG_ROOT"
"$SIG_ROOT/drivers/scene7a.sh" --quick
echo
echo "Report:          $SIG_ROOT/out/scene7a/report.md"
echo "ParaView files:  $(ls "$SIG_ROOT"/out/scene7a/N256/pdas_1e2/*.pvd 2>/dev/null | head -1)"
echo "                 (all runs: ls out/scene7a/N*/*/*.pvd; open with: paraview FILE.pvd)"
