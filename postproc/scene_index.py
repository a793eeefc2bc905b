#!/usr/bin/env python3
"""The index of all scenes: OUTDIR/index.md and OUTDIR/index.html, one page listing each scene's
checks (PASS, FAIL, erratum: a thesis claim an independent reference contradicts, counted apart
from the FAILs and no FAIL of the scene), its key table "ours (thesis)", its charts and links to
its report, its ParaView files and its notes (datafiles/<scene>/README.md of the source tree),
from the entries OUTDIR/<folder>/scene.json that the scene reports write
(postproc/sigreport/scene.py).

    scene_index.py OUTDIR [--runs FILE]

--runs: the table of the driver runs drivers/scenes.sh made (tab-separated: folder, command, exit
status, seconds, log file relative to OUTDIR); every folder listed there is a scene of the index,
and one whose driver failed or left no readable scene.json is shown as a FAIL, never skipped.
Folders of OUTDIR with a scene.json that the runs do not list (a scene run on its own) are shown
too. The HTML is self-contained but for the images, which it links relative to OUTDIR, as the
reports do. Stdlib only, but for sigreport's markdown tables.
"""
import argparse
import datetime
import html
import json
import os
import subprocess
import sys
from pathlib import Path
from urllib.parse import quote

sys.path.insert(0, str(Path(__file__).resolve().parent))
from sigreport import markdown_table  # noqa: E402
from sigreport.files import write_text_atomically  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
CHART_TITLES = {"speed_accuracy": "speed against accuracy", "stability": "stability"}
# The scene folders whose notes, datafiles/<name>/README.md, are named otherwise.
NOTES_FOLDERS = {"friction_hertz": "friction", "scene3d_hertz": "scene3d",
                 "scene3d_cattaneo": "scene3d", "scene3d_impact": "scene3d",
                 "scene3d_crush": "scene3d"}


class Scene:
    """One row of the index: a folder of OUTDIR, its driver run (if any) and its scene.json."""

    def __init__(self, folder, run=None):
        self.folder = folder
        self.run = run or {}
        self.entry = None
        self.problems = []  # what makes the scene a FAIL besides its checks

    @property
    def name(self):
        return (self.entry or {}).get("scene") or self.folder

    @property
    def title(self):
        return (self.entry or {}).get("title") or ""

    @property
    def checks(self):
        return (self.entry or {}).get("checks") or []

    def counts(self):
        """(passed, failed, errata, not run): an erratum is a failed claim with its reference,
        counted apart."""
        passed = sum(c.get("pass") is True for c in self.checks)
        errata = sum(is_erratum(c) for c in self.checks)
        failed = sum(c.get("pass") is False for c in self.checks) - errata
        return passed, failed, errata, len(self.checks) - passed - failed - errata

    @property
    def ok(self):
        passed, failed, errata, _ = self.counts()
        return not self.problems and failed == 0 and passed + errata > 0

    def verdict(self):
        passed, failed, errata, not_run = self.counts()
        if self.entry is None:
            return "FAIL: " + "; ".join(self.problems)
        text = f"{passed}/{len(self.checks)} checks pass"
        if errata:
            text += f", {errata} erratum"
        if failed:
            text += f", {failed} FAIL"
        if not_run:
            text += f", {not_run} not run"
        if not self.checks:
            text = "no checks"
        return ("PASS: " if self.ok else "FAIL: ") + "; ".join([text] + self.problems)

    def seconds(self):
        value = self.run.get("seconds")
        if value in (None, ""):
            value = (self.entry or {}).get("seconds")
        try:
            return f"{float(value):.0f} s"
        except (TypeError, ValueError):
            return "—"

    def report(self, out):
        """The report's path in the scene's folder: scene.json's, or a report.md the scene left
        without one (still worth a link); None when there is none."""
        name = (self.entry or {}).get("report") or "report.md"
        return name if (out / self.folder / name).is_file() else None

    def notes(self, out):
        """(URL relative to OUTDIR, path in the source tree) of the scene's notes, its narrative
        and benchmark tables (datafiles/<scene>/README.md); None when it has none."""
        path = Path("datafiles") / NOTES_FOLDERS.get(self.folder, self.folder) / "README.md"
        if not (ROOT / path).is_file():
            return None
        return quote(os.path.relpath(ROOT / path, out.resolve())), str(path)

    def link(self, path):
        """A path of the scene (relative to its folder) as a URL relative to OUTDIR."""
        return quote(f"{self.folder}/{path}")


def read_runs(path):
    runs = {}
    for line in Path(path).read_text().splitlines():
        if not line.strip():
            continue
        folder, command, status, seconds, log = (line.split("\t") + [""] * 5)[:5]
        runs[folder] = {"command": command, "exit": status, "seconds": seconds, "log": log}
    return runs


