"""contact(fields=True): each patch's fields also as 2-D grids (strips s by a uniform x axis) that keep the element
values unchanged, with 0 pressure / traction and NaN slip outside the contact area (conforma._grid)."""
import numpy as np
import pytest

import conforma

GRID_2D = ["pressure_Pa", "traction_x_Pa", "traction_s_Pa", "slip_x", "slip_s", "wear_index_Pa", "adhesion",
           "in_contact", "cell_index"]


@pytest.fixture(scope="module")
def track():
    return conforma.Track("S1002", "60E1")


@pytest.mark.parametrize("model,lateral_m", [("hertz", 3e-3), ("conformal", 3e-3), ("conformal", 6.25e-3),
                                             ("kp", -2e-3)])
def test_grid_holds_every_element_value_on_its_strip_and_x_extent(track, model, lateral_m):
    wheels = conforma.contact(track, lateral_m=lateral_m, yaw_rad=2e-3, model=model, speed_m_s=20.0)
    patches = [p for w in wheels for p in w["patches"]]
    assert patches
    for p in patches:
        f, g = p["fields"], p["grid"]
        ns, nx = g["s_m"].shape[0], g["x_m"].shape[0]
        assert g["s_m"].ndim == 1 and g["x_m"].ndim == 1 and g["strip_width_m"].shape == (ns,)
        for key in GRID_2D:
            assert isinstance(g[key], np.ndarray) and g[key].shape == (ns, nx), key
        assert g["adhesion"].dtype == np.bool_ and g["in_contact"].dtype == np.bool_
        assert np.all(np.diff(g["s_m"]) > 0) and np.all(np.diff(g["x_m"]) > 0)
        assert np.allclose(np.diff(g["x_m"]), g["x_spacing_m"], rtol=1e-9)
        # one row per strip: the distinct s of the elements
        assert np.array_equal(g["s_m"], np.unique(f["s_m"]))
        idx, inside = g["cell_index"], g["in_contact"]
        assert np.array_equal(inside, idx >= 0)
        rows, cols = np.nonzero(inside)
        e = idx[rows, cols]
        # a node takes the value of an element of its own strip whose x-extent contains it, unchanged
        assert np.array_equal(f["s_m"][e], g["s_m"][rows])
        half = 0.5 * f["length_x_m"][e]
        assert np.all(np.abs(g["x_m"][cols] - f["x_m"][e]) <= half * (1 + 1e-9))
        for key in ["pressure_Pa", "traction_x_Pa", "traction_s_Pa", "slip_x", "slip_s", "wear_index_Pa",
                    "adhesion"]:
            assert np.array_equal(g[key][rows, cols], f[key][e]), key
        # every element at least one x spacing long owns a node
        long_enough = np.flatnonzero(f["length_x_m"] >= g["x_spacing_m"] * (1 + 1e-9))
        assert long_enough.size > 0.8 * len(f["x_m"])
        assert np.all(np.isin(long_enough, e))
        # outside the contact area: no pressure, no traction, no wear, slip undefined
        out = ~inside
        assert out.any()  # the patch is not a rectangle
        for key in ["pressure_Pa", "traction_x_Pa", "traction_s_Pa", "wear_index_Pa"]:
            assert np.all(g[key][out] == 0.0), key
        assert np.all(np.isnan(g["slip_x"][out])) and np.all(np.isnan(g["slip_s"][out]))
        assert not g["adhesion"][out].any()
        assert not np.isnan(g["slip_x"][inside]).any()
        # strip widths: element area / element length of the strip's elements
        strip = np.searchsorted(g["s_m"], f["s_m"])
        assert np.allclose(g["strip_width_m"][strip], f["area_m2"] / f["length_x_m"], rtol=1e-12)
        # the grid integrates to the patch's normal force (nodes of the spacing; elements sampled at their centre)
        fn_grid = np.sum(g["pressure_Pa"] * g["strip_width_m"][:, None]) * g["x_spacing_m"]
        assert fn_grid == pytest.approx(np.sum(f["pressure_Pa"] * f["area_m2"]), rel=0.03)


def test_no_fields_no_grid(track):
    wheel = conforma.contact(track, lateral_m=0.0, model="hertz", side="left", fields=False)[0]
    assert wheel["patches"] and all("grid" not in p and "fields" not in p for p in wheel["patches"])


def test_grid_of_contact_at_pose(track):
    loaded = conforma.contact(track, lateral_m=2e-3, model="kp", side="left", fields=False)[0]
    pose = loaded["pose"]
    wheel = conforma.contact_at_pose(track, "left", pose["y_m"], pose["z_m"], pose["roll_rad"], model="kp",
                                     speed_m_s=10.0)
    g = wheel["patches"][0]["grid"]
    assert g["pressure_Pa"].shape == (g["s_m"].size, g["x_m"].size) and g["in_contact"].any()


def test_grid_of_no_elements_is_empty():
    empty = {key: np.zeros(0) for key in ["x_m", "s_m", "length_x_m", "area_m2", "pressure_Pa", "traction_x_Pa",
                                          "traction_s_Pa", "slip_x", "slip_s", "wear_index_Pa"]}
    empty["adhesion"] = np.zeros(0, dtype=bool)
    g = conforma.patch_grid(empty)
    assert g["x_m"].shape == (0,) and g["s_m"].shape == (0,) and g["pressure_Pa"].shape == (0, 0)
