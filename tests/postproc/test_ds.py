"""sigreport.ds: DS files read through sig-dump --json --values only."""
import math
import shutil
import subprocess

import pytest
from conftest import DATA

from sigreport import Ds, ReportError, read_ds


@pytest.fixture
def contact_case(tmp_path, bin_dir):
    """case.cont of the canned N = 16 half disc, written by sig-mesh, sig-material, sig-contact."""
    deck = tmp_path / "hertz.dat"
    shutil.copy(DATA / "scene/N16/pdas_1e2/hertz.dat", deck)
    for stage in ("mesh", "material", "contact"):
        subprocess.run([bin_dir / f"sig-{stage}", deck, "-o", tmp_path], check=True,
                       capture_output=True)
    return tmp_path / "case.cont"


def test_values_types_and_shapes(contact_case):
    ds = read_ds(contact_case)
    assert ds.kind == "CONT" and ds.creator == "sig-contact"
    weights = ds["weight"]
    assert ds.types["weight"] == "float64" and all(isinstance(w, float) for w in weights)
    assert ds.shape("weight") == [len(weights)] == [17]
    # The tributary lengths of the 17 nodes of Gamma3 add up to the half circle, pi R (8 chords).
    chord = 2 * 8 * math.sin(math.pi / 16 / 2)
    assert sum(weights) == pytest.approx(16 * chord, rel=1e-12)
    ints = [n for n in ds.names if ds.types[n] == "int64"]
    assert ints and all(isinstance(v, int) for n in ints for v in ds[n])
    assert ds.array("weight").shape == (17,)


def test_selected_arrays_and_missing_ones(contact_case):
    ds = read_ds(contact_case, arrays=["weight", "no_such_array"])
    assert "weight" in ds and "no_such_array" not in ds
    assert len(ds.names) > 1  # every array is listed, only the asked ones carry values
    other = next(n for n in ds.names if n != "weight")
    with pytest.raises(ReportError, match=f"was read without the values of '{other}'"):
        ds[other]
    with pytest.raises(ReportError, match="has no array 'no_such_array'"):
        ds["no_such_array"]
    assert ds.get("no_such_array", "x") == "x"


def test_truncated_or_missing_file_is_refused_with_its_name(contact_case, tmp_path):
    cut = tmp_path / "cut.cont"
    cut.write_bytes(contact_case.read_bytes()[:-10])
    with pytest.raises(ReportError, match=r"cut.cont: sig-dump cannot read it"):
        read_ds(cut)
    with pytest.raises(ReportError, match=r"absent.b: sig-dump cannot read it"):
        read_ds(tmp_path / "absent.b")


def test_json_null_is_nan_and_text_stays_text():
    ds = Ds("x.b", {"kind": "B", "arrays": [
        {"name": "r", "type": "float64", "shape": [3], "values": [1, None, 2.5]},
        {"name": "n", "type": "int64", "shape": [1], "values": [7]},
        {"name": "failure", "type": "text", "shape": [4], "values": "none"}]})
    assert ds["r"][0] == 1.0 and isinstance(ds["r"][0], float) and math.isnan(ds["r"][1])
    assert ds.scalar("n") == 7 and ds["failure"] == "none"
    with pytest.raises(ReportError, match="holds no number"):
        ds.scalar("failure")