def load(out, scene):
    """Read the scene's scene.json; every problem found is recorded, nothing raises."""
    status = scene.run.get("exit")
    if status not in (None, "", "0"):
        log = scene.run.get("log")
        scene.problems.append(f"driver exited {status}" + (f" (log: {log})" if log else ""))
    path = out / scene.folder / "scene.json"
    if not path.is_file():
        scene.problems.append(f"no {scene.folder}/scene.json")
        return
    try:
        entry = json.loads(path.read_text())
        if not isinstance(entry, dict):
            raise ValueError("not a JSON object")
    except (OSError, ValueError) as error:
        scene.problems.append(f"{scene.folder}/scene.json unreadable: {error}")
        return
    scene.entry = entry
    folder = out / scene.folder
    wanted = [entry.get("report") or "report.md"] + list((entry.get("charts") or {}).values())
    wanted += list(entry.get("pvd") or [])
    for name in wanted:
        if Path(name).is_absolute() or ".." in Path(name).parts or not (folder / name).is_file():
            scene.problems.append(f"missing {scene.folder}/{name}")
    if not isinstance(entry.get("checks", []), list):
        scene.problems.append("scene.json: checks is not a list")
        entry["checks"] = []


def is_erratum(check):
    return check.get("pass") is False and bool(check.get("erratum"))


def check_text(check):
    if is_erratum(check):
        return "erratum"
    return {True: "PASS", False: "FAIL"}.get(check.get("pass"), "not run")


def check_class(check):
    """The HTML class of a check's result."""
    return {"PASS": "pass", "FAIL": "fail", "erratum": "erratum"}.get(check_text(check), "notrun")


def check_detail(check):
    """The detail, with the erratum's reference or the FAIL's study after it."""
    detail = check.get("detail", "")
    if is_erratum(check):
        return f"{detail}; reference: {check['erratum']}"
    if check.get("study"):
        return f"{detail}; study: {check['study']}"
    return detail


