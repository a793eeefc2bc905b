"""sigreport: the one report library of the scene reports (postproc/<scene>_report.py).

Stdlib + numpy + matplotlib, Debian's /usr/bin/python3. A report script in postproc/ imports it
directly (`from sigreport import ...`: the script's folder is on sys.path); elsewhere put
postproc/ on PYTHONPATH. matplotlib (and numpy) are imported only when a chart is drawn (or an
array asked for), so the deck command line starts fast.

Modules (each docstring states its API):
  ds      read_ds(path[, arrays]) -> Ds: DS files through `sig-dump --json --values` only
  deck    Deck.read(path): cards and fields of a datafile; set/drop/remove_cards/replace_card/
          add_card/write for deck variants (drivers: `python3 -m sigreport deck ...`)
  thesis  load_thesis() -> ThesisValues: postproc/thesis_values.csv, lookup by (scene, item, key)
  cells   fmt, fmt_spec, pct, run_cell (Nv, sway), ours_thesis, within (tolerance),
          tolerance_text
  table   Table(header, rows, caption).markdown() / .as_json(); markdown_table
  checks  Checks().add(name, passed, ...): PASS / FAIL / not run, table and JSON
  charts  speed_accuracy_chart(path, [Series(label, [Point(x, y, text)])], ...);
          stability_map(path, [MapPanel(title, rows, columns, cells)]) with MapCell(text, status);
          energy_chart(path, [(label, marker, times, energies)], title, window)
  figure  save_figure(fig, path): the one way a report writes a PNG; refuses an axis without
          its unit ("x1 (m)") and texts on top of each other (ChartError)
  fits    loglog_slope(xs, ys): convergence rates
  mesh    Mesh.read(case.nopo): coordinates, triangles, edges, boundary, strain_norm(u)
  march   March(folder, deck, arrays): a run of sig-march (case.hist, error.json); read_error
  impact  energy.csv runs of the impact scenes: read_energy_rows, hist_scalars, wall_seconds,
          energy_measures, impact_window, energy_curves, speed_point, stability_status
  scene   read_command, read_summary, solve_seconds, read_csv_columns, find_pvd,
          write_scene_json(out, scene, title, command, checks, key_table, charts, pvd),
          write_report(out, text, ...): report.md and then scene.json; finish_report(out, text,
          ..., checks, summary, ...): summary.json too, the checks printed, the exit status

A scene report, in outline (scene7a_report.py, scene4_report.py): one function a section,
returning its markdown lines and adding its checks; main() reads the folder and joins them.

    from sigreport import (Checks, Table, load_thesis, main_guard, ours_thesis, read_command,
                           run_cell, speed_accuracy_chart, within, write_report)

    def section_fig45(out, thesis, checks):
        table = Table(["alpha", "outer iterations"], caption="Fig 4.5: ours (thesis)")
        table.add(1, ours_thesis(run_cell(conv, its), thesis.get("convexification_iterations",
                                                                   "alpha=1;a=1;b=0.5")))
        checks.add("slope of Fig 4.7 within 1 +- 0.15", within(slope, 1, abs=0.15), ours=slope)
        speed_accuracy_chart(out / "speed_accuracy.png", series, "sig-solve time (s)",
                             "relative error (-)")
        return ["## Fig 4.5", "", table.markdown(), "", "![speed](speed_accuracy.png)"], table

    def main():
        out = Path(sys.argv[1])
        info = read_command(out, required=("command",))
        checks = Checks()
        lines, table = section_fig45(out, load_thesis().scene("4"), checks)
        write_report(out, "\n".join(lines), "4", "Scene 4: ...", info, checks, key_table=table,
                     charts={"speed_accuracy": "speed_accuracy.png"})

    if __name__ == "__main__":
        main_guard(main)
"""
import sys

__all__ = [
    "MapCell", "MapPanel", "Point", "Series", "energy_chart", "pyplot", "speed_accuracy_chart",
    "stability_map", "ChartError", "axis_unit", "save_figure",
    "MISSING", "fmt", "fmt_spec", "is_missing", "ours_thesis", "pct", "run_cell",
    "tolerance_text", "within", "Check", "Checks", "Deck", "read_deck", "Ds", "read_ds",
    "ReportError", "loglog_slope", "March", "read_error", "Mesh",
    "EARLIER_STAGE_PHASES", "find_pvd", "read_command", "read_csv_columns", "read_summary",
    "solve_seconds", "finish_report", "write_report", "write_scene_json", "Table",
    "markdown_table", "THESIS_CSV",
    "ThesisValues", "load_thesis", "main_guard",
]

from .charts import (MapCell, MapPanel, Point, Series, energy_chart, pyplot,
                     speed_accuracy_chart, stability_map)
from .cells import (MISSING, fmt, fmt_spec, is_missing, ours_thesis, pct, run_cell,
                    tolerance_text, within)
from .checks import Check, Checks
from .deck import Deck, read_deck
from .ds import Ds, read_ds
from .errors import ReportError
from .figure import ChartError, axis_unit, save_figure
from .fits import loglog_slope
from .march import March, read_error
from .mesh import Mesh
from .scene import (EARLIER_STAGE_PHASES, find_pvd, finish_report, read_command, read_csv_columns,
                    read_summary, solve_seconds, write_report, write_scene_json)
from .table import Table, markdown_table
from .thesis import THESIS_CSV, ThesisValues, load_thesis


def main_guard(main, name=None):
    """Run a report's main(); a ReportError ends the script with "NAME: error: message" on
    stderr and exit code 1 instead of a traceback. main's return value is the exit code."""
    name = name or sys.argv[0].rsplit("/", 1)[-1]
    try:
        code = main()
    except ReportError as e:
        sys.exit(f"{name}: error: {e}")
    sys.exit(code or 0)

