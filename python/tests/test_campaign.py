"""Campaigns (conforma.campaign, issue 19): the same cases give the same results bit for bit serially and on a
Dask LocalCluster of 2 worker processes started here (loopback only); a worker killed mid-run loses no case and
duplicates none; a rerun of a finished campaign runs nothing; bad input fails before any case runs. A generated
scenario is the base scenario: the case that varies nothing gives the results of `conforma wear` on the base file.

Cases: the default scenario, Hertz, 1 wear step (~2-3 s each)."""
import csv
import os
import pathlib
import signal
import socket
import subprocess
import threading
import time

import pytest

import conforma
from conforma import _campaign_task

SOURCE = pathlib.Path(__file__).resolve().parents[2]
BASE = SOURCE / "scenarios" / "default_metro.yaml"


def write_campaign(folder, body, name="small"):
    path = pathlib.Path(folder) / f"{name}.yaml"
    path.write_text(f"name: {name}\nbase: {BASE}\nmodels: [hertz]\nsteps: 1\n" + body)
    return path


# 4 cases; the base scenario has friction 0.3 and smoothing_mm 7 (one case varies nothing)
GRID = "parameters:\n  friction: [0.3, 0.4]\n  update.smoothing_mm: {from: 5, to: 7, step: 2}\n"


def digests(summary):
    return {cid: r["digest"] for cid, r in summary["records"].items()}


def result_rows(folder):
    with open(pathlib.Path(folder) / "results.csv", newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="module")
def serial(tmp_path_factory, cli):
    folder = tmp_path_factory.mktemp("campaign")
    file = write_campaign(folder, GRID)
    summary = conforma.campaign(file, folder / "serial", scheduler="serial", cli=cli)
    return file, folder, summary


@pytest.fixture()
def local_cluster():
    import distributed  # Debian python3-distributed (scripts/setup.sh): missing is a failure, not a skip
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                       dashboard_address=None)
    client = distributed.Client(cluster)
    yield cluster, client
    client.close()
    cluster.close()


def test_serial_campaign_runs_every_case_once(serial):
    _, folder, s = serial
    assert (s["cases"], s["ran"], s["ok"], s["failed"]) == (4, 4, 4, 0)
    rows = result_rows(folder / "serial")
    assert sorted(r["case_id"] for r in rows) == sorted(s["records"])
    assert {(r["friction"], r["update.smoothing_mm"]) for r in rows} == {
        ("0.3", "5"), ("0.3", "7"), ("0.4", "5"), ("0.4", "7")}
    # the parameters act: more friction, more wear per km (another km to the 0.4 mm cap)
    km = {(r["friction"], r["update.smoothing_mm"]): float(r["km"]) for r in rows}
    assert km[("0.3", "7")] != km[("0.4", "7")]
    assert km[("0.3", "7")] != km[("0.3", "5")]
    for cid in s["records"]:
        case = folder / "serial" / "cases" / cid
        assert (case / "result.json").is_file() and (case / "output" / "steps.csv").is_file()
        assert (case / "output" / "wheel_step_001.prw").is_file()


def test_the_case_that_varies_nothing_is_the_base_scenario(serial, cli, tmp_path):
    _, folder, s = serial
    (cid,) = [c for c, r in s["records"].items() if r["params"] == {"friction": 0.3, "update.smoothing_mm": 7}]
    subprocess.run([cli, "--quiet", "wear", "--scenario", str(BASE), "--model", "hertz", "--steps", "1",
                    "--out", str(tmp_path / "direct")], check=True, capture_output=True)
    for name in ["steps.csv", "wheel_step_001.prw", "rail_left_000.prr"]:
        direct = (tmp_path / "direct" / name).read_bytes()
        kept = (folder / "serial" / "cases" / cid / "output" / name).read_bytes()
        assert _campaign_task.without_timing(name, kept) == _campaign_task.without_timing(name, direct), name


