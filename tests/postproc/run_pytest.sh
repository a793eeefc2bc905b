#!/usr/bin/env bash
# ctest cases postproc.sigreport and postproc.figures: the pytest suite of the report library
# (postproc/sigreport) on the canned result tree of tests/postproc/data, with the stages of
# $SIG_BIN; arguments (test files, --ignore=FILE) go to pytest, none runs the whole folder.
# Skipped (77) only when the Python lacks pytest (Debian: python3-pytest, which drivers/setup.sh
# installs).
set -euo pipefail
python=${PYTHON:-/usr/bin/python3}
"$python" -c 'import pytest' 2>/dev/null ||
  { echo "postproc.sigreport: skipped, $python has no pytest (Debian: python3-pytest)"; exit 77; }
[ $# -gt 0 ] || set -- "$(dirname "$0")"
PYTHONDONTWRITEBYTECODE=1 exec "$python" -m pytest -q -p no:cacheprovider "$@"
