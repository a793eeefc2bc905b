"""sigreport.deck: the datafile syntax as modules/core/src/datafile.cpp reads it, and deck variants
that keep the rest of the file as written and that the stages read as intended."""
import os
import re
import shutil
import subprocess
import sys

import pytest
from conftest import DATA, ROOT

from sigreport import Deck, ReportError


def test_reads_the_syntax_the_stages_read(tmp_path, bin_dir):
    deck_path = tmp_path / "deck.dat"
    shutil.copy(DATA / "deck_syntax.dat", deck_path)
    # The fixture is a deck the C++ reader accepts (else the expectations below would be moot).
    done = subprocess.run([bin_dir / "sig-mesh", deck_path, "-o", tmp_path], capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr
    deck = Deck.read(deck_path)
    assert deck.title == "A deck # with a hash and spaces"
    assert deck.card("MESH").line == 3
    assert deck.card("mesh").fields == {"generator": "half-disc", "r": "8", "n": "16",
                                        "grading": "0.1"}
    assert deck.number("MATERIAL", "E") == 150.0  # "E = 150": spaces around '='
    assert deck.numbers("TRACTION", "f") == [0.4, -2.0]  # "0.4, -2": the list goes on
    assert deck.value("OUTPUT", "name") == "two words # not a comment"
    assert [c.fields["ref"] for c in deck.cards("DIRICHLET")] == ["1", "4"]
    assert deck.value("SOLVER", "eps") == "1e-8"
    assert deck.value("SOLVER", "r") is None and deck.value("FRICTION", "mu", "x") == "x"
    assert deck.number("MESH", "missing", 7) == 7.0
    with pytest.raises(ReportError, match="no FRICTION mu="):
        deck.number("FRICTION", "mu")


@pytest.mark.parametrize("line, message", [
    ('MESH N=8 file="a b', r"deck.dat:2: unterminated quote"),
    ("MESH N 8", r"deck.dat:2: field 'N': missing '=' after the field name"),
    ("MESH N=", r"deck.dat:2: field 'N': missing value after '='"),
    ("MESH N=8 n=16", r"deck.dat:2: field 'n': field given twice"),
    ("MESH =8", r"deck.dat:2: expected name=value, got '=8'"),
])
def test_syntax_errors_name_file_line_and_field(tmp_path, line, message):
    path = tmp_path / "deck.dat"
    path.write_text(f"# comment\n{line}\n")
    with pytest.raises(ReportError, match=message):
        Deck.read(path)


def test_unedited_deck_is_written_back_byte_for_byte(tmp_path):
    for source in [DATA / "deck_syntax.dat"] + sorted((ROOT / "datafiles").glob("*/*.dat")):
        Deck.read(source).write(tmp_path / "copy.dat")
        assert (tmp_path / "copy.dat").read_bytes() == source.read_bytes(), source


def test_edits_keep_everything_else_as_written(tmp_path):
    deck = Deck.read(DATA / "deck_syntax.dat")
    original = deck.text().splitlines()
    deck.set("MESH", N=64, grading=0)
    deck.set("SOLVER", method="alm", r="1e2").drop("SOLVER", "gamma")
    deck.set("OUTPUT", name="a b")
    deck.remove_cards("DIRICHLET")
    deck.replace_card("CONTACT", "DIRICHLET ref=3 uy=0")
    deck.add_card("LOADSTEPS n=3")
    lines = deck.text().splitlines()
    assert lines[2] == "mesh  generator=half-disc R=8   N=64 grading=0   # lower-case keyword, extra spaces"
    assert "SOLVER method=alm eps=1e-8 r=1e2   # the comment stays with its card" in lines
    assert 'OUTPUT vtk=no name="a b"' in lines
    assert "DIRICHLET ref=3 uy=0" in lines and not any("ux=0" in x for x in lines)
    assert lines[-1] == "LOADSTEPS n=3"
    # Every line not edited is unchanged, comments included.
    untouched = [x for x in original if not re.match(r"(?i)\s*(mesh|solver|output|dirichlet|contact)\s", x)]
    assert all(x in lines for x in untouched)
    deck.write(tmp_path / "variant.dat")
    again = Deck.read(tmp_path / "variant.dat")
    assert again.value("MESH", "N") == "64" and again.value("SOLVER", "r") == "1e2"
    assert oct((tmp_path / "variant.dat").stat().st_mode & 0o777) == oct(0o666 & ~_umask())
    with pytest.raises(ReportError, match="no FRICTION card"):
        deck.set("FRICTION", mu=0.2)


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_command_line_writes_the_variant_the_stages_mesh(tmp_path, bin_dir):
    out = tmp_path / "hertz.dat"
    env = dict(os.environ, PYTHONPATH=str(ROOT / "postproc"))
    done = subprocess.run([sys.executable, "-m", "sigreport", "deck",
                           str(ROOT / "datafiles/scene7a/hertz.dat"), "-o", str(out),
                           "--set", "MESH.N=8", "--drop", "SOLVER.gamma", "--set",
                           "SOLVER.method=alm", "--set", "SOLVER.r=1e2", "--drop-card", "COMPARE"],
                          capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    deck = Deck.read(out)
    assert deck.value("SOLVER", "method") == "alm" and deck.value("SOLVER", "gamma") is None
    assert not deck.has("COMPARE")
    subprocess.run([bin_dir / "sig-mesh", out, "-o", tmp_path], check=True, capture_output=True)
    dump = subprocess.run([bin_dir / "sig-dump", tmp_path / "case.nopo"], capture_output=True,
                          text=True, check=True).stdout
    assert "3 (8 edges, 9 nodes)" in dump  # Gamma3 in N = 8 segments: the edit reached sig-mesh
    bad = subprocess.run([sys.executable, "-m", "sigreport", "deck", str(out), "-o", str(out),
                          "--set", "FRICTION.mu=1"], capture_output=True, text=True, env=env)
    assert bad.returncode == 1 and "no FRICTION card" in bad.stderr
