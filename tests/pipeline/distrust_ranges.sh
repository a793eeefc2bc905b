#!/usr/bin/env bash
# Requirement (issue 16): stages re-check the meaning of what they read, not only its checksum.
# A case.mili with nu = 0.5 or NaN, E < 0 or thickness 0 (its CRC valid) is refused by
# sig-assemble with the MATERIAL card's own ranges (core/ranges.hpp: one table for the deck and
# the files), a case.b with status 99 or converged 7 and a case.hist with ndof 7 or 2^62 steps by
# sig-post, each naming the file and the array; no file of the case changes. A case.cont whose gap
# or weight is 1e300 is refused by sig-solve (ranges bounded by the mesh's size).
set -euo pipefail
source tests/pipeline/lib/distrust.sh

static_deck "$work/block.dat"
chain "$work/block.dat" "$work/good"
damaged() { # damaged FOLDER FILE ARRAY EDIT...: a copy of the good case with one array edited
  local folder=$work/$1
  rm -rf "$folder"
  cp -r "$work/$2" "$folder"
  $ds_edit "$folder/$3" "${@:4}"
}
damaged nu good case.mili poisson 0.5
expect_refusal "nu = 0.5 in case.mili" assemble "$work/block.dat" "$work/nu" \
  "nu/case.mili: array 'poisson', row 1: 0.5 is not in (-1, 0.5) (the range of MATERIAL nu=)"
damaged nan good case.mili poisson nan
expect_refusal "nu = NaN in case.mili" assemble "$work/block.dat" "$work/nan" \
  "nan/case.mili: array 'poisson': value 1 of 1 is NaN"
damaged young good case.mili young -200
expect_refusal "E < 0 in case.mili" assemble "$work/block.dat" "$work/young" \
  "young/case.mili: array 'young', row 1: -200 is not > 0"
damaged thick good case.mili thickness 0
expect_refusal "thickness 0 in case.mili" assemble "$work/block.dat" "$work/thick" \
  "thick/case.mili: array 'thickness', row 1: 0 is not > 0"

contact_deck "$work/hertz.dat"
chain "$work/hertz.dat" "$work/hertz"
damaged status hertz case.b status --index 8 99
expect_refusal "status 99 in case.b" post "$work/hertz.dat" "$work/status" \
  "status/case.b: array 'status', row 9: 99 is not in 0..1"
damaged converged hertz case.b converged 7
expect_refusal "converged 7 in case.b" post "$work/hertz.dat" "$work/converged" \
  "converged/case.b: array 'converged': 7 is not in 0..1"

dynamic_deck "$work/disc.dat"
chain "$work/disc.dat" "$work/disc"
damaged ndof disc case.hist ndof 7
expect_refusal "ndof 7 in case.hist" post "$work/disc.dat" "$work/ndof" \
  "ndof/case.hist: array 'ndof': 7, the mesh has"
damaged steps disc case.hist steps 4611686018427387904
expect_refusal "2^62 steps in case.hist" post "$work/disc.dat" "$work/steps" \
  "steps/case.hist: array 'steps': 4611686018427387904 is not in 1..1000000000"

# The CONT's geometry in its ranges (issue 25): an edited gap held the body off the obstacle with
# exit 0, an edited weight scaled its contact forces.
damaged gap hertz case.cont gap --index 3 1e300
expect_refusal "gap 1e300 in case.cont" solve "$work/hertz.dat" "$work/gap" \
  "gap/case.cont: array 'gap', row 4: 1e+300 is not in [0, 4e+30]"
damaged weight hertz case.cont weight --index 3 1e300
expect_refusal "weight 1e300 in case.cont" solve "$work/hertz.dat" "$work/weight" \
  "weight/case.cont: array 'weight', row 4: 1e+300 is not in (0," "the mesh's diameter"
distrust_finish
