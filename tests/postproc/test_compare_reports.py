"""postproc/compare_reports.py: the numeric comparison of two runs that the issues ask for
(scene results unchanged by a change: integers exact, reals to 1e-9 relative)."""
import subprocess
import sys

from conftest import ROOT

TOOL = ROOT / "postproc" / "compare_reports.py"
REPORT = """# A scene

Iterations per method:

| N | pdas | gap |
|---|---|---|
| 64 | 7 | 0.125 |
| 128 | 8 | 1e-20 |

Solve times (s):

| N | pdas |
|---|---|
| 64 | 0.013 |
"""


def write_run(folder, report, csv_text):
    (folder / "N64").mkdir(parents=True)
    (folder / "report.md").write_text(report)
    (folder / "N64" / "contact.csv").write_text(csv_text)


def compare(old, new):
    done = subprocess.run([sys.executable, TOOL, old, new], capture_output=True, text=True)
    return done.returncode, done.stdout


def test_the_same_numbers_pass_and_timings_are_left_out(tmp_path):
    write_run(tmp_path / "a", REPORT, "node,u1\n1,0.5\n")
    # Another timing table, a round-off near zero in a column of 0.125, a column added by the change.
    write_run(tmp_path / "b", REPORT.replace("0.013", "0.027").replace("1e-20", "3e-21"),
              "node,u1,converged\n1,0.5,1\n")
    code, out = compare(tmp_path / "a", tmp_path / "b")
    assert code == 0, out
    assert "0 cells moved" in out


def test_a_count_or_a_real_that_moved_is_named(tmp_path):
    write_run(tmp_path / "a", REPORT, "node,u1\n1,0.5\n")
    write_run(tmp_path / "b", REPORT.replace("| 128 | 8 |", "| 128 | 9 |"),
              "node,u1\n1,0.50000001\n")
    code, out = compare(tmp_path / "a", tmp_path / "b")
    assert code == 1
    assert "column 'pdas': 8 -> 9" in out
    assert "column 'u1': 0.5 -> 0.50000001" in out


def test_a_dropped_column_or_table_is_reported(tmp_path):
    write_run(tmp_path / "a", REPORT, "node,u1\n1,0.5\n")
    write_run(tmp_path / "b", REPORT, "node\n1\n")
    code, out = compare(tmp_path / "a", tmp_path / "b")
    assert code == 1 and "column 'u1' dropped" in out
    write_run(tmp_path / "c", REPORT.split("Solve times")[0], "node,u1\n1,0.5\n")
    code, out = compare(tmp_path / "a", tmp_path / "c")
    assert code == 2


def test_a_norm_in_a_header_stays_one_column(tmp_path):
    # sigreport writes the pipes of a norm escaped; a time column after it must still be a time.
    from sigreport import markdown_table
    table = markdown_table(["h", "||u - u_h||_V", "march (s)"], [["1/2", "0.0177", "0.001"]])
    assert "\\|\\|u - u_h\\|\\|_V" in table
    write_run(tmp_path / "a", "Errors:\n\n" + table + "\n", "node,u1\n1,0.5\n")
    write_run(tmp_path / "b", "Errors:\n\n" + table.replace("0.001", "0.004") + "\n",
              "node,u1\n1,0.5\n")
    code, out = compare(tmp_path / "a", tmp_path / "b")
    assert code == 0, out
    write_run(tmp_path / "c", "Errors:\n\n" + table.replace("0.0177", "0.0178") + "\n",
              "node,u1\n1,0.5\n")
    code, out = compare(tmp_path / "a", tmp_path / "c")
    assert code == 1
    assert "column '||u - u_h||_V': 0.0177 -> 0.0178" in out