def test_dask_local_cluster_equals_serial_bit_for_bit_and_rerun_does_nothing(serial, cli, local_cluster):
    file, folder, s = serial
    cluster, _ = local_cluster
    out = folder / "dask"
    d = conforma.campaign(file, out, scheduler=cluster.scheduler_address, cli=cli)
    assert (d["ran"], d["ok"]) == (4, 4)
    assert digests(d) == digests(s)
    for cid in s["records"]:  # the kept files themselves, steps.csv without its wall times
        a, b = folder / "serial" / "cases" / cid / "output", out / "cases" / cid / "output"
        names = sorted(str(p.relative_to(a)) for p in a.rglob("*") if p.is_file())
        assert names == sorted(str(p.relative_to(b)) for p in b.rglob("*") if p.is_file())
        for n in names:
            assert _campaign_task.without_timing(n, (a / n).read_bytes()) == \
                _campaign_task.without_timing(n, (b / n).read_bytes()), (cid, n)
    lines = []
    again = conforma.campaign(file, out, scheduler="tcp://127.0.0.1:9", cli=cli, log=lines.append)
    assert (again["ran"], again["skipped"]) == (0, 4)  # nothing to run: the scheduler is not even contacted
    assert "nothing to run" in lines[-1]


def test_a_worker_killed_mid_run_loses_and_duplicates_no_case(serial, cli, local_cluster, tmp_path):
    file, _, s = serial
    cluster, client = local_cluster
    killed = {}

    def kill_a_busy_worker():
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and not killed:
            for worker, keys in client.processing().items():
                if any(str(k).startswith("conforma-case-") for k in keys):
                    time.sleep(0.5)  # the case's conforma process is running
                    pid = client.run(os.getpid, workers=[worker])[worker]
                    os.kill(pid, signal.SIGKILL)
                    killed.update(worker=worker, keys=[str(k) for k in keys])
                    return
            time.sleep(0.05)

    killer = threading.Thread(target=kill_a_busy_worker)
    killer.start()
    lines = []
    out = tmp_path / "killed"
    k = conforma.campaign(file, out, scheduler=cluster.scheduler_address, cli=cli, log=lines.append)
    killer.join()
    assert killed, "no worker was busy with a case"
    assert (k["ran"], k["ok"], k["failed"]) == (4, 4, 0)
    ids = [r["case_id"] for r in result_rows(out)]
    assert sorted(ids) == sorted(s["records"]) and len(set(ids)) == len(ids)
    assert sum(" case " in line and "/4]" in line for line in lines) == 4  # each case recorded once
    assert digests(k) == digests(s)
    assert sorted(p.name for p in (out / "cases").iterdir()) == sorted(s["records"])


def free_port():
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


@pytest.mark.parametrize("body, message", [
    ("parameters:\n  update.smothing_mm: [5, 7]\n", r"unknown key 'smothing_mm'"),
    ("parameters:\n  tracks.gauge_mm: [1435]\n", r"parameter 'tracks.gauge_mm': not a key of the scenario: no 'tracks'"),
    ("parameters:\n  track_classes.9.friction: [0.3]\n", r"track_classes is a list of 4 items, no item '9'"),
    ("parameters:\n  update.cap_mm: {from: 0.4, to: 0.2, step: 0.1}\n", r"empty range"),
    ("parameters:\n  friction: []\n", r"no values"),
    ("parameters:\n  friction: {random: uniform, low: 0.2, high: 0.4, count: 0, seed: 1}\n", r"no values"),
    ("parameters:\n  friction: [-0.1]\n", r"friction must be > 0"),
    # sizes that hung or ran out of memory before the first case (fuzzing, session 25)
    ("parameters:\n  friction: {random: uniform, low: 0.2, high: 0.4, count: 1000000000, seed: 1}\n",
     r"more than 100000 cases"),
    ("parameters:\n  friction: {from: 0.2, to: 0.4, step: 1.0e-15}\n", r"more than 100000 cases"),
    ("parameters:\n  friction: {from: 0.2, to: 0.4, count: 1000}\n  update.cap_mm: {from: 0.1, to: 0.4, count: 1000}\n",
     r"1000000 combinations"),
])
def test_bad_input_fails_before_any_case_runs(tmp_path, cli, body, message):
    file = write_campaign(tmp_path, body)
    with pytest.raises(conforma.CampaignError, match=message):
        conforma.campaign(file, tmp_path / "out", cli=cli)
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("models, message", [
    ("[hertz, conformall]", r"models: .*unknown contact model 'conformall'"),
    ("[exact]", r"models: .*'exact' solves the normal problem only"),
])
def test_an_unknown_model_fails_before_any_case_runs(tmp_path, cli, models, message):
    """The model names are checked once, as the wear command checks them, not case by case (session 26)."""
    file = write_campaign(tmp_path, GRID)
    file.write_text(file.read_text().replace("models: [hertz]", f"models: {models}"))
    with pytest.raises(conforma.CampaignError, match=message):
        conforma.campaign(file, tmp_path / "out", cli=cli)
    assert not (tmp_path / "out").exists()


