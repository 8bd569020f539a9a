"""One campaign case, as a worker runs it: the generated scenario into a private temporary folder, one `conforma`
process on it, the files to keep read back and returned (conforma.campaign).

Standard library only and no import of the rest of the package: Dask ships this module to its workers by value
(cloudpickle), so a worker needs the `conforma` executable but not the Python package. The worker writes nothing
into the campaign folder: the client alone writes a case's folder, once, from the returned result, which is why a
worker killed mid-case loses nothing and a case run twice (a rescheduled task) is recorded once.
"""
import fnmatch
import hashlib
import os
import shutil
import socket
import subprocess
import tempfile
import time

# timing columns of steps.csv: the only values that differ between two runs of the same case
TIMING_COLUMNS = ("wall_s",)


def _final_profiles(run_dir, names):
    """The wheel profile of the last row of each steps.csv and the last rails (files of wear_output.cpp)."""
    keep = []
    for steps in [n for n in names if os.path.basename(n) == "steps.csv"]:
        folder = os.path.dirname(steps)
        with open(os.path.join(run_dir, steps)) as f:
            rows = [line.split(",") for line in f.read().splitlines() if line]
        rail_step, step = (int(rows[-1][0]), int(rows[-1][1])) if len(rows) > 1 else (0, 0)
        tag = (f"r{rail_step:03d}_" if rail_step > 0 else "") + f"step_{step:03d}"
        keep += [os.path.join(folder, f"wheel_{tag}{ext}") for ext in (".prw", ".csv")]
        for side in ("left", "right"):
            rails = sorted(n for n in names if os.path.dirname(n) == folder
                           and fnmatch.fnmatch(os.path.basename(n), f"rail_{side}_[0-9][0-9][0-9].prr"))
            if rails:
                keep += [rails[-1], rails[-1][:-4] + ".csv"]
    return [k for k in keep if k in names]


def kept_files(run_dir, command, outputs):
    """Relative names (in run_dir) of the files a case keeps."""
    names = set()
    for root, _, files in os.walk(run_dir):
        for f in files:
            names.add(os.path.relpath(os.path.join(root, f), run_dir))
    always = {"steps.csv", "status.txt", "kinematics_fallbacks.csv"}
    per_command = {"wear": set(), "compare": {"report.md"},
                   "validate": {"validate.json", "validate.csv", "validate_profiles.csv", "report.md"}}[command]
    keep = {n for n in names if os.path.basename(n) in always or n in per_command}
    if outputs.get("final_profiles", True):
        keep |= set(_final_profiles(run_dir, names))
    for pattern in outputs.get("files", []):
        keep |= {n for n in names if fnmatch.fnmatch(n, pattern)}
    return sorted(keep)


def without_timing(name, data):
    """steps.csv without its timing columns (the rest of a file as it is): what the result digest covers."""
    if os.path.basename(name) != "steps.csv":
        return data
    lines = data.decode().splitlines()
    if not lines:
        return data
    header = lines[0].split(",")
    drop = {i for i, h in enumerate(header) if h in TIMING_COLUMNS}
    return "\n".join(",".join(v for i, v in enumerate(line.split(",")) if i not in drop) for line in lines).encode()


def result_digest(files):
    """SHA-256 over the kept files (names and contents, steps.csv without wall_s, report.md and validate.json left
    out as they print wall times): equal digests = the same results, bit for bit."""
    h = hashlib.sha256()
    for name in sorted(files):
        if os.path.basename(name) in ("report.md", "validate.json"):
            continue
        h.update(name.encode() + b"\0" + without_timing(name, files[name]) + b"\0")
    return h.hexdigest()


def _die_with_parent():
    """Linux: the conforma process is killed when the worker running it dies (prctl PR_SET_PDEATHSIG), so that a
    killed worker leaves no orphan computing a case that is rescheduled elsewhere; None elsewhere."""
    try:
        import ctypes
        import signal

        prctl = ctypes.CDLL(None, use_errno=True).prctl  # loaded here, before the fork
    except (OSError, AttributeError):
        return None
    return lambda: prctl(1, signal.SIGKILL)  # 1: PR_SET_PDEATHSIG


def run_case(task):
    """task: id, command, cli, scenario_yaml (text), models, steps, args, outputs, threads (OMP threads or None).
    Returns a dict: id, returncode, stdout, stderr, wall_s, host, files (relative name -> bytes), error (None or
    the text of a failure to start)."""
    out = {"id": task["id"], "returncode": None, "stdout": "", "stderr": "", "wall_s": 0.0,
           "host": socket.gethostname(), "files": {}, "error": None}
    cli = task["cli"]
    if not os.path.isfile(cli):
        cli = shutil.which("conforma") or cli
    with tempfile.TemporaryDirectory(prefix=f"conforma-case-{task['id']}-") as tmp:
        scenario = os.path.join(tmp, "scenario.yaml")
        with open(scenario, "w") as f:
            f.write(task["scenario_yaml"])
        run_dir = os.path.join(tmp, "run")
        argv = [cli, "--quiet", task["command"], "--scenario", scenario, "--out", run_dir]
        models = task["models"]
        if models:
            argv += ["--model", models[0]] if task["command"] == "wear" else ["--models", ",".join(models)]
        if task["steps"] is not None:
            argv += ["--steps", str(task["steps"])]
        if task["command"] != "wear":
            argv.append("--no-plot")
        argv += task["args"]
        env = dict(os.environ)
        if task.get("threads"):
            env["OMP_NUM_THREADS"] = str(task["threads"])
        start = time.monotonic()
        try:
            p = subprocess.run(argv, cwd=tmp, env=env, capture_output=True, text=True,
                               preexec_fn=_die_with_parent())
        except OSError as e:
            out["error"] = f"cannot run {cli}: {e.strerror}"
            return out
        out["wall_s"] = time.monotonic() - start
        out["returncode"], out["stdout"], out["stderr"] = p.returncode, p.stdout, p.stderr
        if os.path.isdir(run_dir):
            for name in kept_files(run_dir, task["command"], task["outputs"]):
                with open(os.path.join(run_dir, name), "rb") as f:
                    out["files"][name] = f.read()
    return out
