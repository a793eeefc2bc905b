#!/usr/bin/env bash
# Requirement (issue 16): the files of a case belong together, and case.nopo is checked. Every DS
# records the fingerprints of the mesh and of the DS it was built from (core/provenance.hpp): a
# stage given another case's case.mili or a foreign case.nopo refuses, naming both files.
# case.nopo carries the fingerprint of its mesh records: a node moved by 0.5 or a byte damaged
# mid-file is refused by the next stage that reads it. No file of the case changes.
set -euo pipefail
name=distrust_belong
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source tests/pipeline/lib/distrust.sh

contact_deck "$work/a.dat"
sed -e 's/E=150/E=210/' "$work/a.dat" > "$work/b.dat"     # another law
sed -e 's/N=16 /N=32 /' "$work/a.dat" > "$work/fine.dat"  # another mesh
chain "$work/a.dat" "$work/a"
chain "$work/b.dat" "$work/b"
chain "$work/fine.dat" "$work/fine"

# sig-post with another case's case.mili computed the stresses of the wrong law.
cp -r "$work/a" "$work/mili"
cp "$work/b/case.mili" "$work/mili/case.mili"
expect_refusal "another case's case.mili" post "$work/a.dat" "$work/mili" \
  "do not belong together" "mili/case.b was built from the MILI" "mili/case.mili is the MILI"

# A foreign case.nopo: sig-assemble refuses it against case.mili; sig-contact, which reads only
# the mesh, builds a CONT of it, and sig-solve refuses that against case.tae.
cp -r "$work/a" "$work/nopo"
cp "$work/fine/case.nopo" "$work/nopo/case.nopo"
expect_refusal "a foreign case.nopo" assemble "$work/a.dat" "$work/nopo" \
  "do not belong together" "nopo/case.mili was built from the NOPO" "nopo/case.nopo is the NOPO"
"$bin/sig-contact" "$work/a.dat" -o "$work/nopo" > /dev/null 2>&1 || fail "sig-contact failed"
expect_refusal "a CONT of a foreign mesh" solve "$work/a.dat" "$work/nopo" \
  "do not belong together" "nopo/case.cont" "nopo/case.tae"

# case.nopo's integrity: a node moved by 0.5 (x of node 1: i8r8 records, byte 636).
cp -r "$work/a" "$work/moved"
python3 - "$work/moved/case.nopo" <<'PY'
import struct, sys
data = bytearray(open(sys.argv[1], "rb").read())
x, = struct.unpack_from("<d", data, 636)
struct.pack_into("<d", data, 636, x + 0.5)
open(sys.argv[1], "wb").write(data)
PY
expect_refusal "a node of case.nopo moved by 0.5" material "$work/a.dat" "$work/moved" \
  "moved/case.nopo: the mesh (NOP2, NOP4, NOP5) does not match the fingerprint" "rerun sig-mesh"
cp -r "$work/a" "$work/damaged"
size=$(stat -c %s "$work/damaged/case.nopo")
printf '\x5a' | dd of="$work/damaged/case.nopo" bs=1 seek=$((size / 2)) conv=notrunc status=none
expect_refusal "a byte of case.nopo damaged mid-file" contact "$work/a.dat" "$work/damaged" \
  "damaged/case.nopo" "does not match the fingerprint"
finish
