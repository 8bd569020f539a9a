#!/usr/bin/env bash
# Sets up (installs what is missing, builds) and runs Conforma's main job on its built-in default scenario.
# Extra arguments replace the default job, e.g.: scripts/run.sh contact --wheel S1002 --rail 60E1 --y-mm 3 --json
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$here/build"
"$here/scripts/setup.sh" "$build" >/dev/null
if (($#)); then exec "$build/conforma" "$@"; fi
exec "$build/conforma" sweep
