# Sourced by the scene and benchmark drivers: the repository, the executables, the Python with
# matplotlib, and die() naming the script.
source "$(dirname "${BASH_SOURCE[0]}")/environment.sh"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
# The reports read DS files through this build's sig-dump (postproc/sigreport/ds.py).
export SIG_BIN=$bin
python=${PYTHON:-/usr/bin/python3}
source "$(dirname "${BASH_SOURCE[0]}")/deck.sh"
source "$(dirname "${BASH_SOURCE[0]}")/stages.sh"

die() {
  echo "$(basename "$0"): error: $*" >&2
  exit 1
}

# require_decks DECK...: each deck is readable.
require_decks() {
  local deck
  for deck; do
    [ -r "$deck" ] || die "cannot read the deck $deck"
  done
}

# require_charts: the Python of the reports has matplotlib and numpy.
require_charts() {
  "$python" -c 'import matplotlib, numpy' 2>/dev/null ||
    die "$python lacks matplotlib or numpy (Debian: python3-matplotlib python3-numpy)"
}

# require_half_ball_scene: what the half-ball scenes (scene3d_hertz.sh, scene3d_cattaneo.sh) need:
# the stages of a static solve, their deck $template, the reports' Python and gmsh.
require_half_ball_scene() {
  require_stages mesh material contact assemble solve post dump
  require_decks "$template"
  require_charts
  command -v "${SIG_GMSH:-gmsh}" >/dev/null || die "gmsh is needed to mesh the half ball"
}

