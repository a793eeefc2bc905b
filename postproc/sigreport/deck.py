"""Datafiles (decks) for reports and drivers: reading cards and writing deck variants, one way.

The format is modules/core/src/datafile.cpp's: one card per line, `KEYWORD name=value ...`; `#`
starts a comment anywhere outside double quotes; keywords and field names are case-insensitive;
`name = value` may have spaces around '='; a value with spaces is quoted (`title="a b"`); a list
`0,-2` may continue after a comma and a space (`f=0.4, -2` is "0.4,-2"); TITLE takes the rest of
its line as free text. Which cards and fields exist is the C++ card schema's business (the stages
reject unknown ones): this module parses the syntax only.

Reading:

    deck = Deck.read("datafiles/scene7a/hertz.dat")
    deck.value("MESH", "R")             # "8" (text; None when the card or field is absent)
    deck.number("MESH", "grading", 0.0) # 0.1 (float; the default when absent)
    deck.numbers("TRACTION", "f")       # [0.0, -2.0]
    deck.card("SOLVER").fields          # {"method": "pdas", "gamma": "100", ...} (lower-case names)
    deck.cards("DIRICHLET")             # every card of a repeatable keyword, in order
    deck.title                          # TITLE text

Writing a variant (edits keep every other line, comment and spacing as written):

    deck.set("MESH", N=512, grading=0)              # replace, or add, fields of the first MESH card
    deck.drop("SOLVER", "r", "gamma", "c")          # remove fields where present
    deck.set("SOLVER", method="alm", r="1e2")
    deck.remove_cards("FRICTION")                   # every FRICTION card
    deck.replace_card("CONTACT", "DIRICHLET ref=3 uy=0")
    deck.add_card("LOADSTEPS n=3")
    deck.write("out/run/hertz.dat")                 # written whole or not at all

Drivers (bash) use the same code through `python3 -m sigreport deck` (see __main__.py):

    PYTHONPATH=postproc python3 -m sigreport deck TEMPLATE -o OUT --set MESH.N=512 \\
        --drop SOLVER.r --set SOLVER.method=alm --drop-card FRICTION

Every error is a ReportError naming the file, the line and the field.
"""
from pathlib import Path

from .errors import ReportError
from .files import write_text_atomically

FREE_TEXT_CARDS = ("TITLE",)  # cards whose rest of line is free text (their schema has no field)


def _is_name_char(c):
    return c.isalnum() or c == "_"


class Field:
    """One `name=value` of a card: `name` lower case, `written` as in the file, `value` text
    (quotes removed), and the spans of the field and of its value in the line."""

    def __init__(self, name, written, value, start, value_start, value_end):
        self.name, self.written, self.value = name, written, value
        self.start, self.value_start, self.value_end = start, value_start, value_end


class Card:
    """One card: keyword (upper case), line number (from 1), `fields` {name: value text} in the
    order written, `text` (free text of TITLE)."""

    def __init__(self, deck, index):
        self._deck, self.index = deck, index
        self.keyword, self.text, self._fields, self._content_end = _parse_line(
            deck.lines[index], deck.path, index + 1)

    @property
    def line(self):
        return self.index + 1

    @property
    def fields(self):
        return {f.name: f.value for f in self._fields}

    def value(self, name, default=None):
        for f in self._fields:
            if f.name == name.lower():
                return f.value
        return default

    def _field(self, name):
        return next((f for f in self._fields if f.name == name.lower()), None)

    def set(self, **values):
        """Replace each field's value, or append the field to the card."""
        for name, value in values.items():
            text = _value_text(value)
            raw = self._deck.lines[self.index]
            f = self._field(name)
            if f is None:
                raw = raw[:self._content_end] + f" {name}={text}" + raw[self._content_end:]
            else:
                raw = raw[:f.value_start] + text + raw[f.value_end:]
            self._reparse(raw)
        return self

    def drop(self, *names):
        """Remove the fields that are present (with the spaces before them)."""
        for name in names:
            f = self._field(name)
            if f is None:
                continue
            raw = self._deck.lines[self.index]
            start = f.start
            while start > 0 and raw[start - 1] in " \t":
                start -= 1
            self._reparse(raw[:start] + raw[f.value_end:])
        return self

    def _reparse(self, raw):
        self._deck.lines[self.index] = raw
        self.keyword, self.text, self._fields, self._content_end = _parse_line(
            raw, self._deck.path, self.index + 1)


def _value_text(value):
    text = str(value)
    if any(c in text for c in " \t#") or text == "":
        if '"' in text:
            raise ReportError(f"a deck value cannot hold both a space and a quote: {text!r}")
        return f'"{text}"'
    return text


def _strip_comment(raw, path, line):
    quoted = False
    for i, c in enumerate(raw):
        if c == '"':
            quoted = not quoted
        if c == "#" and not quoted:
            return raw[:i]
    if quoted:
        raise ReportError(f"{path}:{line}: unterminated quote")
    return raw


