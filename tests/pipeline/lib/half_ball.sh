# Sourced after common.sh by the 3D impact tests (impact3d.sh, friction3d_impact.sh): a
# datafiles/scene3d impact deck on a coarse half ball, built once, and its variants.

# half_ball_base DECK H GRADING: $base = $work/base holds DECK with the half ball of mesh size H
# and grading GRADING as ball.dat, and its sig-mesh, sig-material and sig-assemble.
half_ball_base() {
  base=$work/base
  mkdir -p "$base"
  sed -E -e "s|^MESH .*|MESH generator=half-ball R=10 h=$2 grading=$3|" "$1" >"$base/ball.dat"
  local stage
  for stage in mesh material assemble; do
    "$bin/sig-$stage" "$base/ball.dat" -o "$base" >"$work/$stage.log" 2>&1 ||
      { cat "$work/$stage.log"; die "sig-$stage on the coarse half ball"; }
  done
}

# run NAME CONTACT_LINE MASS [SED]: sig-contact and sig-march in $work/NAME on the base deck with
# that CONTACT card and mass (and the sed expression SED).
run() {
  local dir=$work/$1
  mkdir -p "$dir"
  for ds in nopo mili tae; do ln -s "$base/case.$ds" "$dir/case.$ds"; done
  sed -E -e "s|^CONTACT .*|$2|" -e "s|mass=emm|mass=$3|" -e "${4:-}" "$base/ball.dat" >"$dir/ball.dat"
  "$bin/sig-contact" "$dir/ball.dat" -o "$dir" >"$dir/contact.log" 2>&1 ||
    { cat "$dir/contact.log"; die "sig-contact for $1"; }
  "$bin/sig-march" "$dir/ball.dat" -o "$dir" >"$dir/march.log" 2>&1 ||
    { cat "$dir/march.log"; die "sig-march for $1"; }
}
