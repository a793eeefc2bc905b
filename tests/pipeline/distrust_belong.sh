#!/usr/bin/env bash
# Requirement (issues 16 and 25): the files of a case belong together, to the deck, and case.nopo
# is checked. Every DS records the fingerprints of the mesh and of the DS it was built from, and
# the values of the deck's cards it was made from (core/provenance.hpp); case.nopo's record is
# case.nopo.prov. A stage given another case's case.mili (another MATERIAL card) refuses naming
# the card; files of one deck that do not belong together (a stage rerun alone) are refused
# naming both files; a foreign case.nopo is refused without its record (it is not the mesh the
# record describes) and with it (another MESH card). case.nopo carries the fingerprint of its
# mesh records: a node moved by 0.5 or a byte damaged mid-file is refused by the next stage that
# reads it. No file of the case changes.
set -euo pipefail
source tests/pipeline/lib/distrust.sh

contact_deck "$work/a.dat"
sed -e 's/E=150/E=210/' "$work/a.dat" > "$work/b.dat"     # another law
sed -e 's/N=16 /N=32 /' "$work/a.dat" > "$work/fine.dat"  # another mesh
chain "$work/a.dat" "$work/a"
# The deck's lines of its MATERIAL and MESH cards, as the messages name them.
material_line=$(grep -n '^MATERIAL' "$work/a.dat" | head -1 | cut -d: -f1)
mesh_line=$(grep -n '^MESH' "$work/a.dat" | head -1 | cut -d: -f1)
chain "$work/b.dat" "$work/b"
chain "$work/fine.dat" "$work/fine"

# sig-post with another case's case.mili computed the stresses of the wrong law.
cp -r "$work/a" "$work/mili"
cp "$work/b/case.mili" "$work/mili/case.mili"
expect_refusal "another case's case.mili" post "$work/a.dat" "$work/mili" \
  "mili/case.mili was made with MATERIAL E=210, but" "a.dat:$material_line now says MATERIAL E=150" \
  "rerun sig-material"

# Files of the deck that do not belong together: sig-assemble rerun alone writes another
# case.tae (its phase times differ), which case.b was not built from.
cp -r "$work/a" "$work/alone"
"$bin/sig-assemble" "$work/a.dat" -o "$work/alone" > /dev/null 2>&1 || fail "sig-assemble failed"
expect_refusal "a case.tae rerun alone" post "$work/a.dat" "$work/alone" \
  "do not belong together" "alone/case.b was built from the TAE" "alone/case.tae is the TAE"

# A foreign case.nopo copied in alone is not the mesh its record describes: sig-assemble and
# sig-contact, which reads only the mesh, refuse it.
cp -r "$work/a" "$work/nopo"
cp "$work/fine/case.nopo" "$work/nopo/case.nopo"
for stage in assemble contact; do
  expect_refusal "a foreign case.nopo (sig-$stage)" $stage "$work/a.dat" "$work/nopo" \
    "nopo/case.nopo is not the NOPO that" "nopo/case.nopo.prov records" "rerun sig-mesh"
done
# With its record, it is the mesh of another MESH card.
cp "$work/fine/case.nopo.prov" "$work/nopo/case.nopo.prov"
expect_refusal "a foreign case.nopo with its record" contact "$work/a.dat" "$work/nopo" \
  "nopo/case.nopo was made with MESH N=32, but" "a.dat:$mesh_line now says MESH N=16" "rerun sig-mesh"

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
distrust_finish
