"""The per-element fields of a patch as 2-D grids over (s, x): rows are the strips (s along the rail profile),
columns a uniform x axis (along the track).

The elements of a patch (``patch["fields"]``, one entry per FASTSIM element) are laid out strip by strip
(include/conforma/fastsim.hpp FastsimStrip): every element of a strip has the strip's s, the elements of a strip
have one length along x, and strips differ in extent and element length. The grid keeps the elements' values
unchanged (no interpolation): node (i, j) at (s_m[i], x_m[j]) takes the value of the element of strip i whose
x-extent [x - dx/2, x + dx/2) contains x_m[j] (its index in the flat fields: ``cell_index``), and nodes outside
every element of the strip are outside the contact area:

    pressure_Pa, traction_x_Pa, traction_s_Pa, wear_index_Pa   0 (no contact: no pressure, no traction, no work)
    slip_x, slip_s                                              NaN (slip is undefined where the bodies do not touch)
    adhesion, in_contact                                        False
    cell_index                                                  -1

The x spacing is the shortest element length of the patch (but at least the patch's x extent / (8 x the most
elements in a strip)), so every element at least that long owns one node or more.
"""
import numpy as np

# the element-wise fields that become grids, with their value outside the contact area
_FILL = {
    "pressure_Pa": 0.0,
    "traction_x_Pa": 0.0,
    "traction_s_Pa": 0.0,
    "wear_index_Pa": 0.0,
    "slip_x": np.nan,
    "slip_s": np.nan,
}
# finest x spacing as a fraction of (patch x extent / most elements in a strip): bounds the grid size
_MAX_REFINEMENT = 8


def patch_grid(fields):
    """The 2-D grids of one patch from its flat ``fields`` dict (see the module docstring): a dict with the axes
    ``x_m`` (nx,), ``s_m`` (ns,), ``strip_width_m`` (ns,), the grids (ns, nx) pressure_Pa, traction_x_Pa,
    traction_s_Pa, slip_x, slip_s, wear_index_Pa (float), adhesion, in_contact (bool), cell_index (int, -1 outside),
    and ``x_spacing_m``."""
    x = np.asarray(fields["x_m"], dtype=float)
    s = np.asarray(fields["s_m"], dtype=float)
    dx = np.asarray(fields["length_x_m"], dtype=float)
    area = np.asarray(fields["area_m2"], dtype=float)
    n = x.size
    if n == 0:
        empty2 = np.zeros((0, 0))
        grid = {key: empty2.copy() for key in _FILL}
        grid.update(x_m=np.zeros(0), s_m=np.zeros(0), strip_width_m=np.zeros(0), x_spacing_m=0.0,
                    adhesion=np.zeros((0, 0), dtype=bool), in_contact=np.zeros((0, 0), dtype=bool),
                    cell_index=np.zeros((0, 0), dtype=np.int64))
        return grid
    s_axis, strip_of = np.unique(s, return_inverse=True)
    ns = s_axis.size
    elements_per_strip = np.bincount(strip_of, minlength=ns)
    x_lo, x_hi = float(np.min(x - 0.5 * dx)), float(np.max(x + 0.5 * dx))
    extent = x_hi - x_lo
    positive = dx[dx > 0]
    h = float(positive.min()) if positive.size else extent
    h = max(h, extent / (_MAX_REFINEMENT * int(elements_per_strip.max())))
    nx = max(1, int(np.ceil(extent / h - 1e-9))) if extent > 0 else 1
    x_axis = x_lo + (np.arange(nx) + 0.5) * (extent / nx if extent > 0 else 0.0)

    index = np.full((ns, nx), -1, dtype=np.int64)
    for e in range(n):  # each element claims the nodes inside its x-extent, within its strip's row
        lo, hi = x[e] - 0.5 * dx[e], x[e] + 0.5 * dx[e]
        j0 = int(np.searchsorted(x_axis, lo, side="left"))
        j1 = int(np.searchsorted(x_axis, hi, side="left"))
        index[strip_of[e], j0:j1] = e
    inside = index >= 0
    safe = np.where(inside, index, 0)

    grid = {"x_m": x_axis, "s_m": s_axis, "x_spacing_m": extent / nx if extent > 0 else 0.0}
    width = np.zeros(ns)
    with np.errstate(divide="ignore", invalid="ignore"):
        per_element_width = np.where(dx > 0, area / dx, 0.0)
    width[strip_of] = per_element_width  # every element of a strip has the strip's width
    grid["strip_width_m"] = width
    for key, fill in _FILL.items():
        values = np.asarray(fields[key], dtype=float)
        grid[key] = np.where(inside, values[safe], fill)
    grid["adhesion"] = np.where(inside, np.asarray(fields["adhesion"], dtype=bool)[safe], False)
    grid["in_contact"] = inside
    grid["cell_index"] = index
    return grid
