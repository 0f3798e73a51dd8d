import numpy as np
import pytest

from rotarykiln import regimes as rg
from rotarykiln.errors import InputError

RPM = 2 * np.pi / 60


def test_froude_and_fraction_of_critical_are_consistent():
    fr = rg.froude_number(3 * RPM, 0.2)
    assert rg.fraction_of_critical(3 * RPM, 0.2) == pytest.approx(np.sqrt(fr))
    assert rg.froude_number(rg.critical_speed(0.7), 0.7) == pytest.approx(1.0)


@pytest.mark.parametrize(
    ("fr", "fill", "expected"),
    [
        (1e-6, 0.2, "slipping"),
        (5e-5, 0.2, "slumping"),
        (5e-4, 0.05, "slumping"),
        (5e-4, 0.2, "rolling"),
        (5e-3, 0.05, "rolling"),
        (0.05, 0.2, "cascading"),
        (0.5, 0.3, "cataracting"),
        (1.0, 0.3, "centrifuging"),
    ],
)
def test_mellmann_bands(fr, fill, expected):
    assert rg.classify_regime(fr, fill).name == expected


def test_henein_bands():
    names = rg.classify_regime(np.array([0.05, 0.3, 0.57, 0.8, 1.0]) ** 2, 0.2, criterion="henein")
    assert list(names.name) == ["slumping", "rolling", "cascading", "cataracting", "centrifuging"]


def test_bands_are_configurable():
    bands = rg.MellmannBands(cascading_min=0.1)
    assert rg.classify_regime(0.05, 0.3, bands=bands).name == "rolling"


def test_low_wall_friction_slips():
    res = rg.classify_regime(1e-3, 0.2, wall_friction=0.05, repose_angle=np.radians(35))
    assert res.name == "slipping"
    res = rg.classify_regime(1e-3, 0.2, wall_friction=1.0, repose_angle=np.radians(35))
    assert res.name == "rolling"


def test_vectorised_classification_frame():
    res = rg.classify_regime(np.logspace(-6, 0.5, 20), 0.2)
    frame = res.to_frame()
    assert len(frame) == 20 and set(frame["regime"]) <= set(rg.REGIMES)


def test_bad_input():
    with pytest.raises(InputError, match="speed"):
        rg.froude_number(-1.0, 1.0)
    with pytest.raises(InputError, match="criterion"):
        rg.classify_regime(0.01, 0.2, criterion="foo")
    with pytest.raises(InputError, match="fill"):
        rg.classify_regime(0.01, 1.0)


def test_regime_map_plot():
    import matplotlib.pyplot as plt

    fig = rg.classify_regime(0.084, 0.3).plot()
    assert fig.axes[0].get_yscale() == "log"
    plt.close(fig)
