"""The two charts every scene report draws, as PNG (matplotlib, Agg backend):

speed_accuracy_chart: each method, mesh and parameter a point (seconds against an error), one
Series per method (or method and parameter), each point annotated with what varies along the
series ("N=128", "r=1e4", "k=1e-3"). Annotations are de-duplicated: points of several series
that fall on one spot (exact methods on one mesh share their error) get ONE label where the
labels would overlap, the series are told apart by the legend; a label that would overlap a
different one moves below or left of its point. A run that did not converge has no error: give
y=None, it is drawn hollow on the chart's top edge, on a grey "Nv" line.

    series = [Series("PDAS gamma = 1e2",
                     [Point(0.21, 3.1e-3, "N=128"), Point(0.52, 1.2e-3, "N=256")], color="C0"),
              Series("projection c = 1", [Point(0.30, None, "N=128")], marker="s", line="")]
    speed_accuracy_chart(out / "speed_accuracy.png", series, xlabel="sig-solve time (s)",
                         ylabel="relative L2 pressure error (-)", title="Hertz: speed vs accuracy")

stability_map: method x parameter x mesh -> a grid per panel (e.g. one panel per method, rows =
meshes, columns = parameter values); each MapCell has a text (an iteration count, "Nv", an
energy change), a status and an optional value. Status "ok" cells with a value are coloured on
one logarithmic colour scale for all panels (its bar labelled value_label); other statuses by a
fixed colour (Nv red, missing grey, gain/drift orange, dissipates blue, chatter yellow); "sway"
and "drift" cells are framed in red.

    panels = [MapPanel("pdas: total iterations", rows=["N = 128"], columns=["1", "10"],
                       cells=[[MapCell("59", "ok", 59), MapCell("Nv", "Nv")]],
                       xlabel="gamma (GPa/m)", ylabel="mesh (-)")]
    stability_map(out / "stability.png", panels, value_label="total (iterations)")

energy_chart: energy histories near an impact (scenes 8a, 8b).

Every chart, these and the reports' own, is written by save_figure (sigreport.figure): it
refuses an axis without its unit and texts on top of each other.
"""
import math
from typing import NamedTuple

from .figure import keep_legends_off_data, save_figure


def pyplot():
    """matplotlib.pyplot with the Agg backend (no display needed)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


class Point(NamedTuple):
    x: float
    y: float = None   # None: not converged (Nv), drawn on the top edge
    text: str = ""    # the annotation ("N=128"); "" for none


class Series:
    """A line (or scatter with line="") of points of one method / parameter."""

    def __init__(self, label, points, color=None, marker="o", line="-", hollow=True,
                 alpha=1.0, markersize=7):
        self.label, self.points = label, list(points)
        self.color, self.marker, self.line = color, marker, line
        self.hollow, self.alpha, self.markersize = hollow, alpha, markersize


def _annotate_once(ax, items, fontsize, gap=3, same_gap=20):
    """Annotate (x, y, text) items without clutter: an item whose label would come within
    `same_gap` pixels of a label with the same text is not labelled again (label once, the legend
    tells the series apart); a label that would come within `gap` pixels of another or of the
    legend moves below, to the left or further away from its point, and is left out when no
    place is free (the report's table has every number). A label stays inside the axes: outside
    it could meet a tick label, the axis labels or the title, which the points' positions (the
    measured times) would decide from run to run."""
    renderer = ax.figure.canvas.get_renderer()
    frame = ax.get_window_extent(renderer)
    legend = ax.get_legend()
    placed = [(legend.get_window_extent(renderer), None)] if legend else []  # (bbox, text)
    offsets = [(4, 4), (4, -10), (-4, 4), (-4, -10), (4, 16), (4, -22), (-4, 16), (-4, -22)]
    for x, y, text in items:
        for offset in offsets:
            ann = ax.annotate(text, (x, y), textcoords="offset points", xytext=offset,
                              fontsize=fontsize, ha="left" if offset[0] > 0 else "right")
            box = ann.get_window_extent(renderer)
            if any(t == text and box.padded(same_gap).overlaps(b) for b, t in placed):
                ann.remove()
                break
            inside = (frame.x0 <= box.x0 and box.x1 <= frame.x1 and frame.y0 <= box.y0
                      and box.y1 <= frame.y1)
            if inside and not any(box.padded(gap).overlaps(b) for b, _ in placed):
                placed.append((box, text))
                break
            ann.remove()


def speed_accuracy_chart(path, series, xlabel, ylabel, title="", log=True, figsize=(7, 5),
                         dpi=120, legend_fontsize=8, label_fontsize=7):
    """Draw the series (see the module docstring) and save the PNG at `path`; returns path."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=figsize)
    if log:
        ax.set_xscale("log")
        ax.set_yscale("log")
    finite = [p.y for s in series for p in s.points if p.y is not None and p.y > 0]
    top = 3 * max(finite) if finite else 1.0
    labels, nv_points = [], False
    for s in series:
        ok = [p for p in s.points if p.y is not None]
        nv = [p for p in s.points if p.y is None]
        style = dict(color=s.color, marker=s.marker, markersize=s.markersize, alpha=s.alpha)
        fill = dict(fillstyle="none") if s.hollow else {}
        handle = None
        if ok:
            handle, = ax.plot([p.x for p in ok], [p.y for p in ok], linestyle=s.line or "none",
                              **style, **fill, label=s.label)
            labels += [(p.x, p.y, p.text) for p in ok if p.text]
        if nv:
            nv_points = True
            color = handle.get_color() if handle else s.color
            ax.plot([p.x for p in nv], [top] * len(nv), linestyle="none", marker=s.marker,
                    markersize=s.markersize, color=color, fillstyle="none", alpha=s.alpha,
                    label=None if handle else s.label)
            labels += [(p.x, top, f"{p.text} Nv".strip()) for p in nv]
    if nv_points:
        ax.axhline(top, color="grey", lw=0.5)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title + (" (hollow on the grey line: Nv)" if nv_points else ""))
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=legend_fontsize)
    ax.margins(0.08)  # room for the labels of the outermost points
    fig.tight_layout()
    if keep_legends_off_data(fig):
        fig.tight_layout()
    fig.canvas.draw()
    _annotate_once(ax, labels, label_fontsize)
    return save_figure(fig, path, dpi=dpi, layout=False)


