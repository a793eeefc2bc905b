"""The thesis's numbers: ONE file, postproc/thesis_values.csv (a copy of
../shared/reference/thesis_values.csv), ONE schema:

    scene,item,key,value,unit,where
    7a,iterations_projection,N=128;c=1,11,,Table 7.1
    7b,iterations_pdas,N=128;gamma=10/1e2/1e3,12/12/12,,Table 7.5

Lines starting with '#' are comments. `key` says which case of `item` (empty when there is one);
`where` is the table, figure or page of the thesis. A row whose key ends in `=a/b/c` and whose
value is as many `/`-separated parts stands also for one entry per part (`N=128;gamma=1e2` -> 12),
so tables can be transcribed as the thesis prints them.

    thesis = load_thesis()                      # postproc/thesis_values.csv
    thesis.get("7a", "iterations_alm", "N=128") # "7" (text as printed: may be "Nv"); None: absent
    thesis.number("7a", "hertz_p0")             # 14.49 (None if absent or not a number)
    thesis.require("7a", "hertz_p0")            # "14.49", or ReportError naming the file and key
    thesis.row("8a", "penetration_error", "specific penalty")  # ThesisValue(.., "m", "p.229")
    t7a = thesis.scene("7a"); t7a.get("iterations_alm", "N=128")  # the same, one scene
"""
import csv
import re
from pathlib import Path
from typing import NamedTuple

from .errors import ReportError

THESIS_CSV = Path(__file__).resolve().parent.parent / "thesis_values.csv"
COLUMNS = ("scene", "item", "key", "value", "unit", "where")
_LIST_KEY = re.compile(r"^(.*=)([^;= /]+(?:/[^;= /]+)+)$")


class ThesisValue(NamedTuple):
    scene: str
    item: str
    key: str
    value: str
    unit: str
    where: str


def _number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


class ThesisValues:
    """The rows of a thesis-values file, looked up by (scene, item, key)."""

    def __init__(self, rows, path=None):
        self.path = path
        self._rows = list(rows)
        self._index = {}
        for row in self._rows:
            self._index.setdefault((row.scene, row.item, row.key), row)
        for row in self._rows:  # list rows: one entry per part, unless a row says otherwise
            m = _LIST_KEY.match(row.key)
            parts = row.value.split("/")
            if m and len(m.group(2).split("/")) == len(parts):
                for k, v in zip(m.group(2).split("/"), parts):
                    self._index.setdefault((row.scene, row.item, m.group(1) + k),
                                           row._replace(key=m.group(1) + k, value=v))

    @classmethod
    def load(cls, path=THESIS_CSV):
        """Read and check a thesis-values file (six columns, the schema above)."""
        path = Path(path)
        try:
            text = path.read_text()
        except OSError as e:
            raise ReportError(f"{path}: cannot read the thesis values ({e.strerror})") from None
        rows = []
        for number, line in enumerate(text.splitlines(), 1):
            if not line.strip() or line.startswith("#"):
                continue
            fields = next(csv.reader([line]))
            if len(fields) != len(COLUMNS):
                raise ReportError(f"{path}:{number}: {len(fields)} columns, the schema has "
                                  f"{len(COLUMNS)} ({','.join(COLUMNS)})")
            rows.append(ThesisValue(*(f.strip() for f in fields)))
        if not rows:
            raise ReportError(f"{path}: no thesis values")
        return cls(rows, path)

    def rows(self, scene=None, item=None):
        """The rows as written (list rows not expanded), filtered by scene and item."""
        return [r for r in self._rows if (scene is None or r.scene == scene)
                and (item is None or r.item == item)]

    def row(self, scene, item, key=""):
        return self._index.get((scene, item, key))

    def get(self, scene, item, key="", default=None):
        row = self.row(scene, item, key)
        return default if row is None else row.value

    def number(self, scene, item, key="", default=None):
        value = _number(self.get(scene, item, key))
        return default if value is None else value

    def require(self, scene, item, key=""):
        row = self.row(scene, item, key)
        if row is None:
            raise ReportError(f"{self.path}: no thesis value scene={scene} item={item} key={key}")
        return row.value

    def keys(self, scene, item):
        """Every key of (scene, item), list parts included, in file order."""
        return [k for (s, i, k) in self._index if s == scene and i == item]

    def scene(self, scene):
        return SceneValues(self, scene)


class SceneValues:
    """The values of one scene: get(item, key), number, require, row, keys, rows."""

    def __init__(self, values, scene):
        self.values, self.name = values, scene

    @property
    def path(self):
        return self.values.path

    def row(self, item, key=""):
        return self.values.row(self.name, item, key)

    def get(self, item, key="", default=None):
        return self.values.get(self.name, item, key, default)

    def number(self, item, key="", default=None):
        return self.values.number(self.name, item, key, default)

    def require(self, item, key=""):
        return self.values.require(self.name, item, key)

    def keys(self, item):
        return self.values.keys(self.name, item)

    def rows(self, item=None):
        return self.values.rows(self.name, item)


_cache = {}


def load_thesis(path=THESIS_CSV):
    """ThesisValues.load(path), read once per process."""
    key = str(Path(path).resolve())
    if key not in _cache:
        _cache[key] = ThesisValues.load(path)
    return _cache[key]
