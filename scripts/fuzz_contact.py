#!/usr/bin/python3
"""Fuzz run of the profile readers and of `conforma contact` (issue 13, "What it must show" item 2).

Generates random inputs -- mutated copies of real profile files (truncation at a random byte, byte flips,
NaN/inf/huge numbers, dropped/duplicated/swapped lines, mirrored, scaled units, noise) and random options (lateral
shift, yaw, load incl. negative/NaN/huge, friction, model, speed, profile-reading flags) -- runs
`conforma contact --json` on each with a per-run timeout and classifies the run:

  crash       killed by a signal, exit 3 (internal error) or timeout
  silent      exit 0 but an incomplete result in the JSON, by the rule of `conforma contact` and Python
              (src/app/contact_status.hpp, python/conforma/_status.py): a wheel not_converged, a wheel without
              contact under a positive prescribed load, a patch normal_status other than ok / hertz_regularised or a
              tangential_status other than ok / full_slip / no_creepage / not_solved (full_slip is a physical
              regime, counted apart; no_contact at load <= 0 is the answer to the question asked)
  nan         exit 0 and NaN/inf in the output (nlohmann's JSON writes NaN as null; both are searched)
  bad_json    exit 0 and stdout is no JSON
  other_exit  an exit code outside 0, 2 (input error), 4 (not converged), 5 (partial result)
  fine        everything else (exit 2/4/5 are correct answers to bad or hard input)

Prints the counts and writes each failing input (profile files, command line, stdout, stderr) to
OUT/<class>/<case>/ for reproduction. Debian python3, standard library and numpy only.

  scripts/fuzz_contact.py --cases 10000 --seed 1 --jobs 2 --out fuzz_out [--cli build/conforma]
"""
import argparse
import concurrent.futures as cf
import json
import math
import os
import random
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)

# Real profile files: (path relative to the repository or to the shared data folder, kind, extra flags needed)
WHEELS = [
    ("repo:profiles/S1002.prw", []),
    ("data:profiles/contact/testbank/profiles/MBench_S1002_v3.prw", []),
    ("data:profiles/contact/testbank/profiles/worn_high_mileage.prw", []),
    ("data:profiles/contact/testbank/profiles/Car7216_0001r.whl", []),
    ("data:profiles/contact/testbank/profiles/Car7358_0001r.whl", []),
    ("data:profiles/contact/testbank/profiles/whl_left_iter288.whl", []),
    ("data:profiles/en15302/RUIC519A.dat", ["--wheel-z-down"]),
    ("data:profiles/analytic/S1002_analytic_DLR.txt", []),
]
RAILS = [
    ("repo:profiles/60E1_1in40.prr", []),
    ("repo:profiles/54E1.prr", []),
    ("data:profiles/contact/testbank/profiles/MBench_UIC60_v3.prr", []),
    ("data:profiles/contact/testbank/profiles/site_b_hr.prr", []),
    ("data:profiles/contact/testbank/profiles/avg_HR.BAN", []),
    ("data:profiles/contact/testbank/profiles/rail_left_iter288.ban", []),
    ("data:profiles/en15302/SUIC519A.dat", []),
    ("data:profiles/analytic/60E1_UIC60_head_analytic.csv", []),
]
BUILT_IN_RAILS = ["60E1", "54E1", "50E6", "50E4", "UIC60"]
MODELS = ["hertz", "kp", "kpec", "conformal", "auto", "exact", "reference", "hertz", "kp"]
NORMAL_COMPLETE = {"ok", "hertz_regularised"}
TANGENTIAL_COMPLETE = {"ok", "full_slip", "no_creepage", "not_solved"}
NUMBER = re.compile(r"[-+]?(\d+\.\d*|\.\d+|\d+)([eE][-+]?\d+)?")


def resolve(spec, data_dir):
    where, rel = spec.split(":", 1)
    return os.path.join(REPO if where == "repo" else data_dir, rel)


def weird_number(rng):
    return rng.choice(["nan", "inf", "-inf", "1e308", "-1e308", "1e999", "0", "-0", "1e-320", "99999999999",
                       "-5e6", "3e-9", "NaN", "Infinity"])


