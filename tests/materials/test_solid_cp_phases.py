"""Solid heat capacities in pieces with phase transitions (quartz alpha/beta), range warnings.

Reference values:

- NIST-JANAF table of SiO2 (cr; alpha-beta quartz), M.W. Chase Jr., NIST-JANAF Thermochemical
  Tables, 4th ed. (1998), cp in J/(mol K): 300 K 44.77, 800 K 73.7, 900 K 67.95, 1200 K 70.92.
  These are recalled, not read from the table here [MEMORY, verify]; hence the 2 % tolerance.
- The NASA Glenn polynomials SiO2(Lqz), SiO2(hqz), CaO(s), CaCO3(caL) (McBride, Gordon & Reno,
  NASA TM-4513, 1993; fitted to the JANAF 6/67 and 6/73 tables and to Barin 1989), read at test
  time from Cantera's ``nasa_condensed.yaml``: an independent fit of the same data, so the
  comparison is verifiable here (tolerance 1 %; the two fits agree to 0.02 % for quartz).
"""

import warnings

import numpy as np
import pytest
from scipy.integrate import quad

from rotarykiln.errors import InputError, OutOfRangeWarning
from rotarykiln.materials.gas import air_table
from rotarykiln.materials.solids import CpSegment, PhaseTransition, Solid, load_solid

M_SIO2 = 0.060084
JANAF_QUARTZ_CP = {300.0: 44.77, 800.0: 73.7, 900.0: 67.95, 1200.0: 70.92}  # [MEMORY, verify]
L_QUARTZ = 728.0  # J/mol, alpha -> beta at 847 K (solids.yaml)


@pytest.fixture(scope="module")
def nasa():
    ct = pytest.importorskip("cantera")
    return {s.name: s.thermo for s in ct.Species.list_from_file("nasa_condensed.yaml")}


def _nasa_quartz(nasa, T):
    return nasa["SiO2(Lqz)"] if T < 847.0 else nasa["SiO2(hqz)"]


@pytest.fixture(scope="module")
def sand():
    return load_solid("sand")


def test_quartz_cp_against_janaf_and_nasa(sand, nasa):
    for T, cp_table in JANAF_QUARTZ_CP.items():
        cp = float(sand.cp(T)) * M_SIO2
        assert cp == pytest.approx(cp_table, rel=0.02), T
        assert cp == pytest.approx(_nasa_quartz(nasa, T).cp(T) / 1000.0, rel=0.01), T
    # the old single Maier-Kelley fit was ~23 % high at 1200 K; beta quartz is nearly flat
    assert float(sand.cp(1200.0)) * M_SIO2 < 72.0


def _phase_cp(sand, k, T):
    """c_p (J/(mol K)) of phase ``k`` of the sand (0 alpha, 1 beta quartz), its own fit."""
    return float(sand._pieces[0][k].cp_molar(np.asarray(float(T))))


def test_quartz_phase_cp_blends_across_847_and_apparent_cp_is_continuous(sand):
    # the phases' own values at 847 K: alpha 76.5, beta 67.4 J/(mol K)
    assert _phase_cp(sand, 0, 847.0) == pytest.approx(76.5, abs=0.1)
    assert _phase_cp(sand, 1, 847.0) == pytest.approx(67.4, abs=0.1)
    # without the latent bump: each phase's value outside the 10 K window, blended by the
    # phase fraction inside it (the mean at 847 K), continuous: no jump for the closures
    below, above = sand.cp([841.9, 852.1], latent=False) * M_SIO2
    assert below == pytest.approx(_phase_cp(sand, 0, 841.9), rel=1e-12)
    assert above == pytest.approx(_phase_cp(sand, 1, 852.1), rel=1e-12)
    mid = float(sand.cp(847.0, latent=False)) * M_SIO2
    assert mid == pytest.approx(0.5 * (_phase_cp(sand, 0, 847.0) + _phase_cp(sand, 1, 847.0)))
    for T in (842.0, 847.0, 852.0):
        a, b = sand.cp([T - 1e-7, T + 1e-7], latent=False)
        assert a == pytest.approx(b, rel=1e-6), T
    # the apparent cp (dh/dT) is continuous: at the window edges and at the centre
    for T in (842.0, 847.0, 852.0):
        a, b = sand.cp([T - 1e-7, T + 1e-7])
        assert a == pytest.approx(b, rel=1e-6), T
    # outside the window the apparent cp is the phase cp
    assert sand.cp(841.0) == sand.cp(841.0, latent=False)
    assert sand.cp(853.0) == sand.cp(853.0, latent=False)
    # inside it, the latent heat shows as a bump of peak 1.5 L / w
    peak = float(sand.cp(847.0) - sand.cp(847.0, latent=False))
    assert peak * M_SIO2 == pytest.approx(1.5 * L_QUARTZ / 10.0, rel=0.01)


