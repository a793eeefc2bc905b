#!/usr/bin/env bash
# Requirement (issue 16): mesh files are distrusted and read as they are.
#  - Header counts are checked against the file before anything is allocated: a FreeFem header
#    of 2e9 vertices, a gmsh 4.1 block of 1e12 nodes, a NOPO with NP = 1e12, MESH nx=ny=100000
#    are errors naming the file and the line (or the field), never std::bad_alloc; a .msh padded
#    to 3 GB fails at the padding within 1 GB of memory.
#  - gmsh binary .msh (2.2 and 4.1) read as their ASCII twins; a quadrangle is refused saying
#    that P1 is the model.
#  - What a reader changes is said: reoriented triangles and dropped nodes are named in a
#    warning; coincident nodes (an open crack) are an error unless MESH coincident=allow.
# Each refusal: exit status, message, and the case's case.nopo left as it was.
set -euo pipefail
source tests/pipeline/lib/distrust.sh

static_deck "$work/block.dat"
chain "$work/block.dat" "$work/out"
mesh_deck() { # mesh_deck NAME MESH-CARD: the good deck with another MESH card
  sed -e "s|^MESH .*|$2|" "$work/block.dat" > "$work/$1.dat"
}

# Counts beyond the file.
printf '2000000000 1 0\n0 0 1\n1 0 1\n0 1 1\n1 2 3 0\n' > "$work/huge_ff.msh"
mesh_deck huge_ff "MESH file=huge_ff.msh"
expect_refusal "FreeFem header of 2e9 vertices" mesh "$work/huge_ff.dat" "$work/out" \
  "huge_ff.msh:1: 2000000000 vertices: more than the 1e+08 a mesh may have"
sed -e '0,/^0 2 0 1$/s//0 2 0 1000000000000/' tests/fuzz/corpus/gmsh/square_v41_ascii.msh > "$work/huge_v41.msh"
grep -q 1000000000000 "$work/huge_v41.msh" || fail "could not write the 1e12-node block"
line=$(grep -n 1000000000000 "$work/huge_v41.msh" | cut -d: -f1)
mesh_deck huge_v41 "MESH file=huge_v41.msh"
expect_refusal "gmsh 4.1 block of 1e12 nodes" mesh "$work/huge_v41.dat" "$work/out" \
  "huge_v41.msh:$line: 1000000000000 nodes: more than the 1e+08"
python3 - meshes/legacy/square3.nopo "$work/huge.nopo" <<'PY'
import struct, sys
data = bytearray(open(sys.argv[1], "rb").read())
struct.pack_into("<q", data, 424 + 8 * 21, 10**12)   # NOP2 word 22, NP (MODULEF.md 4.4)
open(sys.argv[2], "wb").write(data)
PY
mesh_deck huge_nopo "MESH file=huge.nopo"
expect_refusal "NOPO with NP = 1e12" mesh "$work/huge_nopo.dat" "$work/out" \
  "huge.nopo: NOP2: NP = 1000000000000 points, not in 1..1e+08"
mesh_deck generated "MESH generator=rectangle lx=4 ly=1 nx=100000 ny=100000"
expect_refusal "MESH nx=ny=100000" mesh "$work/generated.dat" "$work/out" \
  "generated.dat:2: field 'nx': the mesh would have about 1.00002e+10 nodes"
cp tests/fuzz/corpus/gmsh/square_v22_ascii.msh "$work/padded.msh"
truncate -s 3G "$work/padded.msh" # a valid mesh, then 3 GB of zeros (a sparse file)
mesh_deck padded "MESH file=padded.msh"
checks=$((checks + 1))
status=0
message=$(ulimit -v 1000000 && "$bin/sig-mesh" "$work/padded.dat" -o "$work/out" 2>&1) || status=$?
if [ "$status" -eq 0 ] || ! grep -q "padded.msh:" <<< "$message" || grep -q "bad_alloc" <<< "$message"; then
  fail "a .msh padded to 3 GB: exit $status: $message"
else
  echo "ok ($test_name): a .msh padded to 3 GB, within 1 GB: $message"
fi

