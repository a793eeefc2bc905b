#!/usr/bin/env bash
# Pipeline test (the front door): every driver in drivers/ answers -h and --help with its usage
# (exit 0, the usage on stdout, naming the driver as drivers/NAME.sh) and does nothing else: no set-up, no build, no run (setup.sh,
# test.sh, chain.sh and adapt.sh took --help for a datafile or started a build before; each call
# here is bounded by 20 s, far above a usage's few milliseconds).
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"

for driver in "$root"/drivers/*.sh; do
  name=${driver#"$root"/}
  for flag in -h --help; do
    checks=$((checks + 1))
    status=0
    (cd "$work" && timeout 20 "$driver" "$flag" >"$work/help.out" 2>"$work/help.err" </dev/null) || status=$?
    if [ "$status" -ne 0 ]; then
      fail "$name $flag exits $status: $(head -3 "$work/help.err")"
    elif ! grep -qF "$name" "$work/help.out"; then
      fail "$name $flag prints no usage: $(head -3 "$work/help.out")"
    elif [ -n "$(ls -A "$work" | grep -v '^help\.')" ]; then
      fail "$name $flag wrote files: $(ls -A "$work" | grep -v '^help\.' | head -3 | tr '\n' ' ')"
    fi
  done
done
finish "every driver answers -h and --help with its usage and nothing else"
