#!/usr/bin/env bash
# Refactor guard: re-runs the project's reference outputs with a build and diffs them against the golden copies in
# validation/golden/ (made by the same machine kind and compiler). A refactor must leave every one bit-identical;
# a physics change updates them (--update) and reports old and new figures side by side in its commit.
#
#   scripts/check_identical.sh [--update] [--skip-aosta] [build-dir]
#
# Compared (run-time columns removed: wall_s, time_s, time_*_us):
#   compare_{hertz,conformal}_steps.csv  `conforma compare` on scenarios/default_metro.yaml, 7 steps (scripts/run.sh)
#   aosta_conformal_steps.csv            `conforma wear` on scenarios/aosta_aln501.yaml, conformal (~4 min)
#   mbench.txt                           `conforma mbench` (Manchester A-2.2 against CONTACT, 4 models)
#   bench_errors.csv                     `conforma bench` error columns (err_*, alpha_c_deg, status, reference_status)
#   bench_reference.csv                  `conforma bench` exact reference per case (forces, iterations; time_s removed)
#   final_profiles.sha256                the last wheel profile of every wear run, byte for byte
# Exit 0: all identical; 1: a difference (printed); 2: a run failed.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
update=0
aosta=1
build="$here/build"
for a in "$@"; do
  case "$a" in
    --update) update=1 ;;
    --skip-aosta) aosta=0 ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) build="$a" ;;
  esac
done
exe="$build/conforma"
[ -x "$exe" ] || { echo "check_identical: no executable $exe (build first: scripts/setup.sh)" >&2; exit 2; }
golden="$here/validation/golden"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
out="$work/new"
mkdir -p "$out"
cd "$here"

# drop the named columns (header names) from a CSV
drop_columns() {  # file columns...
  local file="$1"; shift
  python3 - "$file" "$@" <<'EOF'
import csv, sys
path, drop = sys.argv[1], set(sys.argv[2:])
rows = list(csv.reader(open(path, newline="")))
keep = [i for i, name in enumerate(rows[0]) if name not in drop and not (name.startswith("time_") and name.endswith("_us"))]
w = csv.writer(sys.stdout, lineterminator="\n")
for r in rows:
    w.writerow([r[i] for i in keep])
EOF
}

run() {  # name, command...
  local name="$1"; shift
  echo "check_identical: $name"
  # --allow-partial: the guard compares outputs (failed contacts are columns of steps.csv), not completeness;
  # --quiet: no progress lines on stderr in the log (mbench.txt is the log)
  local exe_="$1"; shift
  if ! "$exe_" --allow-partial --quiet "$@" > "$work/$name.log" 2>&1; then
    echo "check_identical: '$*' failed:" >&2
    tail -20 "$work/$name.log" >&2
    exit 2
  fi
}

run compare "$exe" compare --scenario scenarios/default_metro.yaml --out "$work/compare" --steps 7 --models hertz,conformal
for m in hertz conformal; do
  drop_columns "$work/compare/$m/steps.csv" wall_s > "$out/compare_${m}_steps.csv"
  (cd "$work/compare/$m" && sha256sum "$(ls wheel_step_*.csv | tail -1)" | sed "s|  |  compare/$m/|") >> "$out/final_profiles.sha256"
done
if ((aosta)); then
  run aosta "$exe" wear --scenario scenarios/aosta_aln501.yaml --model conformal --out "$work/aosta"
  drop_columns "$work/aosta/steps.csv" wall_s > "$out/aosta_conformal_steps.csv"
  (cd "$work/aosta" && sha256sum "$(ls wheel_step_*.csv | tail -1)" | sed "s|  |  aosta/|") >> "$out/final_profiles.sha256"
fi
run mbench "$exe" mbench
cp "$work/mbench.log" "$out/mbench.txt"
run bench "$exe" bench --out "$work/bench"
drop_columns "$work/bench/bench.csv" time_us > "$out/bench_errors.csv"
drop_columns "$work/bench/bench_reference.csv" time_s > "$out/bench_reference.csv"

if ((update)); then
  mkdir -p "$golden"
  if ((!aosta)); then  # keep the stored Aosta figures and hash line
    grep "aosta/" "$golden/final_profiles.sha256" >> "$out/final_profiles.sha256" 2>/dev/null || true
    cp "$golden/aosta_conformal_steps.csv" "$out/" 2>/dev/null || true
  fi
  cp "$out"/* "$golden/"
  echo "check_identical: golden outputs updated in validation/golden/"
  exit 0
fi

status=0
for f in "$golden"/*; do
  name="$(basename "$f")"
  [ "$name" = README.md ] && continue
  if [ "$name" = final_profiles.sha256 ] && ((!aosta)); then
    grep -v "aosta/" "$f" > "$work/golden_hashes"; f="$work/golden_hashes"
  fi
  [ "$name" = aosta_conformal_steps.csv ] && ((!aosta)) && continue
  if [ ! -f "$out/$name" ]; then echo "MISSING $name"; status=1; continue; fi
  if diff -u "$f" "$out/$name" > "$work/diff"; then
    echo "identical  $name"
  else
    echo "DIFFERENT  $name"; head -40 "$work/diff"; status=1
  fi
done
exit $status
