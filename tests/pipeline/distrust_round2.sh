#!/usr/bin/env bash
# Requirement (issue 25, round two): what a deck of the catalogue (tests/bad_inputs) cannot say.
#  - Non-regular files are refused as inputs (a mesh that is /dev/zero or a FIFO, a FIFO datafile),
#    never read without end.
#  - A CR-only datafile: drivers/chain.sh sees its CONTACT card and runs sig-contact.
#  - sig-error refuses two unrelated domains, naming both meshes.
#  - A case.tae whose stiffness was edited off its diagonal (its CRC valid) is refused naming the
#    array and the dofs: the solvers read one triangle and would use the edit on one side only.
#  - The gmsh generators mesh any radius of the deck's range: gmsh meshes the shape scaled by a
#    power of two (at R = 1e29 it ran without end, at 1e20 it failed, at 1e-25 it ignored the
#    size law), and grading=-0 is grading=0.
#  - SOLVER fields the static solve does not use are said, not silently ignored.
#  - A Saint Venant-Kirchhoff block squashed to 40 % of its height loses the positive tangent
#    (its stored energy is not polyconvex): the Nv names the law, not CHOLMOD alone.
set -euo pipefail
name=distrust_round2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source tests/pipeline/lib/distrust.sh

static_deck "$work/block.dat"
chain "$work/block.dat" "$work/out"

# Non-regular files.
ln -s /dev/zero "$work/zero.msh"
mkfifo "$work/fifo.msh" "$work/fifo.dat"
sed -e 's|^MESH .*|MESH file=zero.msh|' "$work/block.dat" > "$work/zero.dat"
sed -e 's|^MESH .*|MESH file=fifo.msh|' "$work/block.dat" > "$work/fifo_mesh.dat"
expect_refusal "a mesh that is /dev/zero" mesh "$work/zero.dat" "$work/out" \
  "zero.dat:2: field 'file'" "zero.msh: it is a character device, not a regular file"
expect_refusal "a mesh that is a FIFO" mesh "$work/fifo_mesh.dat" "$work/out" \
  "fifo_mesh.dat:2: field 'file'" "fifo.msh: it is a FIFO, not a regular file"
expect_refusal "a datafile that is a FIFO" mesh "$work/fifo.dat" "$work/out" \
  "fifo.dat: cannot read the datafile: it is a FIFO, not a regular file"

# A CR-only deck (old Mac line ends): the chain sees its CONTACT card.
contact_deck "$work/hertz.dat"
tr '\n' '\r' < "$work/hertz.dat" > "$work/hertz_cr.dat"
checks=$((checks + 1))
if ! log=$(drivers/chain.sh "$work/hertz_cr.dat" -o "$work/cr" 2>&1); then
  fail "the CR-only deck's chain failed: $(tail -3 <<< "$log")"
elif ! grep -q "^sig-contact: " <<< "$log" || [ ! -f "$work/cr/case.cont" ]; then
  fail "the chain of the CR-only deck did not run sig-contact: $log"
else
  echo "ok ($name): a CR-only deck's chain runs sig-contact"
fi

# sig-error: two unrelated domains (the 4 x 1 block against the Hertz half disc).
checks=$((checks + 1))
status=0
message=$("$bin/sig-error" "$work/out" "$work/cr" 2>&1) || status=$?
if [ "$status" -eq 0 ] || ! grep -qF "out/case.nopo and $work/cr/case.nopo are not meshes of one domain" <<< "$message"; then
  fail "sig-error compared two unrelated domains (exit $status): $message"
else
  echo "ok ($name): sig-error refuses two unrelated domains"
fi