def mutate_text(text, rng, nprng):
    """One random mutation of a profile file's text (bytes kept as latin-1)."""
    lines = text.split("\n")
    kind = rng.randrange(12)
    if kind == 0 and text:  # truncate at a random byte
        return text[:rng.randrange(len(text) + 1)], "truncate"
    if kind == 1 and text:  # flip bytes
        b = bytearray(text, "latin-1")
        for _ in range(rng.randint(1, 8)):
            b[rng.randrange(len(b))] = rng.randrange(256)
        return b.decode("latin-1"), "byte_flip"
    if kind == 2:  # a NaN / inf / huge number in place of a number
        idx = [i for i, l in enumerate(lines) if NUMBER.search(l)]
        if idx:
            i = rng.choice(idx)
            ms = list(NUMBER.finditer(lines[i]))
            m = rng.choice(ms)
            lines[i] = lines[i][:m.start()] + weird_number(rng) + lines[i][m.end():]
        return "\n".join(lines), "weird_number"
    if kind == 3 and lines:  # drop a run of lines
        a = rng.randrange(len(lines))
        del lines[a:a + rng.randint(1, 30)]
        return "\n".join(lines), "drop_lines"
    if kind == 4 and lines:  # duplicate a line
        a = rng.randrange(len(lines))
        lines.insert(a, lines[a])
        return "\n".join(lines), "duplicate_line"
    if kind == 5 and len(lines) > 1:  # swap two lines (near or far)
        a = rng.randrange(len(lines))
        b = min(len(lines) - 1, a + rng.randint(1, 3)) if rng.random() < 0.5 else rng.randrange(len(lines))
        lines[a], lines[b] = lines[b], lines[a]
        return "\n".join(lines), "swap_lines"
    # numeric transformations of the data lines (two numbers or more)
    def data_line_map(fn):
        out = []
        for l in lines:
            ms = list(NUMBER.finditer(l))
            if len(ms) >= 2 and not re.search(r"[A-DF-Za-df-z=]", l):
                vals = [float(m.group(0)) for m in ms[:2]]
                new = fn(vals)
                rest = l[ms[1].end():]
                sep = "," if "," in l[:ms[1].start()] else "  "
                out.append(f"{new[0]:.6f}{sep}{new[1]:.6f}{rest}")
            else:
                out.append(l)
        return "\n".join(out)
    if kind == 6:
        return data_line_map(lambda v: [-v[0], v[1]]), "mirror_y"
    if kind == 7:
        return data_line_map(lambda v: [v[0], -v[1]]), "mirror_z"
    if kind == 8:
        f = rng.choice([1e-3, 1e3, 25.4, 0.1])
        return data_line_map(lambda v: [v[0] * f, v[1] * f]), f"scale_{f}"
    if kind == 9:
        s = rng.choice([0.0005, 0.002, 0.01, 0.05, 0.2])
        return data_line_map(lambda v: [v[0], v[1] + float(nprng.normal(0, s))]), f"noise_{s}mm"
    if kind == 10:  # reverse the order of the data
        a = rng.randrange(len(lines)) if lines else 0
        lines[a:] = lines[a:][::-1]
        return "\n".join(lines), "reverse_tail"
    return text, "unmodified"


def random_option(rng, name, typical):
    """A typical value mostly, sometimes an absurd one."""
    r = rng.random()
    if r < 0.93:
        return f"{typical(rng):.6g}"
    if r < 0.97:
        return weird_number(rng)
    return f"{rng.uniform(-1e6, 1e6):.6g}"


def make_case(case, seed, data_dir, workdir):
    rng = random.Random(seed * 1_000_003 + case)
    nprng = np.random.default_rng(seed * 1_000_003 + case)
    args = ["contact", "--json"]
    files = []
    notes = []
    for side, pool, builtins in (("wheel", WHEELS, ["S1002"]), ("rail", RAILS, BUILT_IN_RAILS)):
        r = rng.random()
        if r < 0.25:
            args += [f"--{side}", rng.choice(builtins)]
            continue
        spec, flags = rng.choice(pool)
        src = resolve(spec, data_dir)
        with open(src, "r", encoding="latin-1") as f:
            text = f.read()
        what = "unmodified"
        if r < 0.9:
            text, what = mutate_text(text, rng, nprng)
            if rng.random() < 0.25:
                text, w2 = mutate_text(text, rng, nprng)
                what += "+" + w2
        name = f"{side}_{os.path.basename(src)}"
        path = os.path.join(workdir, name)
        with open(path, "w", encoding="latin-1", newline="") as f:
            f.write(text)
        files.append(path)
        notes.append(f"{side}: {spec} {what}")
        args += [f"--{side}", path] + flags
        if rng.random() < 0.1:
            args += [f"--{side}-smooth-mm", rng.choice(["0.01", "0.05", "0.2", "0", "-1", "nan", "5"])]
        if rng.random() < 0.05:
            args += [f"--{side}-mirror"]
        if rng.random() < 0.05:
            args += [f"--{side}-z-down"]
        if rng.random() < 0.03:
            args += [f"--{side}-units", rng.choice(["m", "mm"])]
    if rng.random() < 0.9:
        args += ["--y-mm", random_option(rng, "y", lambda g: g.uniform(-12, 12))]
    if rng.random() < 0.6:
        args += ["--yaw-mrad", random_option(rng, "yaw", lambda g: g.uniform(-15, 15))]
    if rng.random() < 0.8:
        args += ["--load-N", random_option(rng, "load", lambda g: g.choice([g.uniform(1e3, 2e5), -1.0, 0.0]))]
    if rng.random() < 0.6:
        args += ["--mu", random_option(rng, "mu", lambda g: g.uniform(0.05, 0.6))]
    if rng.random() < 0.8:
        args += ["--model", rng.choice(MODELS) if rng.random() < 0.97 else "bogus"]
    if rng.random() < 0.4:
        args += ["--speed", random_option(rng, "speed", lambda g: g.uniform(0.1, 80))]
    if rng.random() < 0.2:
        args += ["--r0-mm", random_option(rng, "r0", lambda g: g.uniform(300, 600))]
    if rng.random() < 0.15:
        args += ["--roll-mrad", random_option(rng, "roll", lambda g: g.uniform(-5, 5))]
    if rng.random() < 0.1:
        args += ["--side", rng.choice(["left", "right"])]
    if rng.random() < 0.1:
        args += ["--grid", str(rng.choice([5, 10, 30, 0, -3]))]
    return args, files, notes


