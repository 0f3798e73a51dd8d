r"""Emissivity of CO2/H2O gas mixtures (weighted sum of grey gases) and the freeboard beam length.

.. math:: \varepsilon_g = \sum_i a_i(T)\,[1 - \exp(-\kappa_i\,p\,L)]

- :func:`smith_wsgg_emissivity`: Smith, Shen & Friedman (1982), 3 grey gases, fixed ratios.
- :func:`johansson_wsgg_emissivity`: Johansson et al. (2011), 4 grey gases, any
  :math:`MR = p_w/p_c` in 0.125-2.
- :func:`gorog_mean_beam_length`: :math:`L_e = 0.95 D (1 - h/D)`.
- :func:`soot_emissivity`: grey soot of a luminous flame, and :func:`combined_emissivity`
  of gas and soot.
- :func:`wsgg_bands`: the grey gases of either WSGG model one by one (their weights at the
  gas temperature and at any surface temperature, and their emissivities), for an exchange
  that keeps the spectrum: the absorptivity of the gas for a surface at :math:`T_s` is
  :math:`\alpha_g = \sum_i a_i(T_s)[1 - e^{-\kappa_i pL}]` (Modest, Radiative Heat Transfer,
  3rd ed., section 11.10; closures.md 3b), not the emissivity at the gas temperature.

Partial pressures in Pa (converted to atm inside: the models are fitted in atm m).
Coefficients: team source folder reference/closures.md 3a, 3c, 3d.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import (
    InputError,
    check_nonnegative,
    check_positive,
    check_range,
    warn_out_of_range,
)

__all__ = [
    "combined_emissivity",
    "gorog_mean_beam_length",
    "johansson_wsgg_emissivity",
    "smith_wsgg_emissivity",
    "soot_emissivity",
    "particle_absorption_coefficient",
    "particle_cloud_emissivity",
    "WsggBands",
    "wsgg_bands",
]

ATM = 101325.0

# kappa [1/(atm m)], b1..b4 for a_i = b1e-1 + b2e-4 T + b3e-7 T^2 + b4e-11 T^3
_SMITH = {
    "pw/pc=1": (
        (0.4303, 5.150, -2.303, 0.9779, -1.494),
        (7.055, 0.7749, 3.399, -2.297, 3.770),
        (178.1, 1.907, -1.824, 0.5608, -0.5122),
    ),
    "pw/pc=2": (
        (0.4201, 6.508, -5.551, 3.029, -5.353),
        (6.516, -0.2504, 6.112, -3.882, 6.528),
        (131.9, 2.718, -3.118, 1.221, -1.612),
    ),
    "co2": (
        (0.3966, 0.4334, 2.620, -1.560, 2.565),
        (15.64, -0.4814, 2.822, -1.794, 3.274),
        (394.3, 0.5492, 0.1087, -0.3500, 0.9123),
    ),
    "h2o": (
        (0.4098, 5.977, -5.119, 3.042, -5.564),
        (6.325, 0.5677, 3.333, -1.967, 2.718),
        (120.5, 1.800, -2.334, 1.008, -1.454),
    ),
    "h2o, pw=1atm": (
        (0.4496, 6.324, -8.358, 6.135, -13.03),
        (7.113, -0.2016, 7.145, -5.212, 9.868),
        (119.7, 3.500, -5.040, 2.425, -3.888),
    ),
}

_JOHANSSON_K = ((0.055, 0.012), (0.880, -0.021), (10.0, -1.6), (135.0, -35.0))
_JOHANSSON_C = (
    ((0.358, 0.0731, -0.0466), (-0.165, -0.0554, 0.0930), (0.0598, 0.0028, -0.0256)),
    ((0.392, -0.212, 0.0191), (-0.291, 0.644, -0.209), (0.0784, -0.197, 0.0662)),
    ((0.142, -0.0831, 0.0148), (0.348, -0.294, 0.0662), (-0.122, 0.118, -0.0295)),
    ((0.0798, -0.0370, 0.0023), (0.0866, -0.106, 0.0305), (-0.0127, 0.0169, -0.0051)),
)
_JOHANSSON_K_ARRAY = np.array(_JOHANSSON_K)
_JOHANSSON_C_ARRAY = np.array(_JOHANSSON_C)


def smith_wsgg_emissivity(temperature, pressure_path_length, case="pw/pc=2", *, check=True):
    r"""Total emissivity of CO2/H2O by the WSGG model of Smith, Shen & Friedman (1982).

    .. math:: \varepsilon_g = \sum_{i=1}^{3} a_i(T)[1 - e^{-\kappa_i pL}], \quad
              a_i = b_{i1}10^{-1} + b_{i2}10^{-4}T + b_{i3}10^{-7}T^2 + b_{i4}10^{-11}T^3

    Parameters
    ----------
    temperature : float or array, K
    pressure_path_length : float or array, Pa m
        :math:`(p_w + p_c)L` for mixtures, or the partial pressure of the single species
        times the path length.
    case : str
        ``"pw/pc=1"``, ``"pw/pc=2"`` (natural gas products), ``"co2"``, ``"h2o"``,
        ``"h2o, pw=1atm"``.
    check : bool
        Warn outside 600-2400 K and 0.001-10 atm m.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(smith_wsgg_emissivity(1200.0, 0.2 * 101325, "pw/pc=1")), 3)
    0.239
    >>> round(float(smith_wsgg_emissivity(1200.0, 0.2 * 101325, "pw/pc=2")), 3)
    0.263

    References
    ----------
    T.F. Smith, Z.F. Shen, J.N. Friedman, J. Heat Transfer 104 (1982) 602-608.
    """
    if case not in _SMITH:
        raise InputError("gas_radiation.case", case, "one of " + ", ".join(_SMITH))
    T = np.asarray(temperature, dtype=float)
    pl = np.asarray(pressure_path_length, dtype=float) / ATM
    if check:
        check_positive("temperature", T, "K")
        check_nonnegative("pressure_path_length", pl, "atm m")
        warn_out_of_range(
            "T [K]",
            T,
            600.0,
            2400.0,
            "Smith et al. (1982) WSGG",
            closure="gas_emissivity.smith1982",
        )
    eps = np.zeros(np.broadcast(T, pl).shape)
    for kappa, b1, b2, b3, b4 in _SMITH[case]:
        a = b1 * 1e-1 + b2 * 1e-4 * T + b3 * 1e-7 * T**2 + b4 * 1e-11 * T**3
        eps = eps + a * (1.0 - np.exp(-kappa * pl))
    return eps


def _johansson_weights(temperature, mr):
    """Weights a_i (4, ...) of Johansson et al. (2011) at ``temperature`` (K), MR in [0.125, 2]."""
    tr = np.asarray(temperature, dtype=float) / 1200.0
    out = []
    for cij in _JOHANSSON_C:
        a = 0.0
        for j in range(3):
            a = a + (cij[0][j] + cij[1][j] * mr + cij[2][j] * mr**2) * tr**j
        out.append(a)
    return np.stack(np.broadcast_arrays(*out))


def _johansson_ratio(p_h2o, p_co2):
    """Molar ratio MR = p_w/p_c (2 without CO2), not clipped."""
    pw = np.asarray(p_h2o, dtype=float)
    pc = np.asarray(p_co2, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(pc > 0, pw / np.where(pc > 0, pc, 1.0), 2.0)


def johansson_wsgg_emissivity(temperature, p_h2o, p_co2, path_length, *, check=True):
    r"""Total emissivity of CO2/H2O by the 4-grey-gas WSGG of Johansson et al. (2011).

    .. math:: \varepsilon_g = \sum_{i=1}^{4} a_i [1 - e^{-\kappa_i (p_w + p_c) L}],\quad
              \kappa_i = k_{1i} + k_{2i} MR,\quad
              a_i = \sum_{j=1}^{3} (c_{1ij} + c_{2ij} MR + c_{3ij} MR^2)(T/1200)^{j-1}

    Parameters
    ----------
    temperature : float or array, K
    p_h2o, p_co2 : float or array, Pa
        Partial pressures.
    path_length : float or array, m
        Mean beam length.
    check : bool
        Warn outside MR 0.125-2 and 500-2500 K. MR is clipped to [0.125, 2] for evaluation.

    Returns
    -------
    float or array, -
        Zero where there is no CO2 and no H2O.

    Examples
    --------
    >>> p = 0.1 * 101325
    >>> round(float(johansson_wsgg_emissivity(1200.0, p, p, 1.0)), 3)
    0.236

    References
    ----------
    R. Johansson, B. Leckner, K. Andersson, F. Johnsson, Combust. Flame 158 (2011) 893-901.
    """
    T = np.asarray(temperature, dtype=float)
    if check:
        check_nonnegative("path_length", path_length, "m")
    pw = np.asarray(p_h2o, dtype=float) / ATM
    pc = np.asarray(p_co2, dtype=float) / ATM
    ptot = pw + pc
    with np.errstate(divide="ignore", invalid="ignore"):
        mr_raw = np.where(pc > 0, pw / np.where(pc > 0, pc, 1.0), 2.0)
    if check:
        check_positive("temperature", T, "K")
        check_nonnegative("p_h2o", pw)
        check_nonnegative("p_co2", pc)
        if np.any(ptot > 0):
            # MR to 9 decimals: a methane flame's 2 (CO2 + 2 H2O) is inside, not round-off above
            mr_shown = np.round(mr_raw[...], 9)
            for what, v, lo, hi in (("MR", mr_shown, 0.125, 2.0), ("T [K]", T, 500.0, 2500.0)):
                warn_out_of_range(
                    what,
                    v,
                    lo,
                    hi,
                    "Johansson et al. (2011) WSGG",
                    closure="gas_emissivity.johansson2011",
                )
    mr = np.minimum(np.maximum(mr_raw, 0.125), 2.0)  # np.clip without its overhead
    tr = T / 1200.0
    pl = ptot * np.asarray(path_length, dtype=float)
    shape = np.broadcast(T, pl, mr).shape
    # the four grey gases on a leading axis; their weights' powers of T/1200 summed over the
    # gases first (sum_j (sum_i c_ij (1 - e^-k_i pL)) tr^j: the composition's part worked out
    # once where the composition is one for all temperatures)
    dims = (1,) * max(np.ndim(pl), np.ndim(mr))
    k = _JOHANSSON_K_ARRAY.reshape((4, 2) + dims)
    c = _JOHANSSON_C_ARRAY.reshape((4, 3, 3) + dims)
    kappa = k[:, 0] + k[:, 1] * mr
    coeff = c[:, 0] + c[:, 1] * mr + c[:, 2] * mr**2  # (4, j, ...)
    b = (coeff * (1.0 - np.exp(-kappa * pl))[:, None]).sum(0)  # (j, ...)
    eps = b[0] + b[1] * tr
    eps += b[2] * tr**2
    return eps if eps.shape == shape else np.array(np.broadcast_to(eps, shape))


def gorog_mean_beam_length(diameter, bed_depth):
    r"""Mean beam length of the kiln freeboard, :math:`L_e = 0.95\,D\,(1 - h/D)`.

    Parameters
    ----------
    diameter : float or array, m
        Kiln inner diameter, > 0.
    bed_depth : float or array, m
        Bed depth at the middle of the chord, in [0, D).

    Returns
    -------
    float or array, m

    Examples
    --------
    >>> round(float(gorog_mean_beam_length(0.4, 0.05)), 4)
    0.3325

    References
    ----------
    J.P. Gorog, J.K. Brimacombe, T.N. Adams, Metall. Trans. B 12B (1981) 55-70, eq. 50.
    """
    check_positive("diameter", diameter, "m")
    D = np.asarray(diameter, dtype=float)
    check_range("bed_depth/diameter", np.asarray(bed_depth) / D, 0.0, 1.0, closed_low=True)
    return 0.95 * D * (1.0 - np.asarray(bed_depth, dtype=float) / D)


def soot_emissivity(volume_fraction, temperature, path_length):
    r"""Emissivity of the soot of a luminous flame, grey with the Planck-mean absorption.

    .. math:: \kappa_s = \frac{3.72\,C_0}{C_2}\,f_v\,T \approx 1810\,f_v T\ \mathrm{m^{-1}},
              \qquad \varepsilon_s = 1 - e^{-\kappa_s L}

    with :math:`C_0 = 7` (the soot optical constant of the Rayleigh limit) and :math:`C_2` =
    0.014388 m K, the second radiation constant.

    Parameters
    ----------
    volume_fraction : float or array
        Soot volume fraction :math:`f_v` (-), >= 0. Natural-gas flames: about 1e-8 to 1e-7;
        oil and coal flames up to 1e-6.
    temperature : float or array
        Flame (gas) temperature (K), > 0.
    path_length : float or array
        Mean beam length (m), >= 0.

    Returns
    -------
    float or array
        :math:`\varepsilon_s` (-), in [0, 1).

    Examples
    --------
    >>> round(float(soot_emissivity(5e-8, 1800.0, 0.35)), 3)  # flames.md section 4
    0.055
    >>> float(soot_emissivity(0.0, 1800.0, 0.35))
    0.0

    References
    ----------
    Sazhin (1994), An approximation for the absorption coefficient of soot in a radiating gas,
    Fluent Europe; Modest, Radiative Heat Transfer, 3rd ed. (2013), section 11.8 (Planck-mean
    absorption of small soot particles); team notes reference/flames.md section 4.
    """
    f_v = np.asarray(volume_fraction, dtype=float)
    T = np.asarray(temperature, dtype=float)
    L = np.asarray(path_length, dtype=float)
    check_nonnegative("soot volume fraction", float(np.min(f_v)))
    check_positive("temperature", float(np.min(T)), "K")
    check_nonnegative("path_length", float(np.min(L)), "m")
    kappa = 3.72 * 7.0 / 0.014388 * f_v * T
    return -np.expm1(-kappa * L)


def particle_absorption_coefficient(number_density, diameter, efficiency=1.0):
    r"""Absorption coefficient of a cloud of large particles (burning coal, char), 1/m.

    .. math:: \kappa_p = \sum_i Q_{abs}\, N_i\, \frac{\pi d_i^2}{4}

    Coal and char particles are large next to the infrared wavelengths (:math:`x = \pi
    d/\lambda \gg 1`): each absorbs what falls on its projected area times :math:`Q_{abs}`
    (about 1, their emissivity 0.8-1; ash-rich particles 0.5-0.7). Scattering is not counted.

    Parameters
    ----------
    number_density : float or array, 1/m3
        Particles per unit volume of each class, >= 0 (classes on the last axis).
    diameter : float or array, m
        Diameter of each class, >= 0 (same shape, or broadcast).
    efficiency : float
        Absorption efficiency :math:`Q_{abs}`, in [0, 1].

    Returns
    -------
    float or array, 1/m
        Summed over the last axis.

    Examples
    --------
    1.5e8 particles of 50 um per m3 (about 0.6 kg/s of coal in 50 m3/s of flame gas):

    >>> round(float(particle_absorption_coefficient(1.5e8, 50e-6)), 4)
    0.2945

    References
    ----------
    M.F. Modest, Radiative Heat Transfer, 3rd ed. (2013), ch. 12 (large-particle limit);
    team notes reference/cement_lime.md section 5.5 (Q_abs about 1, OpenFOAM's coal
    tutorial emissivity 1).
    """
    n = np.asarray(number_density, dtype=float)
    d = np.asarray(diameter, dtype=float)
    check_nonnegative("particle number density", float(np.min(n)))
    check_nonnegative("particle diameter", float(np.min(d)), "m")
    check_range(
        "particle absorption efficiency", efficiency, 0.0, 1.0, closed_low=True, closed_high=True
    )
    kappa = efficiency * n * np.pi * d**2 / 4.0
    return np.sum(kappa, axis=-1) if kappa.ndim else float(kappa)


def particle_cloud_emissivity(absorption_coefficient, path_length):
    r"""Grey emissivity of a particle cloud (or any grey absorber) over a path, -.

    .. math:: \varepsilon_p = 1 - e^{-\kappa_p L}

    Parameters
    ----------
    absorption_coefficient : float or array, 1/m
        :math:`\kappa_p` (:func:`particle_absorption_coefficient`), >= 0.
    path_length : float or array, m
        Mean beam length, >= 0.

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(float(particle_cloud_emissivity(0.2945, 2.0)), 4)
    0.4451

    References
    ----------
    Beer-Lambert over the mean beam length (Hottel & Sarofim, Radiative Transfer, 1967);
    team notes reference/cement_lime.md section 5.5.
    """
    k = np.asarray(absorption_coefficient, dtype=float)
    L = np.asarray(path_length, dtype=float)
    check_nonnegative("particle absorption coefficient", float(np.min(k)), "1/m")
    check_nonnegative("path_length", float(np.min(L)), "m")
    return -np.expm1(-k * L)


def combined_emissivity(eps_gas, eps_soot):
    r"""Emissivity of a gas and the soot in it, each grey and independent.

    .. math:: \varepsilon = \varepsilon_g + \varepsilon_s - \varepsilon_g\,\varepsilon_s

    Parameters
    ----------
    eps_gas, eps_soot : float or array
        Emissivities (-) in [0, 1].

    Returns
    -------
    float or array
        The combined emissivity (-).

    Examples
    --------
    >>> round(combined_emissivity(0.2, 0.055), 3)
    0.244

    References
    ----------
    Hottel & Sarofim, Radiative Transfer (1967): overlap of independent grey absorbers; team
    notes reference/flames.md section 4.
    """
    return eps_gas + eps_soot - eps_gas * eps_soot


WSGG_MODELS = ("johansson2011", "smith1982")


@dataclass(frozen=True)
class WsggBands:
    r"""The grey gases of a WSGG model at one gas state (partial pressures, path length).

    ``model`` (``johansson2011`` or ``smith1982``); ``emissivity``: the emissivity of each
    grey gas, :math:`1 - e^{-\kappa_i pL}` (shape ``(n_gases, ...)``); ``ratio``: the molar
    ratio :math:`p_w/p_c` the Johansson weights are evaluated at (clipped to 0.125-2; None
    for Smith's ``pw/pc=2`` set). :meth:`weights` gives the weights :math:`a_i(T)` at any
    temperature: at the gas temperature they make the emissivity, at a surface temperature the
    gas's absorptivity for that surface's radiation (:meth:`total`). The clear gas (the
    windows) has the weight :math:`1 - \sum_i a_i`.
    """

    model: str
    emissivity: np.ndarray
    ratio: np.ndarray | None = None

    def weights(self, temperature) -> np.ndarray:
        """Weights a_i(T) (-), shape ``(n_gases,) + broadcast shape``: clipped to >= 0 with
        a sum of at most 1 (the polynomials are fitted over 500-2500 K / 600-2400 K)."""
        T = np.asarray(temperature, dtype=float)
        if self.model == "johansson2011":
            a = _johansson_weights(T, self.ratio)
        else:
            a = np.stack(
                np.broadcast_arrays(
                    *(
                        b1 * 1e-1 + b2 * 1e-4 * T + b3 * 1e-7 * T**2 + b4 * 1e-11 * T**3
                        for _, b1, b2, b3, b4 in _SMITH["pw/pc=2"]
                    )
                )
            )
        a = np.maximum(a, 0.0)
        total = a.sum(axis=0)
        return a / np.maximum(total, 1.0)

    def total(self, temperature) -> np.ndarray:
        r""":math:`\sum_i a_i(T)\,\varepsilon_i` (-): the emissivity at the gas temperature,
        the absorptivity for a black surface at ``temperature``."""
        return (self.weights(temperature) * self.emissivity).sum(axis=0)


def wsgg_bands(model, p_h2o, p_co2, path_length) -> WsggBands:
    r"""The grey gases of a WSGG model for CO2/H2O at partial pressures ``p_h2o``, ``p_co2``
    (Pa) over the beam length ``path_length`` (m).

    ``model``: ``johansson2011`` (4 grey gases, any :math:`p_w/p_c` in 0.125-2) or
    ``smith1982`` (3 grey gases, :math:`p_w/p_c = 2`, the natural-gas products). The weights
    at the gas temperature reproduce :func:`johansson_wsgg_emissivity` and
    :func:`smith_wsgg_emissivity` (``pw/pc=2``) exactly; at a surface temperature they give
    the absorptivity :math:`\alpha_g(T_s) = \sum_i a_i(T_s)[1 - e^{-\kappa_i pL}]`.

    Parameters
    ----------
    model : str, -
        ``johansson2011`` or ``smith1982``.
    p_h2o, p_co2 : float or array, Pa
        Partial pressures of water vapour and carbon dioxide.
    path_length : float or array, m
        Mean beam length of the freeboard.

    Returns
    -------
    WsggBands, -
        The grey gases: their emissivities (-) and weights at any temperature (K).

    Examples
    --------
    >>> p = 0.1 * 101325
    >>> b = wsgg_bands("johansson2011", p, p, 1.0)
    >>> round(float(b.total(1200.0)), 3)  # the emissivity, as johansson_wsgg_emissivity
    0.236
    >>> round(float(b.total(800.0)), 3)  # absorptivity for a surface at 800 K: higher
    0.307

    References
    ----------
    M.F. Modest, Radiative Heat Transfer, 3rd ed. (2013), section 11.10 (WSGG with surface
    weights at the emitter's temperature); Johansson et al. (2011); Smith et al. (1982);
    closures.md 3b-3d.
    """
    if model not in WSGG_MODELS:
        raise InputError("closures.gas_emissivity", model, "one of " + ", ".join(WSGG_MODELS))
    pw = np.asarray(p_h2o, dtype=float) / ATM
    pc = np.asarray(p_co2, dtype=float) / ATM
    pl = (pw + pc) * np.asarray(path_length, dtype=float)
    if model == "johansson2011":
        mr = np.clip(_johansson_ratio(pw, pc), 0.125, 2.0)
        kappa = [k1 + k2 * mr for k1, k2 in _JOHANSSON_K]
        eps = np.stack(np.broadcast_arrays(*(-np.expm1(-k * pl) for k in kappa)))
        return WsggBands(model, eps, mr)
    eps = np.stack(np.broadcast_arrays(*(-np.expm1(-row[0] * pl) for row in _SMITH["pw/pc=2"])))
    return WsggBands(model, eps, None)