def _parse_line(raw, path, line):
    """(keyword or None, free text, [Field], end of the card's content in raw) of one line."""
    content = _strip_comment(raw, path, line)
    end_content = len(content.rstrip(" \t\r"))
    i = len(content) - len(content.lstrip(" \t"))
    if i >= end_content:
        return None, "", [], 0
    start = i
    while i < end_content and content[i] not in " \t":
        i += 1
    keyword = content[start:i].upper()
    while i < end_content and content[i] in " \t":
        i += 1
    if keyword in FREE_TEXT_CARDS:
        text = content[i:end_content]
        if len(text) >= 2 and text[0] == '"' and text[-1] == '"':
            text = text[1:-1]
        return keyword, text, [], end_content
    fields = []

    def fail(name, what):
        where = f"{path}:{line}: " + (f"field '{name}': " if name else "")
        raise ReportError(where + what)

    n = end_content
    while True:
        while i < n and content[i] in " \t":
            i += 1
        if i >= n:
            return keyword, "", fields, end_content
        name_start = i
        while i < n and _is_name_char(content[i]):
            i += 1
        if i == name_start:
            word = content[name_start:].split()[0]
            fail("", f"expected name=value, got '{word}'")
        written = content[name_start:i]
        while i < n and content[i] in " \t":
            i += 1
        if i >= n or content[i] != "=":
            fail(written, "missing '=' after the field name")
        i += 1
        while i < n and content[i] in " \t":
            i += 1
        value_start = i
        if i < n and content[i] == '"':
            close = content.index('"', i + 1)
            value = content[i + 1:close]
            i = close + 1
            if i < n and content[i] not in " \t":
                fail(written, "unexpected text after the closing quote")
        else:
            value = ""
            while i < n:
                while i < n and content[i] not in " \t":
                    value += content[i]
                    i += 1
                if not value or value[-1] != ",":
                    break
                while i < n and content[i] in " \t":
                    i += 1
            if not value:
                fail(written, "missing value after '='")
        if any(f.name == written.lower() for f in fields):
            fail(written, "field given twice")
        fields.append(Field(written.lower(), written, value, name_start, value_start, i))


class Deck:
    """A datafile's lines and cards (see the module docstring)."""

    def __init__(self, text, path="<deck>"):
        self.path = str(path)
        self._newline_at_end = text.endswith("\n")
        self.lines = text.splitlines()
        self._cards = [Card(self, i) for i in range(len(self.lines))]

    @classmethod
    def read(cls, path):
        try:
            text = Path(path).read_text()
        except OSError as e:
            raise ReportError(f"{path}: cannot read the datafile ({e.strerror})") from None
        return cls(text, path)

    # -- reading -----------------------------------------------------------------------------
    def cards(self, keyword=None):
        """The cards with this keyword (all cards if None), in file order."""
        return [c for c in self._cards if c.keyword is not None and
                (keyword is None or c.keyword == keyword.upper())]

    def card(self, keyword, required=True):
        """The first card with this keyword; ReportError (or None if not required) if absent."""
        found = self.cards(keyword)
        if found:
            return found[0]
        if required:
            raise ReportError(f"{self.path}: no {keyword.upper()} card")
        return None

    def has(self, keyword):
        return bool(self.cards(keyword))

    def value(self, keyword, field, default=None):
        """Text of a field of the first card with this keyword, or `default`."""
        card = self.card(keyword, required=False)
        return default if card is None else card.value(field, default)

    def number(self, keyword, field, default=None):
        """A field as a float; `default` when absent (ReportError when absent without default
        or not a number)."""
        text = self.value(keyword, field)
        if text is None:
            if default is None:
                raise ReportError(f"{self.path}: no {keyword.upper()} {field}=")
            return float(default)
        try:
            return float(text)
        except ValueError:
            raise ReportError(f"{self._where(keyword)}: field '{field}': '{text}' is not a "
                              f"number") from None

    def numbers(self, keyword, field):
        """A list field `a,b,...` as floats."""
        text = self.value(keyword, field)
        if text is None:
            raise ReportError(f"{self.path}: no {keyword.upper()} {field}=")
        try:
            return [float(v) for v in text.split(",")]
        except ValueError:
            raise ReportError(f"{self._where(keyword)}: field '{field}': '{text}' is not a list "
                              f"of numbers") from None

    @property
    def title(self):
        card = self.card("TITLE", required=False)
        return card.text if card else Path(self.path).stem

    def _where(self, keyword):
        card = self.card(keyword, required=False)
        return f"{self.path}:{card.line}" if card else self.path

    # -- writing a variant -------------------------------------------------------------------
    def set(self, keyword, **values):
        """Replace (or add) fields of the first card with this keyword."""
        self.card(keyword).set(**values)
        return self

    def drop(self, keyword, *names):
        """Remove these fields of the first card with this keyword where present."""
        self.card(keyword).drop(*names)
        return self

    def remove_cards(self, keyword):
        """Remove every card with this keyword (the lines go; comments on lines of their own
        stay). Returns how many were removed."""
        doomed = {c.index for c in self.cards(keyword)}
        self._rebuild([line for i, line in enumerate(self.lines) if i not in doomed])
        return len(doomed)

    def replace_card(self, keyword, line):
        """Replace the first card with this keyword by `line` (a whole card, e.g. "DIRICHLET
        ref=3 uy=0"); its trailing comment goes with it."""
        index = self.card(keyword).index
        _parse_line(line, self.path, index + 1)
        lines = list(self.lines)
        lines[index] = line
        self._rebuild(lines)
        return self

    def add_card(self, line, after=None):
        """Add a card line after the last card with keyword `after`, or at the end."""
        _parse_line(line, self.path, len(self.lines) + 1)
        lines = list(self.lines)
        if after is not None:
            index = self.cards(after)[-1].index if self.has(after) else len(lines) - 1
            lines.insert(index + 1, line)
        else:
            lines.append(line)
        self._rebuild(lines)
        return self

    def _rebuild(self, lines):
        self.lines = lines
        self._cards = [Card(self, i) for i in range(len(lines))]

    def text(self):
        return "\n".join(self.lines) + ("\n" if self._newline_at_end or not self.lines else "")

    def write(self, path):
        """Write the deck to `path` through a temporary file renamed into place."""
        return write_text_atomically(path, self.text())


def read_deck(path):
    """Deck.read(path)."""
    return Deck.read(path)
