#!/usr/bin/env bash
# The cross-check against Mitsuba 3, from a fresh clone: sets up the pinned Mitsuba in a
# git-ignored virtual environment (validate/.venv), builds the renderer, tests the
# converter's conventions, then compares every scene and the XML files (validate/compare.py).
#
#   bash validate/run.sh --quick          # CI: small images, nine scenes, three XML files (~2 min)
#   bash validate/run.sh                  # full: every scene, into validate/results/
#   bash validate/run.sh my_scene.toml    # any scene file, with the full mode's settings
#   bash validate/run.sh scene.xml        # any Mitsuba XML file, read by both renderers
#   bash validate/run.sh --quick my.toml  # ... or the quick mode's
#   bash validate/run.sh --foreign        # the scenes from elsewhere (validate/foreign/) alone
#
# Needs python3 (3.11 or later, for tomllib) with venv and pip, and the Rust toolchain.
# Only Mitsuba's scalar_rgb variant is used here: it needs no LLVM (validate/bench.py does).
set -euo pipefail
cd "$(dirname "$0")/.."
VENV=validate/.venv
REQ=validate/requirements.txt
stamp=$(sha256sum "$REQ" | cut -c1-16)
if [[ ! -x $VENV/bin/python || "$(cat $VENV/.stamp 2>/dev/null)" != "$stamp" ]]; then
    echo "== setting up Mitsuba 3 in $VENV (pinned: $REQ)"
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install --quiet --disable-pip-version-check -r "$REQ"
    echo "$stamp" > "$VENV/.stamp"
fi
echo "== cargo build --release --bin raytrace"
cargo build --release --quiet --bin raytrace
echo "== the converter's conventions (validate/tests)"
"$VENV/bin/python" -m pytest -q -p no:cacheprovider validate/tests
echo "== the comparison"
exec "$VENV/bin/python" validate/compare.py "$@"
