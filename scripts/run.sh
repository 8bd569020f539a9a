#!/usr/bin/env bash
# Sets up (installs what is missing, builds) and runs Conforma's main job on its default scenario: the wear of the
# default metro case (scenarios/default_metro.yaml) with the hertz and the conformal model side by side, 7 wheel
# steps each (about 30 s on 2 cores once built: hertz ~11 s, conformal ~12 s), report in out/compare/report.md with
# plots and paper 003's figures beside ours (docs/physics-reference.md §8.11).
# Extra arguments replace the default job, e.g.: scripts/run.sh contact --wheel S1002 --rail 60E1 --y-mm 3 --json
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$here/build"
"$here/scripts/setup.sh" "$build" >/dev/null
if (($#)); then exec "$build/conforma" "$@"; fi
cd "$here"
exec "$build/conforma" compare --scenario scenarios/default_metro.yaml --out out/compare --steps 7 --models hertz,conformal
