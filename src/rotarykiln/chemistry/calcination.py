"""Limestone calcination CaCO3 -> CaO + CO2: equilibrium CO2 pressure and rate laws."""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import InputError, check_positive, check_range, warn_out_of_range

__all__ = [
    "R_GAS",
    "ATM",
    "baker_co2_equilibrium_pressure",
    "baker_equilibrium_temperature",
    "garcia_labiano_co2_equilibrium_pressure",
    "luisser_calcination_rate",
    "calcination_rate_with_equilibrium",
]

#: Molar gas constant, J/(mol K).
R_GAS = 8.314462618
#: One standard atmosphere, Pa.
ATM = 101325.0

_BAKER_A = 7.079
_BAKER_B = 8308.0


def _baker_peq(T):
    return ATM * 10.0 ** (_BAKER_A - _BAKER_B / np.asarray(T, dtype=float))


def baker_co2_equilibrium_pressure(T):
    r"""Equilibrium CO2 pressure over CaCO3/CaO (Baker 1962), Pa.

    .. math:: \log_{10}(p_{eq}/\mathrm{atm}) = 7.079 - \frac{8308}{T}

    Parameters
    ----------
    T : float or array
        Temperature, K.

    Returns
    -------
    float or ndarray
        :math:`p_{eq}`, Pa.

    Notes
    -----
    Measured by Baker over about 720-1470 K; a warning is issued outside 700-1500 K.

    Examples
    --------
    >>> round(baker_co2_equilibrium_pressure(1173.6) / 101325, 3)
    1.0

    References
    ----------
    E.H. Baker, The calcium oxide-carbon dioxide system in the pressure range 1-300
    atmospheres, J. Chem. Soc. (1962) 464-470.
    """
    T = np.asarray(T, dtype=float)
    check_positive("calcination.T", T, "K")
    warn_out_of_range("T [K]", T, 700.0, 1500.0, "Baker (1962)")
    p = ATM * 10.0 ** (_BAKER_A - _BAKER_B / T)
    return p if p.ndim else float(p)


def baker_equilibrium_temperature(p_co2):
    r"""Temperature at which CaCO3 decomposes under a CO2 partial pressure (Baker 1962), K.

    .. math:: T_{eq} = \frac{8308}{7.079 - \log_{10}(p_{CO_2}/\mathrm{atm})}

    Parameters
    ----------
    p_co2 : float or array
        CO2 partial pressure, Pa (> 0).

    Returns
    -------
    float or ndarray
        K.

    Examples
    --------
    >>> round(baker_equilibrium_temperature(101325.0), 1)
    1173.6

    References
    ----------
    E.H. Baker, The calcium oxide-carbon dioxide system in the pressure range 1-300 atmospheres, J.
    Chem. Soc. (1962) 464-470.
    """
    p = np.asarray(p_co2, dtype=float)
    check_positive("calcination.p_co2", p, "Pa")
    T = _BAKER_B / (_BAKER_A - np.log10(p / ATM))
    return T if T.ndim else float(T)


def garcia_labiano_co2_equilibrium_pressure(T):
    r"""Equilibrium CO2 pressure (Garcia-Labiano et al. 2002), Pa.

    .. math:: p_{eq} = 4.137\times 10^{12}\, \exp(-20474/T)\ \mathrm{Pa}

    Parameters
    ----------
    T : float or array
        K.

    Returns
    -------
    float or ndarray
        Pa.

    Examples
    --------
    >>> round(garcia_labiano_co2_equilibrium_pressure(1173.15) / 1e5, 3)
    1.09

    References
    ----------
    F. Garcia-Labiano, A. Abad, L.F. de Diego, P. Gayan, J. Adanez, Calcination of calcium-based
    sorbents at pressure in a broad range of CO2 concentrations, Chem. Eng. Sci. 57 (2002)
    2381-2393 (as quoted in the team source folder reference/closures.md 5a, [MEMORY, verify]).
    """
    T = np.asarray(T, dtype=float)
    check_positive("calcination.T", T, "K")
    p = 4.137e12 * np.exp(-20474.0 / T)
    return p if p.ndim else float(p)


