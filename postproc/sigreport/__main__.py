"""Command line of the report library, for the drivers (bash):

  python3 -m sigreport deck TEMPLATE -o OUTPUT [EDIT...]   a deck variant (sigreport.deck):
      --set CARD.FIELD=VALUE     replace or add a field of the first CARD card
      --drop CARD.FIELD          remove the field where present
      --drop-card CARD           remove every CARD card
      --replace-card CARD LINE   replace the first CARD card by the card LINE
      --add-card LINE            append the card LINE
    Edits apply in the order given; OUTPUT may be TEMPLATE. Run with PYTHONPATH=postproc.
  python3 -m sigreport thesis SCENE ITEM [KEY]             print a thesis value (exit 1 if absent)
  python3 -m sigreport value DECK CARD FIELD               print a field of a deck (exit 1: absent)
  python3 -m sigreport has DECK CARD                       exit 0 if the deck has a CARD card, else 1

Errors name the file, line and field, and exit 1.
"""
import sys

from .deck import Deck
from .errors import ReportError
from .thesis import load_thesis


def deck_command(args):
    if len(args) < 3 or args[1] != "-o":
        raise ReportError("usage: python3 -m sigreport deck TEMPLATE -o OUTPUT [EDIT...]")
    deck = Deck.read(args[0])
    output, i = args[2], 3

    def card_field(text, what):
        card, dot, field = text.partition(".")
        if not dot or not card or not field:
            raise ReportError(f"{what} wants CARD.FIELD, got '{text}'")
        return card, field

    while i < len(args):
        option = args[i]
        need = 2 if option == "--replace-card" else 1
        if len(args) - i - 1 < need:
            raise ReportError(f"{option} needs {need} argument(s)")
        operands = args[i + 1:i + 1 + need]
        if option == "--set":
            target, eq, value = operands[0].partition("=")
            if not eq:
                raise ReportError(f"--set wants CARD.FIELD=VALUE, got '{operands[0]}'")
            card, field = card_field(target, "--set")
            deck.set(card, **{field: value})
        elif option == "--drop":
            card, field = card_field(operands[0], "--drop")
            deck.drop(card, field)
        elif option == "--drop-card":
            deck.remove_cards(operands[0])
        elif option == "--replace-card":
            deck.replace_card(operands[0], operands[1])
        elif option == "--add-card":
            deck.add_card(operands[0])
        else:
            raise ReportError(f"unknown deck edit '{option}' (--set, --drop, --drop-card, "
                              f"--replace-card, --add-card)")
        i += 1 + need
    deck.write(output)


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0
    command, args = argv[0], argv[1:]
    if command == "deck":
        deck_command(args)
    elif command == "thesis" and len(args) in (2, 3):
        value = load_thesis().get(*args)
        if value is None:
            raise ReportError(f"no thesis value {' '.join(args)}")
        print(value)
    elif command == "has" and len(args) == 2:
        return 0 if Deck.read(args[0]).has(args[1]) else 1
    elif command == "value" and len(args) == 3:
        value = Deck.read(args[0]).value(args[1], args[2])
        if value is None:
            raise ReportError(f"{args[0]}: no {args[1].upper()} {args[2]}=")
        print(value)
    else:
        raise ReportError(f"unknown command '{' '.join(argv)}' (see python3 -m sigreport --help)")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except ReportError as e:
        sys.exit(f"sigreport: error: {e}")