def walk(x, path, statuses, nulls):
    if isinstance(x, dict):
        for k, v in x.items():
            if k.endswith("status") and isinstance(v, str):
                statuses.append((path + "." + k, v))
            walk(v, path + "." + k, statuses, nulls)
    elif isinstance(x, list):
        for i, v in enumerate(x):
            walk(v, f"{path}[{i}]", statuses, nulls)
    elif x is None:
        nulls.append(path)
    elif isinstance(x, float) and not math.isfinite(x):
        nulls.append(path)


def prescribed_load(args):
    """The --load-N of a contact command line (the command's default 10 kN when absent; NaN when unreadable)."""
    if "--load-N" not in args:
        return 10e3
    try:
        return float(args[args.index("--load-N") + 1])
    except (ValueError, IndexError):
        return float("nan")


def incomplete(doc, load):
    """The incomplete parts of a `contact --json` document (the rule of the module docstring)."""
    bad = []
    for i, w in enumerate(doc.get("wheels", [])):
        status = w.get("status")
        if status == "not_converged" or (status == "no_contact" and load > 0) or status not in ("ok", "no_contact",
                                                                                              "not_converged"):
            bad.append((f"wheels[{i}].status", status))
        for j, p in enumerate(w.get("patches", [])):
            if p.get("normal_status") not in NORMAL_COMPLETE:
                bad.append((f"wheels[{i}].patches[{j}].normal_status", p.get("normal_status")))
            if p.get("tangential_status") not in TANGENTIAL_COMPLETE:
                bad.append((f"wheels[{i}].patches[{j}].tangential_status", p.get("tangential_status")))
    return bad


def classify(rc, out, timed_out, load=10e3):
    if timed_out:
        return "crash", "timeout"
    if rc < 0 or rc == 3:
        return "crash", f"exit {rc}"
    if rc in (2, 4, 5):
        return "fine", f"exit {rc}"
    if rc != 0:
        return "other_exit", f"exit {rc}"
    try:
        doc = json.loads(out)
    except ValueError:
        return "bad_json", "stdout is no JSON"
    if re.search(r"\b(nan|inf|infinity)\b", out, re.IGNORECASE):
        return "nan", "NaN/inf in the output"
    statuses, nulls = [], []
    walk(doc, "", statuses, nulls)
    if nulls:
        return "nan", "null (NaN) at " + ", ".join(nulls[:3])
    bad = incomplete(doc, load)
    if bad:
        return "silent", "exit 0 with " + ", ".join(f"{p}={s}" for p, s in bad[:3])
    if any(s == "full_slip" for _, s in statuses):
        return "fine", "full_slip"
    return "fine", "exit 0"


