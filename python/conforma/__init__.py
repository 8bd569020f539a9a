"""Conforma: conformal (non-Hertzian) wheel-rail contact and wear, from Python.

SI units everywhere (m, rad, N, Pa); every dict key carries its unit. Errors in the input raise
``conforma.InputError`` (a ``ValueError``) with the message of the C++ core (file:line: reason for files).

Profiles::

    w = conforma.s1002();  r = conforma.rail("60E1")        # generated from the standard definitions
    p = conforma.load_profile("worn.whl")                   # Simpack, MiniProf, two-column files
    p.points()                                              # (N, 2) NumPy array of (y, z) [m]
    conforma.wheel_dimensions(w)["sd_mm"]                   # Sd, Sh, qR

Contact (same forces as ``conforma contact``)::

    track = conforma.Track("S1002", "60E1")                 # 1:40 rails, gauge 1435 mm
    wheels = conforma.contact(track, lateral_m=7e-3, yaw_rad=2e-3, model="conformal")
    patch = wheels[0]["patches"][0]; patch["fn_N"]; patch["fields"]["pressure_Pa"]   # per element (flat)
    g = patch["grid"]; g["pressure_Pa"][i, j]               # 2-D (s by x) at (g["s_m"][i], g["x_m"][j])

No silent failures: every wheel dict has ``complete`` (bool) and ``problems`` (list of str); a result that is not
complete (load control not converged, a patch cut or failed, a wear run stopped early or with failed contacts)
emits ``conforma.IncompleteResultWarning``, or raises ``conforma.IncompleteResultError`` with ``strict=True``.

Also: ``contact_at_pose`` (one wheel at a given pose and velocities), ``manchester`` (benchmark A-2.2),
``wear`` (the wear loop, when built; ``has_wear`` tells), ``share_dir()`` / ``scenario_path()`` (the scenarios and
standard profile files installed with the package), ``campaign`` / ``campaign_report`` (many wear runs of generated
scenarios on a process pool or a Dask cluster; conforma._campaign, which needs no _core: ``conforma campaign``
runs it without this __init__).
"""
import os as _os
import pathlib as _pathlib

from . import _core, types  # noqa: F401
from ._core import (  # noqa: F401
    InputError,
    Profile,
    Track,
    default_shared_data,
    has_wear,
    load_profile,
    profile_from_points,
    rail,
    s1002,
    wheel_dimensions,
)
from ._campaign import CampaignError, campaign, campaign_report  # noqa: F401  (pure Python: no _core needed)
from ._grid import patch_grid
from ._status import IncompleteResultError, IncompleteResultWarning, wear_problems, wheel_problems
from ._status import flag as _flag

if has_wear:
    from ._core import check_scenario, load_scenario  # noqa: F401

__version__ = "0.1.0"


def _finish_wheel(wheel, load_N=None):
    """Adds complete / problems to a wheel dict and the 2-D grid to each patch that has fields."""
    for p in wheel["patches"]:
        if "fields" in p:
            p["grid"] = patch_grid(p["fields"])
    problems = wheel_problems(wheel, load_N)
    wheel["complete"] = not problems
    wheel["problems"] = problems
    return problems


def contact(track, *args, strict=False, **kwargs):
    problems = []
    wheels = _core.contact(track, *args, **kwargs)
    # the prescribed load: keyword, or the 6th positional argument after track (the signature in _core.pyi)
    load_N = kwargs.get("load_N", args[4] if len(args) > 4 else 10000.0)
    for w in wheels:
        problems += _finish_wheel(w, load_N)
    return _flag(wheels, problems, "contact", strict)


contact.__doc__ = _core.contact.__doc__ + """
No silent failures: each wheel dict also has ``complete`` (bool) and ``problems`` (list of str: a wheel status
"not_converged", "no_contact" under a positive load_N, a patch normal_status other than "ok" / "hertz_regularised", a tangential_status other than "ok",
"full_slip", "no_creepage", "not_solved"); an incomplete result emits conforma.IncompleteResultWarning, or with
strict=True raises conforma.IncompleteResultError (its .result holds the wheels). Bad input raises InputError.

With fields=True each patch also has 'grid': the fields as 2-D arrays (rows: strips along s, columns: a uniform x
axis) -- x_m (nx,), s_m (ns,), strip_width_m (ns,), x_spacing_m, and (ns, nx) arrays pressure_Pa, traction_x_Pa,
traction_s_Pa, slip_x, slip_s, wear_index_Pa, adhesion, in_contact, cell_index (the flat element index, -1 outside).
Outside the contact area pressure, traction and wear index are 0, slip is NaN, adhesion and in_contact False
(conforma._grid)."""


