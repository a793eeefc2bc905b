#!/usr/bin/env bash
# Pipeline test (issue 17): the scene index opens in a real browser. postproc/scene_index.py on a
# canned tree of scenes (tests/pipeline/data/fake_scene.py: charts, reports, .pvd, one failing
# scene), then headless Chromium (tests/pipeline/headless_check.py, the DevTools protocol) loads
# out/index.html: no console error, no failed load, every image decoded. Then a page with a broken
# image and a console error must be caught (the check can fail). Exit 77 (skipped) only when
# Chromium is absent (Debian: chromium, which drivers/setup.sh installs).
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
chromium=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chromium" ] || skip "no chromium"

out=$work/out
for kind in pass fail; do
  "$python" "$root/tests/pipeline/data/fake_scene.py" "$kind" "scene_$kind" -o "$out/scene_$kind" \
    >/dev/null
done
"$python" "$root/postproc/scene_index.py" "$out" || true # scene_fail fails: exit 1
"$python" "$root/tests/pipeline/headless_check.py" --chromium "$chromium" "$out/index.html" ||
  die "the index does not load cleanly in $chromium"
[ "$(grep -o "<img " "$out/index.html" | wc -l)" -eq 4 ] || die "expected 4 images in the index"

# The check itself: a missing image and a console error are reported.
cp "$out/scene_pass/speed_accuracy.png" "$work/ok.png"
cat >"$work/bad.html" <<'HTML'
<!DOCTYPE html><html><head><meta charset="utf-8"><title>bad</title></head>
<body><img src="ok.png"><img src="missing.png"><script>console.error("boom")</script></body></html>
HTML
status=0
"$python" "$root/tests/pipeline/headless_check.py" --chromium "$chromium" "$work/bad.html" \
  >"$work/bad.log" 2>&1 || status=$?
cat "$work/bad.log"
[ "$status" -eq 1 ] || die "headless_check.py exited $status on a broken page, not 1"
grep -q "image does not resolve: missing.png" "$work/bad.log" || die "missing image not caught"
grep -q "console.error: boom" "$work/bad.log" || die "console error not caught"
grep -q "image does not resolve: ok.png" "$work/bad.log" && die "a good image reported"
echo "index_browser: ok"