# gmsh binary files are read, as their ASCII twins (gmsh writes all four here).
checks=$((checks + 1))
cat > "$work/square.geo" <<'GEO'
Point(1) = {0, 0, 0, 0.3}; Point(2) = {4, 0, 0, 0.3}; Point(3) = {4, 1, 0, 0.3};
Point(4) = {0, 1, 0, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Curve(3) = {1}; Physical Curve(4) = {2}; Physical Curve(2) = {3};
Physical Curve(1) = {4}; Physical Surface(1) = {1};
GEO
reference=""
for format in msh22 msh41; do
  for binary in "" -bin; do
    msh=$work/square_$format$binary.msh
    gmsh -2 "$work/square.geo" -format "$format" $binary -o "$msh" > /dev/null 2>&1 || fail "gmsh $format $binary"
    mesh_deck "g_$format$binary" "MESH file=$(basename "$msh")"
    drivers/chain.sh "$work/g_$format$binary.dat" -o "$work/g_$format$binary" > "$work/g.log" 2>&1 ||
      fail "the chain on $format $binary failed: $(tail -2 "$work/g.log")"
    # The mesh and the solution, not the title line.
    dump=$("$bin/sig-dump" "$work/g_$format$binary/case.nopo" | tail -n +2; "$bin/sig-dump" "$work/g_$format$binary/case.b" | grep '^  u ')
    [ -n "$reference" ] || reference=$dump
    [ "$dump" = "$reference" ] || fail "$format $binary: another mesh or solution than msh22 ASCII"
  done
done
echo "ok ($test_name): gmsh 2.2 and 4.1, ASCII and binary: one mesh, one solution"
python3 - "$work/square_msh22.msh" "$work/quad.msh" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
start = lines.index("$Elements") + 2
for i in range(start, len(lines)):
    f = lines[i].split()
    if len(f) > 3 and f[1] == "2":  # the first triangle becomes a quadrangle
        lines[i] = " ".join([f[0], "3"] + f[2:] + [f[-1]])
        break
open(sys.argv[2], "w").write("\n".join(lines))
PY
mesh_deck quad "MESH file=quad.msh"
expect_refusal "a quadrangle" mesh "$work/quad.dat" "$work/out" "quad.msh:" "is a quadrangle: the model is P1"

# What a reader changes is said: a clockwise triangle and an unused node (gmsh 2.2).
checks=$((checks + 1))
cat > "$work/changed.msh" <<'MSH'
$MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
5
1 0 0 0
2 4 0 0
3 4 1 0
4 0 1 0
9 7 7 0
$EndNodes
$Elements
6
1 2 1 1 1 2 3
2 2 1 1 1 4 3
3 1 1 3 1 2
4 1 1 4 2 3
5 1 1 2 3 4
6 1 1 1 4 1
$EndElements
MSH
mesh_deck changed "MESH file=changed.msh"
message=$("$bin/sig-mesh" "$work/changed.dat" -o "$work/changed" 2>&1) || fail "changed.msh refused: $message"
grep -q "changed.msh: reoriented 1 clockwise triangle(s) (1-based, in file order): 2" <<< "$message" ||
  fail "no warning naming the reoriented triangle: $message"
grep -q "changed.msh: dropped 1 node(s) that no triangle uses (node tags): 9" <<< "$message" ||
  fail "no warning naming the dropped node: $message"
echo "ok ($test_name): warnings name the reoriented triangle and the dropped node"

# Coincident nodes: two triangles that do not share their diagonal (an open crack).
printf '6 2 0\n0 0 1\n4 0 1\n4 1 1\n0 0 1\n4 1 1\n0 1 1\n1 2 3 0\n4 5 6 0\n' > "$work/crack.msh"
mesh_deck crack "MESH file=crack.msh"
expect_refusal "coincident nodes" mesh "$work/crack.dat" "$work/out" \
  "crack.dat:2: field 'file'" "2 pair(s) of nodes at the same place (nodes 1 and 4 at (0, 0))" \
  "coincident=allow"
checks=$((checks + 1))
mesh_deck crack_allowed "MESH file=crack.msh coincident=allow"
message=$("$bin/sig-mesh" "$work/crack_allowed.dat" -o "$work/crack" 2>&1) || fail "coincident=allow refused: $message"
grep -q "crack.msh: kept apart (coincident=allow: an open crack) 4 coincident node(s) (1-based, in pairs): 1, 4, 3, 5" <<< "$message" ||
  fail "coincident=allow without the warning: $message"
echo "ok ($test_name): coincident=allow keeps the crack, with a warning"
distrust_finish
