#!/usr/bin/env bash
# Builds Conforma with AddressSanitizer, UndefinedBehaviorSanitizer and float-cast-overflow (a double -> integer
# conversion out of range, which -fsanitize=undefined leaves out) and runs the test suite on that build. A finding
# aborts the program, so the test that reached it fails. About 20 min to build and 7 min to test on 2 cores, so
# it is not part of .ci/run; run it before a release or after touching memory handling.
# Usage: scripts/sanitize.sh [build-dir]   (default: build-sanitize; CONFORMA_SANITIZE overrides the list)
# Not covered: the Python module (its tests load it into an uninstrumented interpreter) and stress_long.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build-sanitize}"
sanitizers="${CONFORMA_SANITIZE:-address,undefined,float-cast-overflow}"
"$here/scripts/setup.sh" "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCONFORMA_SANITIZE=$sanitizers" \
  -DCONFORMA_BUILD_PYTHON=OFF -DCONFORMA_BUILD_BENCHMARKS=OFF
export ASAN_OPTIONS="detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1"
export LSAN_OPTIONS="suppressions=$here/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1"
cd "$build"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" --timeout 2400 -LE stress_long
