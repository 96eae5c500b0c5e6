#!/usr/bin/env bash
# Quick start "run": install what is missing, build, then show the default scene (scripts/show.sh: the viewer
# with a display, a headless render without one). Arguments go to the viewer, e.g. scripts/run.sh --projector.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
exec scripts/show.sh "$@"