# parse_options SPEC... -- "$@": a driver's options by SPEC, and -h, --help (the driver's usage).
# A SPEC "OPTION=VAR" takes a value ("-o=out": -o DIR sets out); "OPTION:VAR=VALUE" is a flag
# ("--quick:quick=1"); "@VAR" collects the arguments that do not start with - into the array VAR
# (without it they are unknown arguments). VAR is the caller's variable: set its default first.
parse_options() {
  local -A parse_value=() parse_flag=()
  local parse_rest=
  while [ "$1" != -- ]; do
    case $1 in
      @*) parse_rest=${1#@} ;;
      *:*) parse_flag[${1%%:*}]=${1#*:} ;;
      *=*) parse_value[${1%%=*}]=${1#*=} ;;
    esac
    shift
  done
  shift
  while [ $# -gt 0 ]; do
    if [ -n "$1" ] && [ -n "${parse_value[$1]:-}" ]; then
      [ $# -ge 2 ] || die "$1 needs a value"
      printf -v "${parse_value[$1]}" '%s' "$2"
      shift
    elif [ -n "$1" ] && [ -n "${parse_flag[$1]:-}" ]; then
      printf -v "${parse_flag[$1]%%=*}" '%s' "${parse_flag[$1]#*=}"
    elif [ "$1" = -h ] || [ "$1" = --help ]; then
      usage
      exit 0
    elif [ -n "$parse_rest" ] && [[ $1 != -* ]]; then
      eval "$parse_rest+=(\"\$1\")"
    else
      usage >&2
      die "unknown argument '$1'"
    fi
    shift
  done
}

# require_positive OPTION VALUE: VALUE is a positive integer, else die naming OPTION.
require_positive() {
  [[ $2 =~ ^[0-9]+$ ]] && [ "$2" -ge 1 ] || die "$1 must be a positive integer, got '$2'"
}

# parse_quick_out DEFAULT_OUTDIR "$@": a scene driver's options --quick and -o OUTDIR; sets quick
# (0 or 1) and out.
parse_quick_out() {
  out=$1
  quick=0
  shift
  parse_options -o=out --quick:quick=1 -- "$@"
}

# parse_repeat_out DEFAULT_OUTDIR DEFAULT_REPEAT "$@": a benchmark driver's options --repeat K
# and -o OUTDIR; sets repeat (a positive integer) and out.
parse_repeat_out() {
  out=$1
  repeat=$2
  shift 2
  parse_options -o=out --repeat=repeat -- "$@"
  require_positive --repeat "$repeat"
}

# run_timed STAGE DECK DIR: run_stage (lib/stages.sh), and its wall seconds to the millisecond in
# DIR/wall.txt when it succeeds.
run_timed() {
  local t0 t1
  t0=$(date +%s.%N)
  run_stage "$@" || return 1
  t1=$(date +%s.%N)
  "$python" -c "print(f'{$t1 - $t0:.3f}')" >"$3/wall.txt"
}

# record_seconds START: append the wall seconds of the runs since START ($SECONDS then) to
# command.txt, the "seconds" of the scene index entry (out/<scene>/scene.json).
record_seconds() {
  echo "seconds: $((SECONDS - $1))" >>"$out/command.txt"
}

# provenance: the lines of a scene's command.txt that say how it was made (the driver's
# $invocation, $out and $template; the date, host, revision and executables).
provenance() {
  echo "command: $invocation"
  echo "outdir: $out"
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "host: $(uname -n), $(nproc) cores"
  echo "revision: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "SIG_BIN: $bin"
  echo "template: $template"
}

# bench_provenance: the lines of a benchmark's command.txt that say how it was made (the driver's
# $invocation; the date, host with its load average, which the timings depend on, and revision).
bench_provenance() {
  echo "command: $invocation"
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "host: $(uname -n), $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "revision: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
}

# ladder_begin NAME [LINE...]: the start of a driver that runs $methods on a ladder of $meshes
# (scene3d_hertz.sh, scene3d_impact.sh): $out/command.txt (provenance, the meshes, the methods,
# each LINE), $template copied to $out/NAME.template.dat, the old m<k> folders removed, and the
# progress of one base and the methods per mesh begun.
ladder_begin() {
  local name=$1 line
  shift
  {
    provenance
    echo "meshes: $(printf '%s;' "${meshes[@]}" | sed 's/;$//')"
    echo "methods: ${methods[*]}"
    for line; do echo "$line"; done
  } >"$out/command.txt"
  cp "$template" "$out/$name.template.dat"
  rm -rf "$out"/m[0-9]*
  progress_begin $((${#meshes[@]} * (1 + ${#methods[@]})))
}

# ladder_mesh "H GRADING" NAME [EDIT...]: the next mesh of a ladder (after ladder_begin and k=0):
# k incremented, h, grading, t0 ($SECONDS) and base ($out/m<k>/base, made) set, and
# $base/NAME.dat written from $template with MESH h= grading= and the deck_variant EDITs.
ladder_mesh() {
  local name=$2
  k=$((k + 1))
  read -r h grading <<<"$1"
  shift 2
  t0=$SECONDS
  base=$out/m$k/base
  mkdir -p "$base"
  deck_variant "$template" "$base/$name.dat" --set MESH.h="$h" --set MESH.grading="$grading" "$@"
}

# Progress of a long driver: `progress_begin N` before its N runs (a run: any unit of work of
# roughly even cost, e.g. sig-solve + sig-post of one variant), `progress_step WHAT` after each.
# Prints "[k/N] WHAT: 1m02s elapsed, about 3m10s left", the rest estimated from the mean time
# per run so far; a driver that does more runs than it announced shows "[k/k]".
progress_begin() {
  progress_total=$1
  progress_done=0
  progress_start=${EPOCHREALTIME/./}
}

# progress_seconds MICROSECONDS: "42s", "3m05s" or "1h02m".
progress_seconds() {
  local s=$(($1 / 1000000))
  if [ $s -lt 10 ]; then
    printf '%d.%ds\n' $s $(($1 / 100000 % 10))
  elif [ $s -lt 60 ]; then
    echo "${s}s"
  elif [ $s -lt 3600 ]; then
    printf '%dm%02ds\n' $((s / 60)) $((s % 60))
  else
    printf '%dh%02dm\n' $((s / 3600)) $((s % 3600 / 60))
  fi
}

progress_step() {
  progress_done=$((progress_done + 1))
  [ "$progress_done" -le "$progress_total" ] || progress_total=$progress_done
  local elapsed=$((${EPOCHREALTIME/./} - progress_start))
  local left=$((elapsed / progress_done * (progress_total - progress_done)))
  echo "[$progress_done/$progress_total] $*: $(progress_seconds "$elapsed") elapsed, about" \
    "$(progress_seconds "$left") left"
}
