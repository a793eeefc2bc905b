#!/usr/bin/env bash
# Pipeline test (issue 17): drivers/scenes.sh (what drivers/run.sh --all runs) on canned scene
# drivers (tests/pipeline/data/fake_scene.py, no solve: seconds), then the index:
#  - every driver runs, with "[k/n]" progress lines, and the script exits 1 since some fail;
#  - out/index.md and out/index.html exist and link every report that exists;
#  - a scene whose checks all pass is a PASS; one failed check, a driver that crashed, a driver
#    that wrote no scene.json, a scene.json pointing at a missing chart: each a FAIL with its
#    reason, none skipped; a scene.json of a scene run on its own is picked up too;
#  - the key tables, charts (relative <img>) and .pvd links are on the page, HTML-escaped;
#  - a scene with notes (datafiles/<scene>/README.md) links them, by a path that leads from
#    OUTDIR to the source tree;
#  - --tee NAME (drivers/run.sh's default scene) shows the driver's output on the terminal as
#    well as in its log, and the index lists that scene.
# The page in a real browser: index_browser.sh.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"

mkdir -p "$work/drivers"
declare -A kinds=([scene1]=pass [scene2]=fail [scene3]=crash [scene4]=silent [scene5]=broken
  [friction_hertz]=pass)
for name in "${!kinds[@]}"; do
  printf '#!/usr/bin/env bash\nexec %q %q %q %q "$@"\n' "$python" \
    "$root/tests/pipeline/data/fake_scene.py" "${kinds[$name]}" "$name" >"$work/drivers/$name.sh"
done
echo "not a scene driver" >"$work/drivers/bench-x.sh"
out=$work/out
mkdir -p "$out/lonely"
"$python" "$root/tests/pipeline/data/fake_scene.py" pass lonely -o "$out/lonely" >/dev/null

status=0
SIG_SCENE_DRIVERS=$work/drivers bash "$root/drivers/scenes.sh" -o "$out" >"$work/log" 2>&1 ||
  status=$?
cat "$work/log"
[ "$status" -eq 1 ] || die "scenes.sh exited $status, not 1 (some scenes fail)"
for k in 1 2 3 4 5 6; do
  grep -qE "^\[$k/6\] " "$work/log" || die "no progress line [$k/6]"
done
grep -q "bench-x" "$work/log" && die "scenes.sh ran bench-x.sh, which is no scene driver"
[ -s "$out/index.md" ] && [ -s "$out/index.html" ] || die "no index.md / index.html"

"$python" - "$out" "$root" <<'PY'
import re, sys
from pathlib import Path

from pipeline_checks import check, finish
out, root = Path(sys.argv[1]), Path(sys.argv[2])
md, page = (out / "index.md").read_text(), (out / "index.html").read_text()
reports = sorted(str(p.relative_to(out)) for p in out.glob("*/report.md"))
check(len(reports) == 6, f"6 reports written: {reports}")
for report in reports:
    check(f"]({report})" in md, f"index.md links {report}")
    check(f'href="{report}"' in page, f"index.html links {report}")
rows = {m.group(1): m.group(2) for m in re.finditer(r"^\| (\S+) \| [^|]* \| ([^|]*) \|", md, re.M)}
expect = {"scene1": "PASS", "scene2": "FAIL", "scene3": "FAIL", "scene4": "FAIL",
          "scene5": "FAIL", "friction_hertz": "PASS", "lonely": "PASS"}
for name, verdict in expect.items():
    check(rows.get(name, "").startswith(verdict), f"{name}: {verdict} in the table ({rows.get(name)})")
check("driver exited 1 (log: scene3.log)" in rows.get("scene3", ""), "scene3: the driver's exit")
check("no scene4/scene.json" in rows.get("scene4", ""), "scene4: no scene.json said")
check("missing scene5/no_such_chart.png" in rows.get("scene5", ""), "scene5: the missing chart")
check("1 FAIL" in rows.get("scene2", ""), "scene2: its failed check counted")
check("3 of 7 scenes pass" in md, "the summary counts 3 of 7")
check('<img src="scene1/speed_accuracy.png"' in page and '<img src="scene1/stability.png"' in page,
      "charts as relative images")
check('href="scene1/N8/run/case.pvd"' in page, ".pvd linked")
check("Table 7.1: ours (thesis)" in page and "<td>12 (11)</td>" in page, "the key table")
check("Fake scene scene1 &lt;&amp;&gt;" in page and "<&>" not in page.split("<body>")[1]
      .replace("&lt;&amp;&gt;", ""), "titles escaped")
notes = "datafiles/friction/README.md"
check(f"Notes: [{notes}](" in md and f">{notes}</a>" in page, "friction_hertz's notes linked")
link = re.search(r'href="([^"]*friction/README\.md)"', page)
check(link is not None and (out / link.group(1)).resolve() == root / notes,
      f"the notes' link leads from OUTDIR to the source tree ({link and link.group(1)})")
check("datafiles/scene1/" not in page, "no notes link for a scene without notes")
check("no_such_chart.png is missing" in page and '<img src="scene5/no_such_chart.png"' not in page,
      "no <img> for a missing chart")
finish("scene_index")
PY
# --tee: drivers/run.sh's way of running its one scene.
tee_out=$work/tee
SIG_SCENE_DRIVERS=$work/drivers bash "$root/drivers/scenes.sh" --tee -o "$tee_out" scene1 \
  >"$work/tee.log" 2>&1 || die "scenes.sh --tee scene1 failed: $(cat "$work/tee.log")"
grep -q "^fake scene1: pass" "$work/tee.log" || die "--tee: the driver's output not on the terminal"
grep -q "^fake scene1: pass" "$tee_out/scene1.log" || die "--tee: the driver's output not in its log"
grep -q "scene1/report.md" "$tee_out/index.html" || die "--tee: the index does not list scene1"
grep -q "scene2" "$tee_out/index.html" && die "--tee scene1: the index lists scene2, not run"
echo "scene_index: ok"
