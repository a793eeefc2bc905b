#!/usr/bin/env bash
# Requirement (issue 16): NaN and inf never leave a stage with exit 0. A DS holding one (its CRC
# valid: written so, or edited) is refused by the stage that reads it, naming the file, the array
# and the value; a displacement of 1e300 (whose stresses would overflow) is refused when read,
# naming the file and the array u. No file of the case changes.
set -euo pipefail
source tests/pipeline/lib/distrust.sh

# A static case: a NaN load in case.tae, a NaN displacement in case.b.
static_deck "$work/block.dat"
chain "$work/block.dat" "$work/block"
$ds_edit "$work/block/case.tae" f --index 7 nan
expect_refusal "NaN load in case.tae" solve "$work/block.dat" "$work/block" \
  "block/case.tae: array 'f': value 8 of" "is NaN"
drivers/chain.sh "$work/block.dat" -o "$work/block2" > /dev/null 2>&1
$ds_edit "$work/block2/case.b" u --index 3 inf
expect_refusal "inf displacement in case.b" post "$work/block.dat" "$work/block2" \
  "block2/case.b: array 'u': value 4 of" "is inf"

# A dynamic case: a NaN stiffness in case.tae used to give 'E = nan' and exit 0.
dynamic_deck "$work/disc.dat"
chain "$work/disc.dat" "$work/disc"
$ds_edit "$work/disc/case.tae" K_val --index 0 nan
expect_refusal "NaN stiffness in case.tae" march "$work/disc.dat" "$work/disc" \
  "disc/case.tae: array 'K_val': value 1 of" "is NaN"
chain "$work/disc.dat" "$work/disc3"
$ds_edit "$work/disc3/case.hist" v --index 5 -inf
expect_refusal "-inf velocity in case.hist" post "$work/disc.dat" "$work/disc3" \
  "disc3/case.hist: array 'v': value 6 of" "is -inf"

# A displacement whose stresses would overflow (a case.b edited to 1e300, finite; a deck cannot
# ask for it: its numbers are bounded by 1e30): refused when read, naming case.b's array u, not a
# field of the .vtu (core/ranges.hpp: |u| <= 1e6 x the mesh's diameter); the same in case.hist.
drivers/chain.sh "$work/block.dat" -o "$work/huge" > /dev/null 2>&1
$ds_edit "$work/huge/case.b" u --index 11 -1e300
rm -f "$work/huge/block.pvd" "$work/huge"/block_*.vtu
expect_refusal "a displacement of 1e300 in case.b" post "$work/block.dat" "$work/huge" \
  "huge/case.b: array 'u', row 12: -1e+300 is not in [-4.12311e+06, 4.12311e+06]" \
  "1e6 times the mesh's diameter"
[ ! -e "$work/huge/block.pvd" ] || fail "a .pvd was written for a displacement of 1e300"
chain "$work/disc.dat" "$work/disc4"
$ds_edit "$work/disc4/case.hist" u --index 5 1e300
expect_refusal "a displacement of 1e300 in case.hist" post "$work/disc.dat" "$work/disc4" \
  "disc4/case.hist: array 'u', row 6: 1e+300 is not in [-2.82843e+06, 2.82843e+06]"
distrust_finish