# An edited stiffness: one entry off the diagonal (dof 5 = u1 of node 3, which no Dirichlet card
# holds) made 1000 where its mirror stays.
cp -r "$work/out" "$work/edited"
rowptr=$("$bin/sig-dump" --json --values=K_rowptr,K_col "$work/edited/case.tae" |
  python3 -c 'import json, sys
arrays = {a["name"]: a.get("values") for a in json.load(sys.stdin)["arrays"]}
rowptr, col = arrays["K_rowptr"], arrays["K_col"]
print(next(k for k in range(rowptr[4] - 1, rowptr[5] - 1) if col[k] == 6))')
$ds_edit "$work/edited/case.tae" K_val --index "$rowptr" 1000
expect_refusal "a stiffness edited off its diagonal" solve "$work/block.dat" "$work/edited" \
  "edited/case.tae: array 'K_val': the matrix is not symmetric" \
  "row u1 of node 3, column u2 of node 3 is 1000" "rerun sig-assemble"

# gmsh at the ends of the range of lengths: the mesh of R = 8, scaled.
counts() { # counts DECK OUTDIR: "N nodes, M triangles" of sig-mesh, or the error
  timeout 20 "$bin/sig-mesh" "$1" -o "$2" 2>&1 | grep -o '[0-9]* nodes, [0-9]* triangles' || echo "failed: $(timeout 20 "$bin/sig-mesh" "$1" -o "$2" 2>&1 | tail -2)"
}
reference=$(counts "$work/hertz.dat" "$work/r8")
for change in "s/R=8 /R=1e29 /" "s/R=8 /R=1e20 /" "s/R=8 /R=1e-25 /" "s/grading=[^ ]*/grading=-0/"; do
  checks=$((checks + 1))
  sed -e "$change" "$work/hertz.dat" > "$work/scaled.dat"
  grep -q "grading=-0" "$work/scaled.dat" && reference=$(sed -e 's/grading=[^ ]*/grading=0/' "$work/hertz.dat" > "$work/g0.dat" && counts "$work/g0.dat" "$work/g0")
  got=$(counts "$work/scaled.dat" "$work/scaled")
  if [ "$got" != "$reference" ]; then
    fail "half disc with '$change': $got, expected the $reference of the reference mesh"
  else
    echo "ok ($name): half disc with '$change': $got"
  fi
done

# SOLVER fields a static solve does not use: a warning naming the deck's line and the field.
expect_warning() { # expect_warning WHAT SOLVER-CARD FRAGMENT
  checks=$((checks + 1))
  sed -e "s|^SOLVER .*|$2|" "$work/block.dat" > "$work/unused.dat"
  local message
  message=$("$bin/sig-solve" "$work/unused.dat" -o "$work/out" 2>&1) || { fail "$1: refused: $message"; return; }
  if grep -qF -- "$3" <<< "$message"; then echo "ok ($name): $1"; else fail "$1: no warning '$3': $message"; fi
}
expect_warning "gamma= beside method=linear" "SOLVER method=linear gamma=5" \
  "unused.dat:6: SOLVER gamma=5 is not used by method=linear (it is a parameter of method=pdas): ignored"
expect_warning "maxit= in a linear deck" "SOLVER method=linear maxit=5" \
  "unused.dat:6: SOLVER maxit=5 is not used: a small-strain deck without contact is one linear solve"
sed -e 's/^SOLVER .*/SOLVER method=pdas r=5 gamma=100/' "$work/hertz.dat" > "$work/pdas_r.dat"
checks=$((checks + 1))
message=$(drivers/chain.sh "$work/pdas_r.dat" -o "$work/pdas_r" 2>&1) || fail "r= beside pdas refused: $message"
line=$(grep -n '^SOLVER' "$work/pdas_r.dat" | cut -d: -f1)
grep -qF "pdas_r.dat:$line: SOLVER r=5 is not used by method=pdas (it is a parameter of method=alm and method=penalty)" <<< "$message" &&
  echo "ok ($name): r= beside method=pdas" || fail "r= beside method=pdas: no warning: $message"

# law=svk squashed: the tangent is lost; the failure says why in the deck's words.
cat > "$work/svk.dat" <<'EOF'
TITLE distrust: a Saint Venant-Kirchhoff block squashed
MESH generator=rectangle lx=1 ly=1 nx=4 ny=4
MATERIAL law=svk E=100 nu=0.3 plane=strain
DIRICHLET ref=2 ux=0 uy=-0.6
DIRICHLET ref=3 ux=0 uy=0
SOLVER method=linear
OUTPUT vtk=no
EOF
checks=$((checks + 1))
message=$(drivers/chain.sh "$work/svk.dat" -o "$work/svk" 2>&1) || fail "the squashed svk block: the chain failed: $message"
detail=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["failure_detail"])' "$work/svk/summary.json")
if grep -qF "the tangent stiffness of the deformed body is not positive definite" <<< "$detail" &&
  grep -qF "MATERIAL law=svk softens in strong compression" <<< "$detail"; then
  echo "ok ($name): a squashed svk block's Nv names the law"
else
  fail "the squashed svk block's failure does not say why: $detail"
fi
finish