def test_unreachable_scheduler_fails_before_any_case_runs(tmp_path, cli):
    file = write_campaign(tmp_path, GRID)
    with pytest.raises(conforma.CampaignError, match="cannot reach the Dask scheduler"):
        conforma.campaign(file, tmp_path / "out", scheduler=f"tcp://127.0.0.1:{free_port()}", cli=cli,
                          connect_timeout=2)
    assert not (tmp_path / "out").exists()


def test_value_lists_ranges_and_seeded_draws(tmp_path):
    from conforma._campaign_spec import load_campaign

    file = write_campaign(tmp_path, "parameters:\n  update.cap_mm: {from: 0.1, to: 0.3, step: 0.1}\n"
                                    "  friction: {random: uniform, low: 0.2, high: 0.4, count: 3, seed: 5}\n"
                                    "  load_tolerance: [1e-6]\n")
    c = load_campaign(file)
    assert c["parameters"]["update.cap_mm"] == [0.1, 0.2, 0.3]
    assert c["parameters"]["load_tolerance"] == [1e-6]  # a number (YAML 1.2), not the text '1e-6'
    draws = c["parameters"]["friction"]
    assert len(draws) == 3 and all(0.2 <= v <= 0.4 for v in draws) and load_campaign(file)["parameters"]["friction"] == draws
    assert len(c["cases"]) == 9 and len({x["id"] for x in c["cases"]}) == 9
    assert [x["id"] for x in load_campaign(file)["cases"]] == [x["id"] for x in c["cases"]]  # deterministic ids
    assert c["cases"][0]["scenario"]["profiles"]["rail"] == "50E4"  # the base's text as it was


def test_cli_campaign_runs_without_the_extension_and_reports(serial, cli, tmp_path):
    """`conforma campaign` execs the campaign module without conforma/__init__.py (no _core needed): a rerun of
    the finished serial campaign says so, and the report writes report.md and a plot per parameter."""
    file, folder, _ = serial
    env = dict(os.environ, PYTHONPATH="")  # the package of the build folder is not importable
    p = subprocess.run([cli, "campaign", "run", str(file), "--out", str(folder / "serial")], env=env,
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert "all 4 cases are already complete" in p.stdout and "nothing to run" in p.stdout
    p = subprocess.run([cli, "campaign", "report", str(folder / "serial")], env=env, capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    report = (folder / "serial" / "report.md").read_text()
    assert "4 cases (4 ok, 0 partial, 0 failed" in report
    assert (folder / "serial" / "plot_friction.png").is_file()
    assert (folder / "serial" / "plot_update_smoothing_mm.png").is_file()
    bad = write_campaign(tmp_path, "parameters:\n  frictio: [0.3]\n")
    p = subprocess.run([cli, "campaign", "run", str(bad), "--out", str(tmp_path / "o")], env=env,
                       capture_output=True, text=True)
    assert p.returncode == 2 and "unknown key 'frictio'" in p.stderr


def test_a_failed_case_is_recorded_and_does_not_stop_the_others(tmp_path, cli):
    """An executable that fails the friction-0.4 case (a wrapper of the real one): the other case completes, the
    failure is recorded with its error, a rerun skips it, --retry-failed runs it again (with the real one)."""
    wrapper = tmp_path / "conforma-failing"
    wrapper.write_text(f"#!/bin/sh\nif [ \"$2\" = wear ] && grep -q '^friction: 0.4$' \"$4\"; then\n"
                       f"  echo 'injected failure' >&2; exit 3\nfi\nexec '{cli}' \"$@\"\n")
    wrapper.chmod(0o755)
    file = write_campaign(tmp_path, "parameters:\n  friction: [0.3, 0.4]\n")
    out = tmp_path / "out"
    s = conforma.campaign(file, out, workers=2, cli=str(wrapper))
    assert (s["ran"], s["ok"], s["failed"]) == (2, 1, 1)
    (failed,) = [r for r in s["records"].values() if r["status"] == "failed"]
    assert failed["params"] == {"friction": 0.4} and "injected failure" in failed["error"]
    assert {r["case_id"]: r["status"] for r in result_rows(out)} == {c: r["status"] for c, r in s["records"].items()}
    assert conforma.campaign(file, out, cli=cli)["ran"] == 0  # a recorded failure is a complete case
    again = conforma.campaign(file, out, cli=cli, retry_failed=True)
    assert (again["ran"], again["ok"], again["failed"]) == (1, 2, 0)
