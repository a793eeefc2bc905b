#!/usr/bin/env bash
# drivers/chain.sh DATAFILE [-o OUTDIR] [--time-limit SECONDS]: run a datafile's whole chain of
# stages, MODULEF style (the options go to every stage):
# sig-mesh -> sig-material -> sig-contact (if the deck has a CONTACT card) -> sig-assemble ->
# sig-solve -> sig-post, or sig-march -> sig-post for a dynamic deck (TIME card). Each stage
# reads what the earlier ones wrote to OUTDIR (default out/<datafile stem>/). Uses $SIG_BIN, or
# build/bin.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/environment.sh"
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
if [ $# -lt 1 ]; then
  echo "usage: drivers/chain.sh DATAFILE [-o OUTDIR] [--time-limit SECONDS]" >&2
  exit 2
fi
deck=$1
shift
[ -r "$deck" ] || { echo "chain.sh: cannot read datafile $deck" >&2; exit 2; }
[ -x "$bin/sig-mesh" ] || { echo "chain.sh: no executables in $bin (run drivers/run.sh)" >&2; exit 2; }

# sig-mesh reads the deck first; then the stages' own parser says which stages the deck calls for
# (sig-dump --chain: a CONTACT card adds sig-contact, a TIME card makes the case dynamic, sig-march
# replacing sig-solve), so that the chain sees the cards the stages see, whatever the line ends.
"$bin/sig-mesh" "$deck" "$@"
stages=$("$bin/sig-dump" --chain "$deck")
for stage in $stages; do
  [ "$stage" = mesh ] || "$bin/sig-$stage" "$deck" "$@"
done