def test_enthalpy_is_integral_of_cp_plus_latent_heat(sand, nasa):
    assert float(sand.enthalpy(298.15)) == 0.0
    # the sharp transition: alpha quartz to 847 K, then beta, plus the latent heat
    sensible = quad(lambda t: _phase_cp(sand, 0, t), 298.15, 847.0)[0]
    sensible += quad(lambda t: _phase_cp(sand, 1, t), 847.0, 1200.0)[0]
    h = float(sand.enthalpy(1200.0))
    assert h == pytest.approx((sensible + L_QUARTZ) / M_SIO2, rel=1e-10)
    # and the apparent cp integrates to h everywhere, through the window
    for T in (845.0, 847.0, 850.0, 1200.0):
        apparent = quad(lambda t: float(sand.cp(t)), 298.15, T, points=[842.0, 847.0, 852.0])[0]
        assert float(sand.enthalpy(T)) == pytest.approx(apparent, rel=1e-10), T
    # the NASA polynomials carry their own enthalpy constants: H(1200, beta) - H(298.15, alpha)
    h_nasa = (nasa["SiO2(hqz)"].h(1200.0) - nasa["SiO2(Lqz)"].h(298.15)) / 1000.0
    assert h * M_SIO2 == pytest.approx(h_nasa, rel=2e-3)


def test_enthalpy_continuous_and_differentiable_across_transition(sand):
    eps = 1e-6
    for T in (842.0, 847.0, 852.0):
        lo, hi = sand.enthalpy([T - eps, T + eps])
        assert hi - lo == pytest.approx(2 * eps * float(sand.cp(T)), rel=1e-3, abs=1e-6), T
    # a centred difference of h equals cp across the window (stencils off the window edges,
    # where cp is continuous but its slope jumps)
    T = np.linspace(840.0, 854.0, 29) + 0.01
    dh = (sand.enthalpy(T + 1e-4) - sand.enthalpy(T - 1e-4)) / 2e-4
    np.testing.assert_allclose(dh, sand.cp(T), rtol=1e-5)
    # h is monotone through the transition (the latent heat is taken up on heating)
    assert np.all(np.diff(sand.enthalpy(np.linspace(800.0, 900.0, 501))) > 0)


def test_limestone_and_lime(nasa):
    lime, limestone = load_solid("lime"), load_solid("limestone")
    for T in (500.0, 1000.0, 1500.0, 2500.0):
        assert float(lime.cp(T)) * lime.molar_mass == pytest.approx(
            nasa["CaO(s)"].cp(T) / 1000.0, rel=0.01
        )
    # JANAF table, CaO at 298.15 K: 42.12 J/(mol K) [MEMORY, verify]
    assert float(lime.cp(298.15)) * lime.molar_mass == pytest.approx(42.12, rel=0.01)
    # calcite at 298.15 K: 83.47 J/(mol K) (NIST WebBook); NASA pieces meet at 1000 K
    assert float(limestone.cp(298.15)) * limestone.molar_mass == pytest.approx(83.47, rel=0.005)
    a, b = limestone.enthalpy([1000.0 - 1e-9, 1000.0 + 1e-9])
    assert abs(b - a) < 1e-3
    for s in (lime, limestone):
        integral = quad(lambda t, s=s: float(s.cp(t)), 298.15, 1150.0, points=[1000.0])[0]
        assert float(s.enthalpy(1150.0)) == pytest.approx(integral, rel=1e-10)


