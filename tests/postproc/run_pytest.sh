#!/usr/bin/env bash
# ctest case postproc.sigreport: the pytest suite of the report library (postproc/sigreport) on
# the canned result tree of tests/postproc/data, with the stages of $SIG_BIN. Skipped (77) only
# when the Python lacks pytest (Debian: python3-pytest, which drivers/setup.sh installs).
set -euo pipefail
python=${PYTHON:-/usr/bin/python3}
"$python" -c 'import pytest' 2>/dev/null ||
  { echo "postproc.sigreport: skipped, $python has no pytest (Debian: python3-pytest)"; exit 77; }
PYTHONDONTWRITEBYTECODE=1 exec "$python" -m pytest -q -p no:cacheprovider "$(dirname "$0")"
