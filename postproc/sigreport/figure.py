"""Writing a figure: the one way a report saves a PNG (`save_figure`), which refuses a figure a
reader cannot read.

    fig, ax = pyplot().subplots()
    ax.plot(h, error)
    ax.set_xlabel("mesh size h (m)")
    ax.set_ylabel("relative error (-)")
    save_figure(fig, out / "error.png")   # the Path; the figure is closed either way

Refused (ChartError, naming the file, the axes and the axis): an axis that shows tick labels (a
measure) without a label ending in its unit in parentheses or brackets, "x1 (m)", "time [s]",
"pressure (GPa)", "cn (GPa s/m)", "relative error (-)", "outer loop (iterations)"; the unit is
made of the words of UNIT_WORDS joined by spaces, '/', '*' or '.', each with an optional power
("m^-2"), and a comma separates the units of a measure that adds two ("mm, MPa"). An axis with
no tick labels (a colour bar's short side, the top panel of a shared x) shows no measure and
needs none. Refused too: texts that collide (tick labels, axis labels, titles, legends,
annotations, the texts in a map's cells).

Before the checks, what can be untangled is: a legend that covers data (a point or a line of
its axes, an image) moves to the right of its axes (keep_legends_off_data); crowded x tick
labels of a log axis are written as plain numbers, then turned by 30 or 90 degrees; a title
that meets a tick label of its axes (a y tick at the top edge reaches half its height above
it, where the data put one) is lifted. The figure is then laid out again (tight_layout) unless
layout=False.
"""
import functools
import re
from pathlib import Path

from .errors import ReportError

# The units an axis may be labelled in: SI and the decks' (GPa, MPa, Pa and m; J/m per unit
# thickness), '-' for a pure number or a name, '%', and the counts the reports plot.
UNIT_WORDS = ("m", "mm", "s", "Pa", "kPa", "MPa", "GPa", "N", "kN", "MN", "GN", "J", "kJ", "MJ",
              "GJ", "kg", "rad", "1", "-", "%", "iterations", "nodes", "steps")
_UNIT_AT_END = re.compile(r"\s[(\[]\s*([^()\[\]]+?)\s*[)\]]$")
_FACTOR = re.compile(r"^(?:%s)(?:\^-?\d+)?$" % "|".join(re.escape(w) for w in UNIT_WORDS))


class ChartError(ReportError):
    """A figure a reader could not read: an axis without its unit, texts on top of each other."""


def axis_unit(label):
    """The unit at the end of an axis label ("x1 (m)" -> "m", "k [s]" -> "s"), or None when the
    label has none, or what it ends with is not a unit (the words of UNIT_WORDS)."""
    match = _UNIT_AT_END.search(label.strip())
    if not match:
        return None
    unit = match.group(1)
    factors = re.split(r"\s*[/*.,]\s*|\s+", unit)
    return unit if all(_FACTOR.match(f) for f in factors) else None


def _shown(texts):
    return [t for t in texts if t.get_visible() and t.get_text().strip()]


def _tick_labels(axis):
    """The tick labels an axis draws: those of its major and minor ticks inside its view."""
    lo, hi = sorted(axis.get_view_interval())
    slack = 1e-10 * max(abs(lo), abs(hi), 1e-300)
    ticks = [t for t in axis.get_major_ticks() + axis.get_minor_ticks()
             if lo - slack <= t.get_loc() <= hi + slack]
    return _shown([label for t in ticks for label in (t.label1, t.label2)])


def _describe(fig, ax):
    title = ax.get_title() or (fig._suptitle.get_text() if fig._suptitle else "")
    return f"axes {fig.axes.index(ax) + 1} of {len(fig.axes)}" + (f" ('{title}')" if title else "")


def missing_units(fig):
    """Every axis of fig that shows tick labels without a label ending in its unit, as text
    ("axes 1 of 2 ('Fig 4.7'): x label 'h' has no unit"); [] when every axis has one. Draws
    the figure (tick labels exist only once drawn)."""
    fig.canvas.draw()
    problems = []
    for ax in fig.axes:
        if not ax.get_visible() or not ax.axison:
            continue
        for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
            label = axis.get_label_text()
            if not _tick_labels(axis) and not label:
                continue
            if axis_unit(label) is None:
                problems.append(f"{_describe(fig, ax)}: {name} label '{label}' has no unit in "
                                "parentheses or brackets")
    return problems


