"""pytest set-up for the report library's tests (tests/postproc/): postproc/ on sys.path, the
canned result tree and the stage executables (SIG_BIN, set by ctest; else build/bin)."""
import os
import shutil
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(__file__).resolve().parent / "data"
sys.path.insert(0, str(ROOT / "postproc"))


@pytest.fixture
def scene(tmp_path):
    """A copy of the canned scene tree (two runs of a small Hertz half disc, N = 16: pdas
    converged, projection c = 1 stopped as Nv after 3 iterations)."""
    out = tmp_path / "scene"
    shutil.copytree(DATA / "scene", out)
    return out


@pytest.fixture
def bin_dir():
    """The stage executables: $SIG_BIN or build/bin (the tests need sig-mesh ... sig-dump)."""
    path = Path(os.environ.get("SIG_BIN", ROOT / "build" / "bin"))
    assert (path / "sig-dump").is_file(), f"no sig-dump in {path}: build first or set SIG_BIN"
    return path
