"""Campaigns: many wear / compare / validate runs of generated scenarios, on this machine or a Dask cluster.

    conforma.campaign("study.yaml", "study_out")                       # local process pool (one case per CPU)
    conforma.campaign("study.yaml", "study_out", scheduler="dask-local", workers=2)   # Dask LocalCluster
    conforma.campaign("study.yaml", "study_out", scheduler="tcp://host:8786")        # a Dask scheduler
    conforma.campaign_report("study_out")                              # study_out/report.md + plots

The same from the command line: `conforma campaign run FILE --out DIR [--scheduler ADDR] [--workers N]` and
`conforma campaign report DIR`. The campaign file: _campaign_spec.py (README.md "Campaigns"); the folder:
_campaign_run.py. Each case is one `conforma` process (the executable: cli=, else $CONFORMA_CLI, else PATH);
this module and its parts need the standard library, PyYAML, matplotlib for the report and Dask distributed
(Debian python3-distributed) for the Dask schedulers, but not the compiled extension conforma._core: the
executable runs them from its share dir without the Python package (python/conforma/_campaign_main.py).
"""
import argparse
import sys

from ._campaign_report import write_report
from ._campaign_run import run_campaign
from ._campaign_spec import CampaignError, load_campaign

__all__ = ["CampaignError", "campaign", "campaign_report", "load_campaign", "main"]


def campaign(file, out, scheduler="local", workers=None, cli=None, retry_failed=False, connect_timeout=10.0,
             log=None):
    """Runs every case of the campaign `file` that is not complete in the folder `out`.

    scheduler: 'local' (a pool of `workers` processes, the default), 'serial' (one after the other),
    'dask-local' (a Dask LocalCluster of `workers` worker processes on 127.0.0.1) or a Dask scheduler's address
    ('tcp://host:8786', reached within connect_timeout seconds); workers: None = the number of CPUs.
    Every check (campaign file, parameters against the base scenario, every generated scenario through the
    executable's scenario reader, the scheduler) comes before any case runs and raises CampaignError (a
    ValueError). A case that fails is recorded (status 'failed', its error) and does not stop the others; a case
    whose folder holds result.json is skipped (retry_failed=True: unless it failed).

    Returns a dict: name, cases, ran, skipped, ok, partial, failed, results (path of results.csv), records
    (case id -> its result.json as a dict), wall_s, backend."""
    return run_campaign(file, out, scheduler=scheduler, workers=workers, cli=cli, retry_failed=retry_failed,
                        connect_timeout=connect_timeout, log=log)


def campaign_report(folder, plots=True):
    """Writes folder/report.md (summary, result table, spread over the other parameters) and a PNG per varied
    numeric parameter (matplotlib); returns the path of report.md."""
    return write_report(folder, plots=plots)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="conforma campaign")
    sub = parser.add_subparsers(dest="what", required=True)
    run = sub.add_parser("run")
    run.add_argument("file")
    run.add_argument("--out", required=True)
    run.add_argument("--scheduler", default="local")
    run.add_argument("--workers", type=int, default=None)
    run.add_argument("--retry-failed", action="store_true")
    run.add_argument("--cli", default=None)
    report = sub.add_parser("report")
    report.add_argument("dir")
    report.add_argument("--cli", default=None)  # given by the executable; not needed here
    a = parser.parse_args(argv)
    try:
        if a.what == "run":
            s = run_campaign(a.file, a.out, scheduler=a.scheduler, workers=a.workers, cli=a.cli,
                             retry_failed=a.retry_failed)
            return 5 if s["failed"] or s["partial"] else 0  # exit_status.hpp PartialResult
        print(f"campaign report: {write_report(a.dir)}")
        return 0
    except CampaignError as e:
        print(f"conforma: error: {e}", file=sys.stderr)
        return 2  # exit_status.hpp InputError
    except OSError as e:  # an output folder that cannot be made or written (a traceback before: session 25)
        print(f"conforma: error: {e}", file=sys.stderr)
        return 2
    except (TypeError, ValueError, KeyError, IndexError, AttributeError) as e:
        if a.what != "report":
            raise
        # a campaign folder whose files are not the campaign's (e.g. campaign.json holding a list)
        print(f"conforma: error: {a.dir}: malformed campaign files ({type(e).__name__}: {e})", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
