"""Burn-out of pulverised coal along a path against the numbers the reference note prints for
its kinetics (team source folder reference/cement_lime.md 5.3, 5.4, check 9), through the
integrated model (``rotarykiln.chemistry.fuel_burnout``), not through the rate functions alone.

No published burn-out curve of a stated coal was found in the note; the oracles are the note's
printed rate constants (Kobayashi k1/k2 at 1000/1500/2000 K and their crossing at 1809 K; the
OpenFOAM Baum & Street R_k and D0 at 1200/1500/1800 K), integrated here in closed form. Each
tolerance is the spread of the closed form over the last printed digit (half a unit either
way) plus the test's own time resolution; nothing is calibrated. The char density (1000 kg/m3)
and the 5 % O2 at 1 atm are stated assumptions of the checks (the note gives no char density;
the burn-out time is proportional to it on both sides).
"""

import itertools
import math
from dataclasses import replace

import numpy as np
import pytest

from rotarykiln.chemistry import fuel_burnout as fb
from rotarykiln.chemistry import solid_fuels as sf
from rotarykiln.chemistry.clinker import element_molar_mass

ATM = 101325.0
P = fb.load_burnout_parameters()
PO2 = 0.05 * ATM  # 5 % O2 at 1 atm (stated)

#: cement_lime.md 5.3 [DERIVED from SEEN PKP/UIN constants], as printed (strings: the digits)
K_PRINTED = {1000.0: ("0.688", "0.0234"), 1500.0: ("45.6", "19.3"), 2000.0: ("371", "552")}
#: cement_lime.md 5.4 table / check 9: R_k and D0(50 um), kg/(m2 s Pa), as printed
RK_D0_PRINTED = {
    1200.0: ("7.3e-7", "2.0e-5"),
    1500.0: ("3.55e-6", "2.41e-5"),
    1800.0: ("1.0e-5", "2.8e-5"),
}


def half_unit(printed):
    """Half a unit of the last digit of a number as printed ("1.0e-5" -> 0.05e-5)."""
    mant, _, exp = printed.lower().partition("e")
    decimals = len(mant.split(".")[1]) if "." in mant else 0
    return 0.5 * 10.0 ** ((int(exp) if exp else 0) - decimals)


def corners(*printed):
    """All combinations of each printed value +- half a unit of its last digit."""
    return itertools.product(*[(float(v) - half_unit(v), float(v) + half_unit(v)) for v in printed])


def printed(*values):
    return [float(v) for v in values]


def pittsburgh():
    return sf.load_kiln_fuel("pittsburgh_8")


def one_class(d):
    return fb.ParticleSizeDistribution.from_table([d], [1.0])


def pure_char():
    h_c = -P.h_f_CO2 / element_molar_mass("C")
    return sf.SolidFuel.from_analyses(
        ultimate={"C": 1.0, "H": 0.0, "O": 0.0, "N": 0.0, "S": 0.0, "ash": 0.0},
        ultimate_basis="d",
        proximate={"volatiles": 0.0, "ash": 0.0},
        proximate_basis="d",
        moisture_ar=0.0,
        hhv=h_c,
        hhv_basis="d",
    )


#: the char "devolatilises" instantly, has no volatiles, and is 1000 kg/m3
INSTANT_CHAR = replace(
    P, A1=1e9, E1=1.0, A2=1e9, E2=1.0, alpha1=0.0, alpha2=0.0, coal_density=1000.0
)


# ------------------------------------------------------------------ Kobayashi yields


def yield_from(k1, k2, a1, a2):
    return (a1 * k1 + a2 * k2) / (k1 + k2)


@pytest.mark.parametrize("T", sorted(K_PRINTED))
def test_kobayashi_yield_of_pittsburgh_from_the_printed_rates(T):
    # Pittsburgh No. 8 (Argonne, Vorres 1990): alpha1 = its VM daf (PKP), alpha2 = 0.9 (PKP's
    # guess). In an O2-free gas at constant T the released volatiles per kg daf tend to
    # (a1 k1 + a2 k2)/(k1 + k2) and follow 1 - exp(-(k1 + k2) t) on the way.
    f = pittsburgh()
    u = f.ultimate("ar")
    daf = 1.0 - u["moisture"] - u["ash"]
    a1, a2 = f.proximate("daf")["volatiles"], P.alpha2
    k1, k2 = printed(*K_PRINTED[T])
    ks = k1 + k2
    t = np.concatenate(([0.0], np.geomspace(0.05 / ks, 20.0 / ks, 60)))
    r = fb.pulverised_fuel_burnout(f, one_class(60e-6), 1.0, t, T, 0.0, time=t)
    V = r.volatiles_released / daf
    spread = [yield_from(c1, c2, a1, a2) for c1, c2 in corners(*K_PRINTED[T])]
    y_inf = yield_from(k1, k2, a1, a2)
    tol = max(abs(s - y_inf) for s in spread) + 1e-7
    assert V[-1] == pytest.approx(y_inf, abs=tol)
    # on the way: at t = 1/(k1 + k2) the yield is (1 - 1/e) of the final, to the same digits
    t1 = 1.0 / ks
    spread_t = [
        yield_from(c1, c2, a1, a2) * (1 - math.exp(-(c1 + c2) * t1))
        for c1, c2 in corners(*K_PRINTED[T])
    ]
    v1 = np.interp(t1, r.t, V)
    assert min(spread_t) - 2e-4 <= v1 <= max(spread_t) + 2e-4  # 2e-4: interpolation in t


