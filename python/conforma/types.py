"""The dicts the conforma functions return, as TypedDicts (for type checkers and editors; at run time they are plain
dicts). Keys carry their units; per-element arrays are NumPy arrays. python/tests/test_types_and_stubs.py checks
that these keys are exactly those the functions return."""
from typing import Any, Dict, List, TypedDict

import numpy as np

Array = np.ndarray


class Fields(TypedDict):
    """Per FASTSIM element of a patch (all arrays of one length n, in the element order: strip by strip)."""
    x_m: Array            # element centre along the track, m
    s_m: Array            # along the rail profile from the patch reference point (+ field side), m
    rail_s_m: Array       # arc length on the mounted rail profile, m
    wheel_y_m: Array      # wheel-profile lateral coordinate facing the element, m
    area_m2: Array        # element area, m^2
    length_x_m: Array     # element length along x, m
    pressure_Pa: Array
    traction_x_Pa: Array  # on the wheel, local (x, s) frame
    traction_s_Pa: Array
    slip_x: Array         # slip velocity / V (0 in adhesion)
    slip_s: Array
    adhesion: Array       # bool
    wear_index_Pa: Array  # |p_t . slip|


class Grid(TypedDict):
    """The fields of a patch as 2-D (ns, nx) arrays over the strips (s) and a uniform x axis (conforma._grid):
    outside the contact area pressure / traction / wear index 0, slip NaN, adhesion / in_contact False."""
    x_m: Array            # (nx,) node x, m
    s_m: Array            # (ns,) strip centre s, m
    x_spacing_m: float
    strip_width_m: Array  # (ns,) m
    pressure_Pa: Array
    traction_x_Pa: Array
    traction_s_Pa: Array
    wear_index_Pa: Array
    slip_x: Array
    slip_s: Array
    adhesion: Array       # bool
    in_contact: Array     # bool
    cell_index: Array     # int, index into Fields, -1 outside


class _PatchScalars(TypedDict):
    normal_status: str
    tangential_status: str
    fn_N: float
    fx_N: float
    fy_N: float
    mz_Nm: float
    pmax_Pa: float
    p0_Pa: float
    area_m2: float
    a_m: float
    b_m: float
    width_m: float
    length_m: float
    approach_m: float
    contact_angle_rad: float
    y_contact_rail_m: float
    z_contact_rail_m: float
    y_contact_wheel_m: float
    rolling_radius_m: float
    lead_m: float
    xi: float
    eta: float
    phi_per_m: float
    alpha_c_deg: float
    is_conformal: bool
    adhesion_area_m2: float
    slip_area_m2: float
    frictional_power_W: float
    vertical_force_N: float
    lateral_force_N: float
    model: str
    auto_alpha_c_deg: float
    normal_iterations: int              # exact model: BEM conjugate-gradient iterations (0 otherwise)
    normal_residual: float              # exact model: last relative pressure change of the BEM solve
    tangential_iterations: int          # exact model: Gauss-Seidel sweeps of the tangential solve
    tangential_residual: float          # exact model: last relative traction change
    force_track_N: List[float]          # [x, y, z] on the wheel, track frame, N
    contact_point_track_m: List[float]  # [x, y, z], track frame, m


class Patch(_PatchScalars, total=False):
    """One contact patch: the keys of `conforma contact --json` plus the track-frame force and point; with
    fields=True also the per-element fields and their grid."""
    fields: Fields
    grid: Grid


class Pose(TypedDict):
    y_m: float
    z_m: float
    roll_rad: float
    yaw_rad: float


class Wheel(TypedDict):
    """One wheel of contact() / contact_at_pose()."""
    side: str                 # "left" | "right"
    model: str
    status: str               # "ok" | "no_contact" | "not_converged"
    pose: Pose
    vertical_force_N: float
    pressure_vertical_force_N: float
    lateral_force_N: float
    load_iterations: int
    candidate_load_N: float   # load the contact candidates were found for (the wheel load, or the fixed point of
                              # load_balance "total-consistent"); 0 in approach mode
    candidate_searches: int   # candidate searches of the solve (1; more with "total-consistent")
    patches: List[Patch]
    warnings: List[str]       # plausibility warnings "code: message" (docs/physics-reference.md §13)
    complete: bool            # no problem below
    problems: List[str]       # what did not converge or failed ([] when complete)


class Dimensions(TypedDict):
    sd_m: float
    sh_m: float
    qr_m: float
    sd_mm: float
    sh_mm: float
    qr_mm: float
    p0_m: List[float]
    tip_m: List[float]
    sd_point_m: List[float]
    qr_point_m: List[float]


class RigidEquilibrium(TypedDict):
    status: str
    y_m: float
    z_m: float
    roll_rad: float
    yaw_rad: float
    rolling_radius_difference_m: float


class ManchesterRow(TypedDict):
    reference: Dict[str, Any]  # the CONTACT reference case (case, y_ws_mm, ..., area_mm2)
    patches: int
    fn_N: float
    fx_N: float
    fs_N: float
    pmax_MPa: float
    area_mm2: float
    y_cp_mm: float
    delta_rad: float
    err_fn: float
    err_pmax: float
    err_area: float
    err_fx_N: float
    err_fs_N: float
    status: str


class WearSteps(TypedDict):
    """The steps table of wear(): NumPy columns, row 0 the initial wheel (km = 0)."""
    rail_step: Array
    step: Array
    km: Array
    step_km: Array
    max_depth_mm: Array
    sd_mm: Array
    sh_mm: Array
    qr_mm: Array
    tread_wear_mm: Array
    flange_wear_mm: Array
    samples: Array
    failed_contacts: Array
    kinematics_fallbacks: Array


class WearRun(TypedDict):
    scenario: str
    model: str
    status: str               # "completed" | "invalid_profile" | "no_wear"
    message: str
    steps: WearSteps
    wheel_profiles: List[Any]  # conforma.Profile per row
    complete: bool
    problems: List[str]


class TrackClass(TypedDict):
    name: str
    curve_radius_m: float
    cant_m: float
    speed_m_s: float
    share: float
    friction: float


class ScenarioCheck(TypedDict):
    name: str
    wheel: str
    rail: str
    contact_model: str
    gauge_m: float
    rail_inclination_rad: float
    friction: float
    cap_m: float
    steps: int
    total_km: float
    track_classes: List[TrackClass]