class MapCell(NamedTuple):
    text: str
    status: str = "ok"   # ok Nv missing sway drift gain dissipates chatter ("a+b": a's colour)
    value: float = None  # coloured by log10(value) when status is ok or framed


class MapPanel(NamedTuple):
    title: str
    rows: list           # row labels (e.g. "N = 128")
    columns: list        # column labels (e.g. parameter values)
    cells: list          # cells[i][j]: MapCell
    xlabel: str = ""
    ylabel: str = ""


def energy_chart(path, curves, title, window, markersize=3,
                 ylabel="discrete energy (8.33) E / E0 (-)"):
    """The energy histories of several runs near an impact: curves = [(label, marker, times,
    energies)], each drawn on the times inside window = (t0, t1); a curve with none is left out.
    Markers every len/25 points, so that long histories stay lines."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    for label, marker, times, energies in curves:
        pts = [(t, e) for t, e in zip(times, energies) if window[0] <= t <= window[1]]
        if pts:
            ax.plot(*zip(*pts), marker=marker, markersize=markersize, linewidth=1,
                    markevery=max(1, len(pts) // 25), label=label)
    ax.set_xlabel("time (s)")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    return save_figure(fig, path, dpi=110)


PALETTE = {"ok": "#8fd18f", "Nv": "#e07070", "missing": "#dddddd", "gain": "#f0b050",
           "drift": "#f0b050", "dissipates": "#9ec5e8", "chatter": "#e8e070", "sway": "#8fd18f"}
FRAMED = ("sway", "drift")


def stability_map(path, panels, value_label="value (-)", title="", palette=None,
                  cmap="viridis", dpi=110, cell_size=(1.3, 0.55), fontsize=8):
    """Draw the panels side by side (see the module docstring) and save the PNG; returns path."""
    plt = pyplot()
    from matplotlib import colors as mcolors
    palette = {**PALETTE, **(palette or {})}
    values = [c.value for p in panels for row in p.cells for c in row
              if c.value is not None and c.value > 0]
    lo, hi = (math.log10(min(values)), math.log10(max(values))) if values else (0.0, 1.0)
    hi = max(hi, lo + 1e-9)
    norm = mcolors.LogNorm(vmin=10 ** min(lo, 0.0), vmax=10 ** hi)
    colormap = plt.get_cmap(cmap)
    width = sum(1.6 + cell_size[0] * len(p.columns) for p in panels) + (1.2 if values else 0)
    height = 1.2 + cell_size[1] * max(len(p.rows) for p in panels)
    fig, axes = plt.subplots(1, len(panels), figsize=(width, height), squeeze=False,
                             gridspec_kw={"width_ratios": [max(1, len(p.columns)) for p in panels]})
    for ax, panel in zip(axes[0], panels):
        for i, row in enumerate(panel.cells):
            for j, cell in enumerate(row):
                status = cell.status.split("+")[0]
                coloured = cell.value is not None and cell.value > 0 and status in ("ok",) + FRAMED
                face = colormap(norm(cell.value)) if coloured else \
                    palette.get(status, palette["missing"])
                ax.add_patch(plt.Rectangle((j, i), 1, 1, facecolor=face, edgecolor="white"))
                if status in FRAMED:
                    ax.add_patch(plt.Rectangle((j + 0.04, i + 0.04), 0.92, 0.92, fill=False,
                                               edgecolor="red", linewidth=2))
                dark = coloured and sum(mcolors.to_rgb(face)) < 1.2
                ax.text(j + 0.5, i + 0.5, cell.text, ha="center", va="center",
                        fontsize=fontsize, color="white" if dark else "black")
        ax.set_xlim(0, len(panel.columns))
        ax.set_ylim(len(panel.rows), 0)
        ax.set_xticks([j + 0.5 for j in range(len(panel.columns))], [str(c) for c in panel.columns],
                      fontsize=fontsize)
        ax.set_yticks([i + 0.5 for i in range(len(panel.rows))], [str(r) for r in panel.rows],
                      fontsize=fontsize)
        ax.set_xlabel(panel.xlabel)
        ax.set_ylabel(panel.ylabel)
        ax.set_title(panel.title, fontsize=fontsize + 1)
    if values:
        from matplotlib import ticker
        mappable = plt.cm.ScalarMappable(norm=norm, cmap=colormap)
        bar = fig.colorbar(mappable, ax=axes[0].tolist(), label=value_label)
        bar.ax.yaxis.set_major_locator(ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
        bar.ax.yaxis.set_major_formatter(ticker.FuncFormatter(lambda v, _: f"{v:g}"))
        bar.ax.yaxis.set_minor_formatter(ticker.NullFormatter())
    if title:
        fig.suptitle(title, fontsize=fontsize + 2, y=1.0 + 0.25 / height)
    return save_figure(fig, path, dpi=dpi, layout=False)
