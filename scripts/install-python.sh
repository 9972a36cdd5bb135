#!/usr/bin/env bash
# Makes `import orogen` work for /usr/bin/python3 from any folder: builds the engine module
# (_orogen) if needed and writes orogen.pth into the user's site-packages, naming this
# repository's python/ folder and the build folder (docs/python.md). Re-run after moving the
# repository; remove the .pth file to undo. Usage: scripts/install-python.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$(pwd)"
build="${1:-build/release}"
[ -f "$build/build.ninja" ] || cmake --preset release
ninja -C "$build" _orogen
site="$(/usr/bin/python3 -m site --user-site)"
mkdir -p "$site"
printf '%s\n%s\n' "$repo/python" "$(cd "$build" && pwd)/python" > "$site/orogen.pth"
(cd / && /usr/bin/python3 -c "import orogen; print('import orogen: version', orogen.__version__, 'from', orogen.__file__)")
echo "wrote $site/orogen.pth"
