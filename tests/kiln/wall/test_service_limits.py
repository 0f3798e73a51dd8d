"""A lining layer whose hot face is above its material's service limit ``t_max`` (also the top of
its k(T)) is said so after a steady solve, once per layer, where the layer is present."""

import warnings

import numpy as np
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.errors import OutOfRangeWarning
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.steady.solve import solve_kiln


def _barr_t4(t_max):
    data = yaml.safe_load(builtin_case_path("barr_T4").read_text(encoding="utf-8"))
    layer = data["wall"]["lining"][0]
    material = layer["material"]
    if isinstance(material, str):
        layer["material"] = {"name": "brick", "k": [1.0], "t_max": t_max}
    else:
        material["t_max"] = t_max
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kiln_from_case(parse_case(data))


def _limits(kiln, cells):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        sol = solve_kiln(kiln, cells)
    said = [w.message for w in caught if "lining layer" in str(w.message)]
    return sol, said


def test_a_brick_hotter_than_its_t_max_is_said_with_where_and_how_hot():
    kiln, cells = _barr_t4("1000 K")
    sol, said = _limits(kiln, cells)
    hot_face = sol.t_lining[0]  # the inner surface, the first layer's hot face
    assert hot_face.max() > 1000.0
    (w,) = said
    assert isinstance(w, OutOfRangeWarning) and w.high == 1000.0
    assert w.outside[1] == np.float64(hot_face.max())  # the hottest face, to the bit
    over = hot_face > 1000.0
    assert np.array_equal(w.mask, over)
    assert f"reaches {hot_face.max():.0f} K" in str(w) and "t_max of 1000 K" in str(w)
    z = np.asarray(sol.z)[over]
    assert f"z = {z[0]:.3g}-{z[-1]:.3g} m" in str(w)


def test_a_brick_within_its_t_max_is_not_mentioned():
    kiln, cells = _barr_t4("3000 K")
    _, said = _limits(kiln, cells)
    assert said == []