def revision():
    try:
        return subprocess.run(["git", "-C", str(ROOT), "describe", "--always", "--dirty"],
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def summary_text(scenes):
    """"5 of 8 scenes pass all their checks", and the errata apart when there are some."""
    ok = sum(s.ok for s in scenes)
    errata = sum(s.counts()[2] for s in scenes)
    return (f"{ok} of {len(scenes)} scenes pass all their checks"
            + (f" ({errata} {'erratum' if errata == 1 else 'errata'} of the thesis: claims an "
               "independent reference contradicts, counted apart from the FAILs)"
               if errata else ""))


def markdown(out, scenes, stamp):
    lines = ["# Signorini: the scenes", "",
             f"{stamp}. {summary_text(scenes)}.", "",
             markdown_table(["scene", "title", "result", "time", "report"],
                            [[s.name, s.title, s.verdict(), s.seconds(),
                              f"[report]({s.link(s.report(out))})" if s.report(out) else "—"]
                             for s in scenes]), ""]
    for s in scenes:
        lines += [f"## {s.title or s.name}", "",
                  f"**{s.verdict()}**", ""]
        command = s.run.get("command") or (s.entry or {}).get("command")
        if command:
            lines += [f"Command: `{command}` ({s.seconds()})", ""]
        if s.report(out):
            lines += [f"[Report]({s.link(s.report(out))})", ""]
        if s.notes(out):
            url, path = s.notes(out)
            lines += [f"Notes: [{path}]({url})", ""]
        if s.entry is None:
            continue
        if s.checks:
            lines += [markdown_table(["check", "result", "detail"],
                                     [[c.get("name", ""), check_text(c), check_detail(c)]
                                      for c in s.checks]), ""]
        table = s.entry.get("key_table")
        if isinstance(table, dict) and table.get("header"):
            if table.get("caption"):
                lines += [f"*{table['caption']}*", ""]
            lines += [markdown_table(table["header"], table.get("rows") or []), ""]
        for name, path in (s.entry.get("charts") or {}).items():
            lines += [f"![{CHART_TITLES.get(name, name)}]({s.link(path)})", ""]
        pvd = s.entry.get("pvd") or []
        if pvd:
            lines += ["ParaView: " + ", ".join(f"[{p}]({s.link(p)})" for p in pvd), ""]
    return "\n".join(lines)


STYLE = """
body { font-family: sans-serif; max-width: 70em; margin: 1em auto; padding: 0 1em; }
table { border-collapse: collapse; margin: 0.5em 0; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; text-align: left; vertical-align: top; }
th { background: #eee; }
.pass { color: #060; font-weight: bold; }
.fail { color: #b00; font-weight: bold; }
.notrun { color: #666; }
.erratum { color: #a60; font-weight: bold; }
.charts { display: flex; flex-wrap: wrap; gap: 1em; }
figure { margin: 0; flex: 1 1 30em; max-width: 100%; }
figcaption { font-weight: bold; margin-bottom: 0.3em; }
img { max-width: 100%; border: 1px solid #ddd; }
code { background: #f4f4f4; }
summary { cursor: pointer; margin: 0.5em 0; }
"""


def html_table(header, rows, raw_columns=()):
    """Cells are escaped, except in raw_columns (already HTML)."""
    out = ["<table>", "<tr>" + "".join(f"<th>{html.escape(str(h))}</th>" for h in header) + "</tr>"]
    for row in rows:
        cells = [str(c) if i in raw_columns else html.escape(str(c)) for i, c in enumerate(row)]
        out.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    return "\n".join(out + ["</table>"])


def verdict_html(scene):
    return f'<span class="{"pass" if scene.ok else "fail"}">{html.escape(scene.verdict())}</span>'


def anchor(scene):
    return "scene-" + quote(scene.folder)


def page(out, scenes, stamp):
    body = ["<h1>Signorini: the scenes</h1>",
            f"<p>{html.escape(stamp)}. {html.escape(summary_text(scenes))}.</p>",
            html_table(["scene", "title", "result", "time", "report"],
                       [[f'<a href="#{anchor(s)}">{html.escape(s.name)}</a>', s.title,
                         verdict_html(s), s.seconds(),
                         f'<a href="{s.link(s.report(out))}">report</a>' if s.report(out) else "—"]
                        for s in scenes], raw_columns=(0, 2, 4))]
    for s in scenes:
        body += [f'<h2 id="{anchor(s)}">{html.escape(s.title or s.name)}</h2>',
                 f"<p>{verdict_html(s)}</p>"]
        command = s.run.get("command") or (s.entry or {}).get("command")
        if command:
            body.append(f"<p>Command: <code>{html.escape(command)}</code> ({s.seconds()})</p>")
        if s.report(out):
            body.append(f'<p><a href="{s.link(s.report(out))}">Report</a></p>')
        if s.notes(out):
            url, path = s.notes(out)
            body.append(f'<p>Notes: <a href="{url}">{html.escape(path)}</a></p>')
        if s.entry is None:
            continue
        if s.checks:
            # A passing scene's checks fold away; a failing one's stay open.
            body.append(f"<details{'' if s.ok else ' open'}><summary>{len(s.checks)} checks"
                        f"</summary>")
            body.append(html_table(
                ["check", "result", "detail"],
                [[c.get("name", ""), f'<span class="{check_class(c)}">{check_text(c)}</span>',
                  check_detail(c)] for c in s.checks],
                raw_columns=(1,)))
            body.append("</details>")
        table = s.entry.get("key_table")
        if isinstance(table, dict) and table.get("header"):
            if table.get("caption"):
                body.append(f"<p><em>{html.escape(str(table['caption']))}</em></p>")
            body.append(html_table(table["header"], table.get("rows") or []))
        figures = []
        for name, path in (s.entry.get("charts") or {}).items():
            title = html.escape(CHART_TITLES.get(name, name))
            if f"missing {s.folder}/{path}" in s.problems:
                body.append(f'<p class="fail">chart {title}: {html.escape(path)} is missing</p>')
                continue
            figures.append(f'<figure><figcaption>{title}</figcaption>'
                           f'<a href="{s.link(path)}"><img src="{s.link(path)}" alt="{title}"></a>'
                           f'</figure>')
        if figures:
            body.append('<div class="charts">' + "".join(figures) + "</div>")
        pvd = s.entry.get("pvd") or []
        if pvd:
            body.append(f"<details><summary>ParaView: {len(pvd)} .pvd files</summary><p>"
                        + ", ".join(f'<a href="{s.link(p)}">{html.escape(p)}</a>' for p in pvd)
                        + "</p></details>")
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<title>Signorini: the scenes</title>\n<style>" + STYLE + "</style>\n</head>\n"
            "<body>\n" + "\n".join(body) + "\n</body>\n</html>\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("outdir", type=Path)
    parser.add_argument("--runs", type=Path, help="the driver runs of drivers/scenes.sh")
    args = parser.parse_args()
    out = args.outdir
    if not out.is_dir():
        sys.exit(f"scene_index.py: {out} is not a folder")
    runs = read_runs(args.runs) if args.runs else {}
    folders = list(runs)
    folders += sorted(p.parent.name for p in out.glob("*/scene.json") if p.parent.name not in runs)
    scenes = [Scene(folder, runs.get(folder)) for folder in folders]
    for scene in scenes:
        load(out, scene)
    stamp = (f"Made {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC at "
             f"revision {revision()}")
    md = write_text_atomically(out / "index.md", markdown(out, scenes, stamp) + "\n")
    page_path = write_text_atomically(out / "index.html", page(out, scenes, stamp))
    failed = [s.folder for s in scenes if not s.ok]
    print(f"{md}\n{page_path}")
    print(f"scene_index.py: {len(scenes) - len(failed)} of {len(scenes)} scenes pass"
          + (f"; FAIL: {', '.join(failed)}" if failed else ""))
    return 1 if failed or not scenes else 0


if __name__ == "__main__":
    sys.exit(main())