def contact_at_pose(track, *args, strict=False, **kwargs):
    wheel = _core.contact_at_pose(track, *args, **kwargs)
    load_N = kwargs.get("load_N", args[10] if len(args) > 10 else -1.0)  # _core.pyi: 11th after track
    return _flag(wheel, _finish_wheel(wheel, load_N), "contact_at_pose", strict)


contact_at_pose.__doc__ = _core.contact_at_pose.__doc__ + """
As contact(): 'complete', 'problems', the patches' 'grid' with fields=True, IncompleteResultWarning (strict=True:
IncompleteResultError) when the wheel's result is incomplete."""


class ContactLut(_core.ContactLut):
    __doc__ = _core.ContactLut.__doc__

    def evaluate(self, track, side, lateral_m, *args, strict=False, **kwargs):
        wheel = super().evaluate(track, side, lateral_m, *args, **kwargs)
        load_N = kwargs.get("load_N", args[1] if len(args) > 1 else 50e3)  # _core.pyi: 2nd after lateral_m
        return _flag(wheel, _finish_wheel(wheel, load_N), "ContactLut.evaluate", strict)

    evaluate.__doc__ = _core.ContactLut.evaluate.__doc__.split("\n", 1)[-1] + """
As contact(): 'complete', 'problems' (the table's status of the wheel and its patches), IncompleteResultWarning
(strict=True: IncompleteResultError) when the wheel's result is incomplete."""


def manchester(*args, strict=False, **kwargs):
    rows = _core.manchester(*args, **kwargs)
    problems = [f"case {r['reference']['case']}: status {r['status']}" for r in rows if r["status"] != "ok"]
    return _flag(rows, problems, "manchester", strict)


manchester.__doc__ = _core.manchester.__doc__ + """
A case whose status is not "ok" emits IncompleteResultWarning (strict=True: IncompleteResultError)."""


def wear(scenario, *args, strict=False, **kwargs):
    run = _core.wear(scenario, *args, **kwargs)
    problems = wear_problems(run)
    run["complete"] = not problems
    run["problems"] = problems
    return _flag(run, problems, "wear", strict)


wear.__doc__ = _core.wear.__doc__ + """
No silent failures: the dict also has 'complete' (bool) and 'problems' (list of str: a status other than
"completed", steps with failed wheel contacts); an incomplete run emits
conforma.IncompleteResultWarning, or with strict=True raises conforma.IncompleteResultError (.result: the run)."""


def share_dir():
    """The folder of the run-time files installed with the package (scenarios/, profiles/ with the standard
    profile files and wear-law tables): $CONFORMA_SHARE_DIR when set and not empty, else the package's share/
    folder (a pip install and the CMake build tree, build/python/conforma/share, both have one)."""
    env = _os.environ.get("CONFORMA_SHARE_DIR", "")
    return _pathlib.Path(env) if env else _pathlib.Path(__file__).resolve().parent / "share"


def scenario_path(name="default_metro"):
    """Path of a scenario shipped with the package (share_dir()/scenarios/NAME.yaml); InputError when there is
    none of that name (the message lists those there are)."""
    folder = share_dir() / "scenarios"
    path = folder / (name if name.endswith(".yaml") else name + ".yaml")
    if not path.is_file():
        there = sorted(p.stem for p in folder.glob("*.yaml")) if folder.is_dir() else []
        raise InputError(f"no scenario '{name}' in {folder} (there are: {', '.join(there) or 'none'})")
    return str(path)


__all__ = sorted(
    [name for name in dir(_core) if not name.startswith("_")]
    + ["CampaignError", "IncompleteResultError", "IncompleteResultWarning", "campaign", "campaign_report", "patch_grid",
       "scenario_path", "share_dir", "types", "wear_problems", "wheel_problems"])