def run_case(case, opts):
    workdir = tempfile.mkdtemp(prefix=f"fuzz_{case}_")
    try:
        args, files, notes = make_case(case, opts.seed, opts.data, workdir)
        cmd = [opts.cli] + args
        t0 = time.time()
        timed_out = False
        try:
            p = subprocess.run(cmd, capture_output=True, timeout=opts.timeout, env=opts.env)
            rc, out, err = p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")
        except subprocess.TimeoutExpired as e:
            timed_out, rc = True, -999
            out = (e.stdout or b"").decode("utf-8", "replace")
            err = (e.stderr or b"").decode("utf-8", "replace")
        cls, why = classify(rc, out, timed_out, prescribed_load(args))
        if cls != "fine":
            dest = os.path.join(opts.out, cls, f"case_{case:06d}")
            os.makedirs(dest, exist_ok=True)
            kept = []
            for f in files:
                shutil.copy(f, dest)
                kept.append(os.path.join(dest, os.path.basename(f)))
            replay = [opts.cli] + [kept[files.index(a)] if a in files else a for a in args]
            with open(os.path.join(dest, "cmd.sh"), "w") as f:
                f.write("#!/bin/sh\n# " + why + "\n# " + "; ".join(notes) + "\n" + shlex.join(replay) + "\n")
            with open(os.path.join(dest, "stdout.txt"), "w") as f:
                f.write(out)
            with open(os.path.join(dest, "stderr.txt"), "w") as f:
                f.write(err)
        return case, cls, why, time.time() - t0, err.strip().splitlines()[-1:] if err.strip() else []
    finally:
        shutil.rmtree(workdir, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out", default="fuzz_out")
    ap.add_argument("--cli", default=os.environ.get("CONFORMA_CLI", os.path.join(REPO, "build", "conforma")))
    ap.add_argument("--data", default=os.environ.get("CONFORMA_DATA_DIR",
                                                     os.path.join(os.path.dirname(REPO), "shared", "data")))
    ap.add_argument("--timeout", type=float, default=300.0,
                    help="seconds per run (the reference BEM takes up to ~80 s on a large patch)")
    ap.add_argument("--max-failures", type=int, default=0, help="exit 1 when more failing cases than this")
    opts = ap.parse_args()
    if not os.path.isfile(opts.cli):
        sys.exit(f"fuzz_contact: no executable at {opts.cli} (--cli)")
    if not os.path.isdir(opts.data):
        sys.exit(f"fuzz_contact: no shared data folder at {opts.data} (--data)")
    opts.out = os.path.abspath(opts.out)
    opts.cli = os.path.abspath(opts.cli)
    opts.env = dict(os.environ, OMP_NUM_THREADS="1")
    if os.path.isdir(opts.out):
        shutil.rmtree(opts.out)
    os.makedirs(opts.out)
    counts, reasons = {}, {}
    t0 = time.time()
    with cf.ThreadPoolExecutor(max_workers=max(1, opts.jobs)) as pool:
        futures = [pool.submit(run_case, k, opts) for k in range(opts.cases)]
        for n, fut in enumerate(cf.as_completed(futures), 1):
            case, cls, why, dt, err_tail = fut.result()
            counts[cls] = counts.get(cls, 0) + 1
            key = why
            if cls == "fine" and why == "exit 2" and err_tail:  # the kind of input error, without paths and numbers
                msg = re.sub(r"^.*?error: ", "", err_tail[0])
                msg = re.sub(r"(/[^ :']+)+", "FILE", msg)
                msg = re.sub(r"[-+]?\d[\d.eE+-]*", "N", msg)
                key = "exit 2: " + msg[:90]
            reasons.setdefault(cls, {}).setdefault(re.sub(r"\[\d+\]", "[]", key), 0)
            reasons[cls][re.sub(r"\[\d+\]", "[]", key)] += 1
            if n % 500 == 0:
                print(f"  {n}/{opts.cases} runs, {time.time() - t0:.0f} s", file=sys.stderr, flush=True)
    elapsed = time.time() - t0
    failing = sum(v for k, v in counts.items() if k != "fine")
    print(f"fuzz_contact: {opts.cases} runs (seed {opts.seed}, {opts.jobs} jobs) in {elapsed:.0f} s")
    for cls in ("crash", "silent", "nan", "bad_json", "other_exit", "fine"):
        print(f"  {cls:10s} {counts.get(cls, 0)}")
        for why, n in sorted(reasons.get(cls, {}).items(), key=lambda kv: -kv[1])[:25]:
            print(f"      {n:6d}  {why}")
    if failing:
        print(f"failing inputs written to {opts.out}/<class>/case_*/ (cmd.sh replays one)")
    with open(os.path.join(opts.out, "summary.json"), "w") as f:
        json.dump({"cases": opts.cases, "seed": opts.seed, "seconds": elapsed, "counts": counts, "reasons": reasons},
                  f, indent=1)
    sys.exit(1 if failing > opts.max_failures else 0)


if __name__ == "__main__":
    main()
