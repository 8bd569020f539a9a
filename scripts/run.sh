#!/usr/bin/env bash
# Sets up (installs what is missing, builds) and runs Conforma's main job on its default scenario: the wear of the
# default metro case (scenarios/default_metro.yaml) with the hertz and the conformal model side by side, 7 wheel
# steps each (about 4 minutes on 2 cores: hertz ~13 s, conformal ~3.8 min since issue 15), report in
# out/compare/report.md with plots.
# Extra arguments replace the default job, e.g.: scripts/run.sh contact --wheel S1002 --rail 60E1 --y-mm 3 --json
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$here/build"
"$here/scripts/setup.sh" "$build" >/dev/null
if (($#)); then exec "$build/conforma" "$@"; fi
cd "$here"
exec "$build/conforma" compare --scenario scenarios/default_metro.yaml --out out/compare --steps 7 --models hertz,conformal