def test_kobayashi_rates_cross_at_1809_K_in_the_burnout_model():
    # where k1 = k2 (1809 K, printed to 4 digits) the final yield is (a1 + a2)/2; the printed
    # temperature's half unit (0.5 K) moves it by |dY/dT| x 0.5 K
    f = pittsburgh()
    u = f.ultimate("ar")
    daf = 1.0 - u["moisture"] - u["ash"]
    a1, a2 = f.proximate("daf")["volatiles"], P.alpha2
    t = np.linspace(0.0, 0.05, 51)  # k1 + k2 ~ 780 1/s: 39 e-folds
    r = fb.pulverised_fuel_burnout(f, one_class(60e-6), 1.0, t, 1809.0, 0.0, time=t)
    ya, yb = (yield_from(*sf.kobayashi_devolatilisation_rates(T), a1, a2) for T in (1808.5, 1809.5))
    assert r.volatiles_released[-1] / daf == pytest.approx(
        0.5 * (a1 + a2), abs=abs(yb - ya) / 2 + 1e-9
    )


# ------------------------------------------------------------------ Baum & Street burn-out


@pytest.mark.parametrize("d0, T", [(50e-6, 1500.0), (100e-6, 1800.0), (75e-6, 1200.0)])
def test_char_burnout_time_from_the_printed_rate_coefficients(d0, T):
    # A char sphere of constant density rho burns from d0 to d in
    #   t = rho (d0 - d)/(2 p R_k) + rho (d0^2 - d^2)/(4 p D0(d0) d0)
    # with R_k and D0(50 um) as printed (D0 scales as 1/d). Burn-out 0.999 is d = d0/10.
    rho = 1000.0
    rk, d0_50 = printed(*RK_D0_PRINTED[T])

    def t_to(d, rk, D50):
        D0 = D50 * 50e-6 / d0
        return rho * (d0 - d) / (2 * PO2 * rk) + rho * (d0**2 - d**2) / (4 * PO2 * D0 * d0)

    expected = t_to(0.1 * d0, rk, d0_50)
    spread = [t_to(0.1 * d0, a, b) for a, b in corners(*RK_D0_PRINTED[T])]
    t_end = 1.2 * max(spread)
    t = np.linspace(0.0, t_end, 2001)
    r = fb.pulverised_fuel_burnout(
        pure_char(), one_class(d0), 1.0, t, T, PO2, time=t, parameters=INSTANT_CHAR
    )
    t999 = float(np.interp(0.999, r.burnout, r.t))
    tol = max(abs(s - expected) for s in spread) + 2 * (t[1] - t[0])
    assert t999 == pytest.approx(expected, abs=tol)


# ------------------------------------------------------------------ a coal: devolatilisation + char


def test_pittsburgh_burnout_time_within_the_kinetics_bracket():
    # Pittsburgh No. 8, one 75 um class, 1500 K, 5 % O2. Devolatilisation (printed k1 + k2 =
    # 64.9 1/s) is 99.99 % done by t_d = ln(1e4)/(k1 + k2); its char (mass m_f from the
    # printed yield, constant density rho_char = coal density x fixed carbon) then burns as a
    # Baum & Street sphere. So the time to burn-out 0.999 lies between
    #   t_d + [t_b(m_low) - t_b(m_end)]  and  t_d + t_b(m_f),
    # with m_low = m_f (1 - 1e-4) - t_d x (burning rate at m_f) the least char left at t_d and
    # m_end = 1e-3 of the daf fuel.
    f = pittsburgh()
    u = f.ultimate("ar")
    daf = 1.0 - u["moisture"] - u["ash"]
    a1, a2 = f.proximate("daf")["volatiles"], P.alpha2
    k1, k2 = printed(*K_PRINTED[1500.0])
    rk, d50 = printed(*RK_D0_PRINTED[1500.0])
    d0, T = 75e-6, 1500.0
    rho_char = P.coal_density * daf * (1.0 - a1)
    m0 = P.coal_density * math.pi * d0**3 / 6.0

    def diameter(m):
        return (6.0 * m / (math.pi * rho_char)) ** (1.0 / 3.0)

    def t_b(m):  # from the printed coefficients, D0 = D0(50 um) x 50 um/d
        d = diameter(m)
        return rho_char * d / (2 * PO2 * rk) + rho_char * d**2 / (4 * PO2 * d50 * 50e-6)

    def rate(m):
        d = diameter(m)
        D0 = d50 * 50e-6 / d
        return math.pi * d**2 * PO2 * D0 * rk / (D0 + rk)

    t_d = math.log(1e4) / (k1 + k2)
    m_f = m0 * daf * (1.0 - yield_from(k1, k2, a1, a2))
    m_low = m_f * (1 - 1e-4) - t_d * rate(m_f)
    m_end = 1e-3 * daf * m0
    lower = t_d + t_b(m_low) - t_b(m_end)
    upper = t_d + t_b(m_f)
    t = np.linspace(0.0, 1.3 * upper, 1301)
    r = fb.pulverised_fuel_burnout(f, one_class(d0), 1.0, t, T, PO2, time=t)
    t999 = float(np.interp(0.999, r.burnout, r.t))
    assert lower <= t999 <= upper
    assert r.element_closure_error <= 1e-8
    assert r.energy_closure_error <= 1e-8
    assert r.cumulative_heat_release[-1] == pytest.approx(f.lhv("ar"), rel=1e-8)