def _texts(fig):
    """(owner, Text or Legend) of every text a reader sees: titles, axis labels, tick labels,
    offset texts, legends, annotations and texts in the axes."""
    items = [("suptitle", fig._suptitle)] if fig._suptitle else []
    for k, ax in enumerate(fig.axes, 1):
        if not ax.get_visible():
            continue
        items += [(f"axes {k} title", t) for t in (ax.title, ax._left_title, ax._right_title)]
        if ax.axison:
            for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
                items.append((f"axes {k} {name} label", axis.label))
                items.append((f"axes {k} {name} offset", axis.get_offset_text()))
                items += [(f"axes {k} {name} tick", t) for t in _tick_labels(axis)]
        items += [(f"axes {k} text", t) for t in ax.texts]
        if ax.get_legend():
            items.append((f"axes {k} legend", ax.get_legend()))
    return [(owner, t) for owner, t in items
            if t.get_visible() and (not hasattr(t, "get_text") or t.get_text().strip())]


def collisions(fig):
    """The pairs of texts of fig whose boxes overlap, as text; [] when none do. Draws fig."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = [(owner, t, t.get_window_extent(renderer)) for owner, t in _texts(fig)]
    found = []
    for i, (owner_a, a, box_a) in enumerate(boxes):
        for owner_b, b, box_b in boxes[i + 1:]:
            if box_a.overlaps(box_b) and box_a.width > 0 and box_b.width > 0:
                found.append(f"{owner_a} '{_text_of(a)}' and {owner_b} '{_text_of(b)}'")
    return found


def _text_of(artist):
    return artist.get_text() if hasattr(artist, "get_text") else "legend"


def _overlapping(texts, renderer):
    boxes = [t.get_window_extent(renderer) for t in texts]
    return any(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1:])


@functools.cache
def _plain_log_formatter():
    """The formatter class (made once, matplotlib being imported only when a figure is drawn)."""
    from matplotlib import ticker

    class PlainLogFormatter(ticker.LogFormatter):
        """The labels LogFormatter chooses, written "0.03" and "20", not "3 x 10^-2"."""

        def __call__(self, x, pos=None):
            return f"{x:g}" if super().__call__(x, pos) else ""
    return PlainLogFormatter


def _turn_crowded_x_ticks(fig):
    """Untangle the x tick labels of every axes where two of them overlap: on a log axis first
    write them as plain numbers ("20", not "2 x 10^1"), then turn them by 30 degrees (their end
    at the tick), by 90 where that is not enough; True when any changed."""
    turned = False
    for ax in fig.axes:
        if ax.get_xscale() == "log" and \
                not isinstance(ax.xaxis.get_major_formatter(), _plain_log_formatter()) and \
                _overlapping(_tick_labels(ax.xaxis), fig.canvas.get_renderer()):
            ax.xaxis.set_major_formatter(_plain_log_formatter()(labelOnlyBase=False))
            ax.xaxis.set_minor_formatter(_plain_log_formatter()(labelOnlyBase=False))
            turned = True
            fig.canvas.draw()
        for angle in (30, 90):
            ticks = _tick_labels(ax.xaxis)
            if not ticks or ticks[0].get_rotation() >= angle or \
                    not _overlapping(ticks, fig.canvas.get_renderer()):
                continue
            for t in ticks:
                t.set_rotation(angle)
                t.set_horizontalalignment("right" if angle < 90 else "center")
                t.set_rotation_mode("anchor" if angle < 90 else "default")
            turned = True
            fig.canvas.draw()
    return turned


def _lift_titles(fig):
    """Lift the title of every axes that meets one of its tick labels, by the labels' overlap
    and a gap of 2 points; True when any moved. Draws fig."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    lifted = False
    for ax in fig.axes:
        title = ax.title
        if not title.get_visible() or not title.get_text().strip():
            continue
        box = title.get_window_extent(renderer)
        ticks = [t.get_window_extent(renderer) for t in
                 _tick_labels(ax.xaxis) + _tick_labels(ax.yaxis)]
        overlap = max((t.y1 - box.y0 for t in ticks if t.overlaps(box)), default=0.0)
        if overlap <= 0:
            continue
        from matplotlib import rcParams
        pad = rcParams["axes.titlepad"] + (overlap + 2 * fig.dpi / 72) * 72 / fig.dpi
        ax.set_title(title.get_text(), pad=pad, fontsize=title.get_fontsize(),
                     fontweight=title.get_fontweight())
        lifted = True
    if lifted:
        fig.canvas.draw()
    return lifted