def test_warning_outside_the_range_once_with_the_span(sand):
    T = np.array([[300.0, 2100.0], [2250.0, 1000.0]])
    with pytest.warns(OutOfRangeWarning, match=r"sand temperature \[K\] = 2100 to 2250") as rec:
        assert sand.check_range(T) is True
    assert len(rec) == 1 and "298, 1996" in str(rec[0].message)
    with pytest.warns(OutOfRangeWarning, match="= 250"):
        sand.cp(250.0, check=True)
    with pytest.warns(OutOfRangeWarning, match="limestone"):
        load_solid("limestone").enthalpy(1300.0, check=True)


def test_no_warning_inside_the_range_nor_from_the_hot_path(sand):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert sand.check_range(np.linspace(298.15, 1996.0, 50)) is False
        sand.cp(np.array([250.0, 2500.0]))  # extrapolated, but no check asked
        sand.enthalpy(2500.0)
        assert load_solid("charcoal").check_range(3000.0) is False  # constant cp: no range
        legacy = Solid("mk", 1600.0, 2600.0, 1e-3, 0.9, cp_coeffs=(46.94, 0.03431, -1.13e6),
                       molar_mass=M_SIO2)  # fmt: skip
        assert legacy.check_range(3000.0) is False


def test_vectorised_shapes(sand):
    T = np.linspace(300.0, 1500.0, 4 * 25).reshape(4, 25)
    cp, h = sand.cp(T), sand.enthalpy(T)
    assert cp.shape == h.shape == (4, 25)
    scalar = np.array([[float(sand.enthalpy(t)) for t in row] for row in T])
    np.testing.assert_array_equal(h, scalar)
    # a NaN in one element leaves the others right (the piece selection ignores it)
    Tn = T.copy()
    Tn[0, 0] = np.nan
    hn = sand.enthalpy(Tn)
    assert np.isnan(hn[0, 0]) and np.array_equal(hn.ravel()[1:], h.ravel()[1:])
    assert np.ndim(sand.cp(900.0)) == 0 and sand.cp(np.empty((2, 0))).shape == (2, 0)


def test_legacy_maier_kelley_matches_the_old_formula():
    a, b, c = 104.52, 0.02192, -2.594e6
    s = load_solid("limestone", cp_coeffs=(a, b, c))
    T = np.array([400.0, 900.0])
    T0 = 298.15
    old = (a * (T - T0) + 0.5 * b * (T**2 - T0**2) - c * (1 / T - 1 / T0)) / s.molar_mass
    np.testing.assert_allclose(s.enthalpy(T), old, rtol=1e-12)
    np.testing.assert_allclose(s.cp(T), (a + b * T + c / T**2) / s.molar_mass, rtol=1e-14)
    assert float(load_solid("sand", cp_const=800.0).enthalpy(398.15)) == pytest.approx(8e4)


def test_bad_segments_are_refused():
    alpha = CpSegment("shomate", (1.0, 0.0, 0.0, 0.0, 0.0), 298.0, 847.0)
    beta = CpSegment("shomate", (1.0, 0.0, 0.0, 0.0, 0.0), 850.0, 1000.0)
    kw = dict(molar_mass=0.06, cp_segments=(alpha, beta))
    with pytest.raises(InputError, match="contiguous"):
        Solid("x", 1600.0, 2600.0, 1e-3, 0.9, **kw)
    beta = CpSegment("shomate", (1.0, 0.0, 0.0, 0.0, 0.0), 847.0, 1000.0)
    kw["cp_segments"] = (alpha, beta)
    with pytest.raises(InputError, match="boundary"):
        Solid("x", 1600.0, 2600.0, 1e-3, 0.9, transitions=(PhaseTransition(900.0, 1.0),), **kw)
    with pytest.raises(InputError, match="narrower"):
        Solid("x", 1600.0, 2600.0, 1e-3, 0.9, transitions=(PhaseTransition(847.0, 1.0, 400),), **kw)
    with pytest.raises(InputError, match="form"):
        CpSegment("janaf", (1.0,), 298.0, 847.0)
    with pytest.raises(InputError, match="coefficients"):
        CpSegment("nasa7", (1.0, 2.0), 298.0, 847.0)


def test_gas_table_range_check():
    air = air_table()
    with pytest.warns(OutOfRangeWarning, match=r"gas temperature \[K\] = 3500"):
        assert air.check_range(np.array([1000.0, 3500.0])) is True
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert air.check_range(np.array([200.0, 3200.0])) is False
