# Sourced by the drivers (through scene.sh and hertz_deck.sh): deck variants and deck fields through
# the report library's deck module (postproc/sigreport/deck.py), the one reader and writer of the
# datafile syntax outside the C++ stages: edits keep every other line and comment as written, and
# a card or field that is not there is an error naming the file, not a silent no-op.
# Needs $python (default /usr/bin/python3) and die() from the caller.
sigreport_path=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../postproc" && pwd)

# deck_variant TEMPLATE OUTPUT EDIT...: OUTPUT (may be TEMPLATE) is the template with the edits, in
# order: --set CARD.FIELD=VALUE (replace or add), --drop CARD.FIELD, --drop-card CARD,
# --replace-card CARD "CARD LINE", --add-card "CARD LINE".
deck_variant() {
  local template=$1 output=$2
  shift 2
  PYTHONPATH=$sigreport_path "${python:-/usr/bin/python3}" -m sigreport deck "$template" -o "$output" "$@" ||
    die "cannot write the deck $output from $template"
}

# deck_value DECK CARD FIELD: print the field of the first CARD card; status 1 (and no output) when
# the card or the field is absent.
deck_value() {
  PYTHONPATH=$sigreport_path "${python:-/usr/bin/python3}" -m sigreport value "$@" 2>/dev/null
}

# deck_has DECK CARD: status 0 when the deck has a CARD card.
deck_has() {
  PYTHONPATH=$sigreport_path "${python:-/usr/bin/python3}" -m sigreport has "$@"
}

# deck_cards DECK KEYWORD...: the deck's lines of these cards, comments removed (to tell which DS
# files a variant changes against its base).
deck_cards() {
  local deck=$1
  shift
  local pattern
  pattern=$(IFS='|'; echo "$*")
  grep -iE "^[[:space:]]*($pattern)([[:space:]]|$)" "$deck" | sed 's/#.*//' || true
}