def _covers_data(ax, box):
    """Whether the display box covers data of ax: an image, a point of a collection, a vertex of
    a line or a point of one of its segments (nine points a segment)."""
    import numpy as np
    if any(im.get_visible() for im in ax.images):
        return True

    def inside(p):
        return bool(np.any((p[:, 0] >= box.x0) & (p[:, 0] <= box.x1)
                           & (p[:, 1] >= box.y0) & (p[:, 1] <= box.y1)))
    for c in ax.collections:
        offsets = np.asarray(c.get_offsets(), dtype=float).reshape(-1, 2)
        if c.get_visible() and len(offsets) and inside(c.get_offset_transform().transform(offsets)):
            return True
    for line in ax.lines:
        if not line.get_visible():
            continue
        xy = line.get_transform().transform(np.asarray(line.get_xydata(), dtype=float))
        if line.get_linestyle() not in ("None", "none", "", " ") and len(xy) > 1:
            a, b = xy[:-1], xy[1:]
            ok = np.all(np.isfinite(a), axis=1) & np.all(np.isfinite(b), axis=1)
            t = np.linspace(0, 1, 9)[None, :, None]
            xy = (a[ok][:, None, :] + t * (b[ok] - a[ok])[:, None, :]).reshape(-1, 2)
        if len(xy) and inside(xy[np.all(np.isfinite(xy), axis=1)]):
            return True
    return False


def keep_legends_off_data(fig):
    """Move every legend that covers data of its axes to the right of them (the figure widened
    by its width); True when one moved. Draws fig."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    moved = []
    for ax in fig.axes:
        legend = ax.get_legend()
        if legend is None or not legend.get_visible() or \
                not _covers_data(ax, legend.get_window_extent(renderer)):
            continue
        handles, labels = ax.get_legend_handles_labels()
        size = legend.get_texts()[0].get_fontsize() if legend.get_texts() else None
        moved.append(ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.02, 1),
                               borderaxespad=0, fontsize=size))
    if moved:
        fig.canvas.draw()
        width = max(legend.get_window_extent(renderer).width for legend in moved) / fig.dpi
        columns = max(ax.get_subplotspec().get_geometry()[1] if ax.get_subplotspec() else 1
                      for ax in fig.axes if ax.get_legend() in moved)
        w, h = fig.get_size_inches()
        fig.set_size_inches(w + columns * (width + 0.2), h)
    return bool(moved)


def save_figure(fig, path, dpi=110, layout=True):
    """Save fig as a PNG at path (bbox_inches="tight": nothing drawn outside the axes is cut)
    after the untangling and the checks of the module docstring; close it either way and return
    the Path. layout: lay the figure out again (tight_layout) after a legend moved or tick labels
    turned; False for a figure laid out by hand (a colour bar shared by several axes)."""
    from .charts import pyplot
    path = Path(path)
    try:
        problems = missing_units(fig)
        if problems:
            raise ChartError(f"{path}: not saved, an axis without its unit: " + "; ".join(problems))
        if keep_legends_off_data(fig) and layout:
            fig.tight_layout()
        for _ in range(2):  # a new layout changes the room between the ticks
            if not _turn_crowded_x_ticks(fig) or not layout:
                break
            fig.tight_layout()
        if _lift_titles(fig) and layout:
            fig.tight_layout()
            _lift_titles(fig)  # the new layout may put a tick at the top edge again
        problems = collisions(fig)
        if problems:
            raise ChartError(f"{path}: not saved, texts on top of each other: "
                             + "; ".join(problems))
        fig.savefig(path, dpi=dpi, bbox_inches="tight")
    finally:
        pyplot().close(fig)
    return path
