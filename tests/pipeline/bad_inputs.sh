#!/usr/bin/env bash
# The catalogue of bad inputs (tests/bad_inputs/README.md): every deck there runs through its
# chain (drivers/chain.sh) in a folder of its own and must be refused by the stage its
# '# stage:' line names, with a non-zero exit and every '# expect:' fragment in the message
# (case-insensitive), leaving no temporary file behind. Runs them two at a time.
set -euo pipefail
bin=${SIG_BIN:?SIG_BIN is not set}
export SIG_BIN=$bin
catalogue=tests/bad_inputs
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# check_case DECK: prints "ok NAME" or "FAIL NAME: why".
check_case() {
  local deck=$1 name status=0 message stage
  name=$(basename "$deck" .dat)
  stage=$(sed -n 's/^# stage: *//p' "$deck")
  message=$(drivers/chain.sh "$deck" -o "$work/$name" 2>&1) || status=$?
  if [ "$status" -eq 0 ]; then
    echo "FAIL $name: accepted (exit 0)"
    return
  fi
  if [ -n "$stage" ] && ! grep -q "^$stage: error:" <<< "$message"; then
    echo "FAIL $name: not refused by $stage: $(grep -m1 'error:' <<< "$message" || tail -1 <<< "$message")"
    return
  fi
  while IFS= read -r fragment; do
    grep -qiF -- "$fragment" <<< "$message" || { echo "FAIL $name: the message lacks '$fragment': $(grep -m1 'error:' <<< "$message")"; return; }
  done < <(sed -n 's/^# expect: *//p' "$deck")
  [ -z "$(find "$work/$name" -name '.*.tmp.*' 2> /dev/null)" ] || { echo "FAIL $name: temporaries left"; return; }
  echo "ok $name"
}
export -f check_case
export work

decks=("$catalogue"/*.dat)
for deck in "${decks[@]}"; do
  grep -q '^# expect: ' "$deck" || { echo "FAIL $(basename "$deck"): no '# expect:' line"; exit 1; }
done
results=$(printf '%s\n' "${decks[@]}" | xargs -P 2 -I{} bash -c 'check_case "$@"' _ {})
failed=$(grep -c '^FAIL' <<< "$results" || true)
grep '^FAIL' <<< "$results" || true
[ "$failed" -eq 0 ] || { echo "bad_inputs: $failed of ${#decks[@]} cases failed"; exit 1; }
echo "bad_inputs: ${#decks[@]} bad decks, each refused by its stage with its message"
