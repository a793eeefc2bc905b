#!/usr/bin/env bash
# drivers/chain.sh DATAFILE [-o OUTDIR]: run a datafile's whole chain of stages, MODULEF style:
# sig-mesh -> sig-material -> sig-contact (if the deck has a CONTACT card) -> sig-assemble ->
# sig-solve -> sig-post, or sig-march -> sig-post for a dynamic deck (TIME card). Each stage
# reads what the earlier ones wrote to OUTDIR (default out/<datafile stem>/). Uses $SIG_BIN, or
# build/bin.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/environment.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
if [ $# -lt 1 ]; then
  echo "usage: drivers/chain.sh DATAFILE [-o OUTDIR]" >&2
  exit 2
fi
deck=$1
shift
[ -r "$deck" ] || { echo "chain.sh: cannot read datafile $deck" >&2; exit 2; }
[ -x "$bin/sig-mesh" ] || { echo "chain.sh: no executables in $bin (run drivers/run.sh)" >&2; exit 2; }

stages=(mesh material)
grep -qiE '^[[:space:]]*contact([[:space:]]|$)' "$deck" && stages+=(contact)
stages+=(assemble)
# A TIME card makes the case dynamic: sig-march (case.hist) replaces sig-solve (case.b); sig-post
# reads whichever the datafile calls for.
if grep -qiE '^[[:space:]]*time([[:space:]]|$)' "$deck"; then
  stages+=(march post)
else
  stages+=(solve post)
fi
for stage in "${stages[@]}"; do
  "$bin/sig-$stage" "$deck" "$@"
done
