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
    patch = wheels[0]["patches"][0]; patch["fn_N"]; patch["fields"]["pressure_Pa"]

Also: ``contact_at_pose`` (one wheel at a given pose and velocities), ``manchester`` (benchmark A-2.2),
``wear`` (the wear loop, when built; ``has_wear`` tells).
"""
from ._core import (  # noqa: F401
    InputError,
    Profile,
    Track,
    contact,
    contact_at_pose,
    default_shared_data,
    has_wear,
    load_profile,
    manchester,
    profile_from_points,
    rail,
    s1002,
    wear,
    wheel_dimensions,
)
from . import _core

if has_wear:
    from ._core import check_scenario, load_scenario  # noqa: F401

__all__ = [name for name in dir(_core) if not name.startswith("_")]
