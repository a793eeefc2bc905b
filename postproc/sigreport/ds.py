"""DS files (case.b, case.hist, case.cont, ...) for the reports: read ONLY through
`sig-dump --json --values FILE` (modules/post/app/sig-dump.cpp), never by a second parser of the
binary layout in Python. If a report needs something sig-dump does not print, extend sig-dump.

    ds = read_ds("out/scene7b/N128/pdas_1e4/case.b")
    ds.scalar("iterations")     # first value of an array: 59 (int64 arrays give ints)
    ds["step_iterations"]       # flat row-major list of values; text arrays give a str
    ds.shape("step_u")          # [14, 1792]
    ds.get("failure", "")       # default when the DS has no such array
    ds.array("step_u")          # numpy array in its shape
    read_ds(path, arrays=["converged", "failure", "time_march"])  # only these values (those
                                                                  # the DS lacks are left out)

Float64 values read back as the same doubles (sig-dump prints the shortest round-trip form);
non-finite values come back as nan (JSON has no NaN: sig-dump writes null).
"""
import json
import math
import os
import shutil
import subprocess
from pathlib import Path

from .errors import ReportError

ROOT = Path(__file__).resolve().parents[2]


def sig_dump_path():
    """The sig-dump executable: $SIG_BIN/sig-dump (the drivers and ctest set SIG_BIN), else the
    repository's build/bin/sig-dump, else sig-dump on PATH."""
    candidates = []
    if os.environ.get("SIG_BIN"):
        candidates.append(Path(os.environ["SIG_BIN"]) / "sig-dump")
    candidates.append(ROOT / "build" / "bin" / "sig-dump")
    for path in candidates:
        if path.is_file() and os.access(path, os.X_OK):
            return path
    found = shutil.which("sig-dump")
    if found:
        return Path(found)
    raise ReportError(f"no sig-dump executable (looked in {', '.join(map(str, candidates))} and "
                      f"PATH): build first, or set SIG_BIN")


def sig_dump_json(path, values=None):
    """The parsed output of `sig-dump --json [--values[=NAMES]] path`. `values`: None (shapes
    only), True (every array's values) or a list of array names (each must exist)."""
    command = [str(sig_dump_path()), "--json"]
    if values is True:
        command.append("--values")
    elif values:
        command.append("--values=" + ",".join(values))
    done = subprocess.run(command + [str(path)], capture_output=True, text=True)
    if done.returncode != 0:
        message = (done.stderr or done.stdout).strip() or f"exit code {done.returncode}"
        raise ReportError(f"{path}: sig-dump cannot read it: {message}")
    try:
        return json.loads(done.stdout)
    except json.JSONDecodeError as e:
        raise ReportError(f"{path}: sig-dump printed no JSON ({e})") from None


class Ds:
    """The arrays of one DS file. Attributes: path, kind, title, creator, date; `names` (every
    array, in file order); per array its type ("int64", "float64", "text"), shape and, when read,
    its values."""

    def __init__(self, path, dump):
        self.path = Path(path)
        self.kind = dump.get("kind", "")
        self.title = dump.get("title", "")
        self.creator = dump.get("creator", "")
        self.date = dump.get("date", "")
        self.names = []
        self.types, self.shapes, self.values = {}, {}, {}
        for entry in dump.get("arrays", []):
            name = entry["name"]
            self.names.append(name)
            self.types[name] = entry["type"]
            self.shapes[name] = list(entry["shape"])
            if "values" in entry:
                self.values[name] = _convert(entry["type"], entry["values"])

    def __contains__(self, name):
        return name in self.values

    def __getitem__(self, name):
        """The values of an array: a list (flat, row-major) or, for a text array, a str."""
        try:
            return self.values[name]
        except KeyError:
            what = "has no array" if name not in self.types else "was read without the values of"
            raise ReportError(f"{self.path}: the {self.kind} DS {what} '{name}'") from None

    def get(self, name, default=None):
        return self.values.get(name, default)

    def scalar(self, name):
        """The first value of a numeric array (an int for int64 arrays)."""
        values = self[name]
        if isinstance(values, str) or not values:
            raise ReportError(f"{self.path}: array '{name}' holds no number")
        return values[0]

    def shape(self, name):
        if name not in self.shapes:
            raise ReportError(f"{self.path}: the {self.kind} DS has no array '{name}'")
        return self.shapes[name]

    def array(self, name):
        """The values as a numpy array in the array's shape."""
        import numpy as np
        return np.array(self[name]).reshape(self.shape(name))


def _convert(kind, values):
    if kind == "text":
        return values
    if kind == "int64":
        return [int(v) for v in values]
    return [math.nan if v is None else float(v) for v in values]


def read_ds(path, arrays=None):
    """Read a DS file through sig-dump. `arrays`: None for the values of every array, or the
    names wanted (names the file does not hold are left out: ask `name in ds`). Raises
    ReportError naming the file when sig-dump refuses it (missing, truncated, corrupted)."""
    path = Path(path)
    if arrays is None:
        return Ds(path, sig_dump_json(path, values=True))
    listing = sig_dump_json(path)
    held = {entry["name"] for entry in listing.get("arrays", [])}
    wanted = [name for name in arrays if name in held]
    return Ds(path, sig_dump_json(path, values=wanted) if wanted else listing)
