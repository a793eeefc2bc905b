"""Markdown tables, and the same table as the `key_table` of the scene index entry.

    t = Table(["N", "c = 1", "ALM"], [[128, "12 (11)", "7 (7)"]], caption="Table 7.1: iterations")
    t.markdown()   # "| N | c = 1 | ALM |\\n|---|---|---|\\n| 128 | 12 (11) | 7 (7) |"
    t.as_json()    # {"caption": ..., "header": [...], "rows": [["128", "12 (11)", "7 (7)"]]}
    markdown_table(header, rows)  # the markdown alone
"""


def _cell(value):
    """A cell's text with its pipes escaped: a norm ||u||_V would otherwise split the cell."""
    return str(value).replace("|", "\\|")


def markdown_table(header, rows):
    """A GitHub markdown table: header row, '|---|' rule, one line per row (cells with str(),
    pipes escaped)."""
    lines = ["| " + " | ".join(_cell(h) for h in header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(_cell(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


class Table:
    """A header, rows of cells and a caption."""

    def __init__(self, header, rows=(), caption=""):
        self.header = list(header)
        self.rows = [list(r) for r in rows]
        self.caption = caption

    def add(self, *cells):
        self.rows.append(list(cells))

    def markdown(self):
        return markdown_table(self.header, self.rows)

    def lines(self):
        return self.markdown().split("\n")

    def as_json(self):
        return {"caption": self.caption, "header": [str(h) for h in self.header],
                "rows": [[str(c) for c in row] for row in self.rows]}