def luisser_calcination_rate(T, conversion, A=9.8e4, E=142000.0, order=0.5):
    r"""Calcination rate of seed 004 (Luisser 2004), dx/dt in 1/s.

    .. math::
        \frac{dx}{dt} = A\, \exp\!\left(-\frac{E}{R T}\right) (1 - x)^{n},
        \quad A = 98\,000\ \mathrm{s^{-1}},\ E = 142\ \mathrm{kJ/mol},\ n = 0.5

    No equilibrium term: the rate is positive at any temperature.

    Parameters
    ----------
    T : float or array
        Solid temperature, K.
    conversion : float or array
        CaCO3 conversion :math:`x` in [0, 1].
    A : float
        Pre-exponential factor, 1/s.
    E : float
        Activation energy, J/mol.
    order : float, -
        Reaction order in :math:`1 - x`.

    Returns
    -------
    float or ndarray
        dx/dt, 1/s.

    Notes
    -----
    Lumped kinetics quoted by Ahmad (2006) eq. (3.22) for the 600-1200 degC decomposition zone;
    the primary source (Luisser, PhD TU Vienna 2004) could not be verified.

    Examples
    --------
    >>> round(luisser_calcination_rate(1100.0, 0.0), 4)
    0.0177

    References
    ----------
    S. Ahmad, Simulation of Rotary Reactor, IIT Roorkee (2006), eq. (3.22), citing M. Luisser
    (2004).
    """
    x = np.asarray(conversion, dtype=float)
    check_range("calcination.conversion", x, 0.0, 1.0, closed_low=True, closed_high=True)
    T = np.asarray(T, dtype=float)
    check_positive("calcination.T", T, "K")
    r = A * np.exp(-E / (R_GAS * T)) * (1.0 - x) ** order
    return r if r.ndim else float(r)


def calcination_rate_with_equilibrium(
    T, conversion, p_co2, A=9.8e4, E=142000.0, order=0.5, equilibrium="baker"
):
    r"""Calcination rate that stops at the CO2 equilibrium pressure, dx/dt in 1/s.

    .. math::
        \frac{dx}{dt} = A\, e^{-E/(R T)} (1 - x)^{n}\,
        \max\!\left(0,\ 1 - \frac{p_{CO_2}}{p_{eq}(T)}\right)

    The kinetic part is Luisser's (seed 004); the driving force is the standard linear
    one (closures.md 5a). The rate is zero wherever :math:`p_{CO_2} \ge p_{eq}(T)`, i.e. below
    the decomposition temperature for the local CO2 partial pressure (1173.6 K at 1 atm CO2
    with Baker's equilibrium).

    Parameters
    ----------
    T : float or array
        Solid temperature, K.
    conversion : float or array
        CaCO3 conversion, [0, 1].
    p_co2 : float or array
        CO2 partial pressure in the gas over the bed, Pa.
    A, E, order : float
        As in :func:`luisser_calcination_rate` (1/s, J/mol, -).
    equilibrium : {"baker", "garcia_labiano"}
        Equilibrium pressure correlation.

    Returns
    -------
    float or ndarray
        dx/dt, 1/s.

    Examples
    --------
    >>> calcination_rate_with_equilibrium(1160.0, 0.0, 101325.0)
    0.0
    >>> round(calcination_rate_with_equilibrium(1250.0, 0.0, 101325.0), 4)
    0.072

    References
    ----------
    Ahmad (2006) eq. (3.22); Baker (1962); closures.md 5a.
    """
    peq_fn = {
        "baker": _baker_peq,  # no range warning here: below 700 K the rate is zero anyway
        "garcia_labiano": garcia_labiano_co2_equilibrium_pressure,
    }
    if equilibrium not in peq_fn:
        raise InputError("calcination.equilibrium", equilibrium, "one of baker, garcia_labiano")
    p = np.maximum(np.asarray(p_co2, dtype=float), 0.0)
    peq = np.asarray(peq_fn[equilibrium](T), dtype=float)
    drive = np.maximum(1.0 - p / peq, 0.0)
    r = np.asarray(luisser_calcination_rate(T, conversion, A, E, order)) * drive
    return r if r.ndim else float(r)
