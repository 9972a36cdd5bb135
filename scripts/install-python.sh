#!/usr/bin/env bash
# Installs the Python package `orogen` (python/pyproject.toml) into Debian's python3, with the
# compiled engine _orogen inside it (built here if needed), so that `import orogen`,
# `python3 -m orogen.charts.wedge RUN` and the commands that run the package (`orogen charts`,
# `orogen report`, the statistics of `orogen ensemble`) work from any folder, and keep working
# after the source tree moves. Re-run after changing python/; a source tree's own package is
# used instead with PYTHONPATH=python (docs/python.md). Undo: pip uninstall orogen.
# Usage: scripts/install-python.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
[ -f "$build/build.ninja" ] || cmake --preset release -DPython3_EXECUTABLE=/usr/bin/python3
ninja -C "$build" _orogen
# pip builds from a copy: the engine goes into the package, and the source tree stays clean.
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
cp python/pyproject.toml "$stage/"
cp -r python/orogen "$stage/orogen"
find "$stage" -name __pycache__ -prune -exec rm -rf {} +
cp "$build"/python/_orogen*.so "$stage/orogen/"
rm -f "$(/usr/bin/python3 -m site --user-site)/orogen.pth"  # the path file of the set-up before the package
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo /usr/bin/python3 -m pip install --quiet --no-deps --no-build-isolation --no-index --break-system-packages \
  --root-user-action=ignore "$stage"
(cd / && /usr/bin/python3 -c "import orogen; print('import orogen: version', orogen.__version__, 'from', orogen.__file__)")
