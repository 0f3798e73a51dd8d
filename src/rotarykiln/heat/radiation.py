r"""Grey radiative exchange in the freeboard: gas, exposed wall and exposed bed surface.

Per unit kiln length, the exposed wall (arc :math:`A_w`) and the bed surface (chord
:math:`A_b`) exchange with a grey gas of emissivity :math:`\varepsilon_g` (absorptivity equal
to emissivity) through the electrical network of Holman (Fig. 8-39), as in SimCem:

- blackbody potentials :math:`E_i = \sigma T_i^4`, radiosities :math:`J_w, J_b`;
- surface conductances :math:`G_i = \varepsilon_i A_i/(1-\varepsilon_i)`;
- gas-surface conductances :math:`\varepsilon_g A_i`;
- direct wall-bed conductance :math:`A_b F_{bw}(1-\varepsilon_g)`, :math:`F_{bw} = 1` (the
  chord sees only the arc).

The two radiosity balances are solved in closed form; the net heat absorbed by wall and bed and
lost by the gas sum to zero exactly.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import check_nonnegative, check_positive, check_range

__all__ = [
    "STEFAN_BOLTZMANN",
    "freeboard_radiation",
    "freeboard_radiation_bands",
    "freeboard_radiation_paths",
]

STEFAN_BOLTZMANN = 5.670374419e-8  # W/(m2 K4)
_EPS_CAP = 1.0 - 1e-9
#: Cap of the emissivity of one grey gas of a WSGG set (as the grey gas's 0.95).
EPS_BAND_MAX = 0.95


def freeboard_radiation(
    t_gas,
    t_wall,
    t_bed,
    eps_gas,
    eps_wall,
    eps_bed,
    wall_area,
    bed_area,
    *,
    check=True,
):
    r"""Net radiative heat absorbed by the exposed wall and the bed surface (grey network).

    .. math::
        \frac{E_w - J_w}{R_w} + \frac{E_g - J_w}{R_{gw}} + \frac{J_b - J_w}{R_{wb}} = 0,\quad
        \frac{E_b - J_b}{R_b} + \frac{E_g - J_b}{R_{gb}} + \frac{J_w - J_b}{R_{wb}} = 0

    with :math:`R_i = (1-\varepsilon_i)/(\varepsilon_i A_i)`,
    :math:`R_{gi} = 1/(\varepsilon_g A_i)`, :math:`R_{wb} = 1/(A_b(1-\varepsilon_g))`.

    Parameters
    ----------
    t_gas, t_wall, t_bed : float or array, K
    eps_gas : float or array, -
        Gas emissivity in [0, 1).
    eps_wall, eps_bed : float or array, -
        Surface emissivities in (0, 1].
    wall_area, bed_area : float or array, m2/m
        Exposed wall arc and bed chord per unit kiln length.
    check : bool

    Returns
    -------
    q_wall, q_bed : float or array, W/m
        Net heat absorbed by the exposed wall and by the bed surface; the gas loses
        ``q_wall + q_bed``.

    Examples
    --------
    Transparent gas, black bed: wall to bed :math:`\sigma(T_w^4-T_b^4)/(R_w + 1/A_b)`.

    >>> qw, qb = freeboard_radiation(1000.0, 1200.0, 900.0, 0.0, 0.8, 1.0, 2.0, 0.5)
    >>> round(float(qb), 0), round(float(qw + qb), 6)
    (37825.0, 0.0)

    References
    ----------
    J.P. Holman, Heat Transfer, ch. 8 (gas-surface network); SimCem kiln.hpp
    (twobodygas_network); closures.md 3b.
    """
    if check:
        check_range("eps_gas", eps_gas, 0.0, 1.0, closed_low=True)
        check_range("eps_wall", eps_wall, 0.0, 1.0, closed_high=True)
        check_range("eps_bed", eps_bed, 0.0, 1.0, closed_high=True)
        check_positive("t_gas", t_gas, "K")
        check_positive("t_wall", t_wall, "K")
        check_positive("t_bed", t_bed, "K")
        check_nonnegative("wall_area", wall_area, "m2/m")
        check_nonnegative("bed_area", bed_area, "m2/m")
    s = STEFAN_BOLTZMANN
    Eg = s * np.asarray(t_gas, dtype=float) ** 4
    Ew = s * np.asarray(t_wall, dtype=float) ** 4
    Eb = s * np.asarray(t_bed, dtype=float) ** 4
    gw, gb, wb = _network(Eg, Ew, Eb, eps_gas, eps_wall, eps_bed, wall_area, bed_area)
    return gw - wb, gb + wb


def _network(Eg, Ew, Eb, eps_gas, eps_wall, eps_bed, wall_area, bed_area):
    """Path flows (W/m) of the grey network: gas -> wall, gas -> bed, wall -> bed (direct),
    for the emissive powers ``Eg``, ``Ew``, ``Eb`` (W/m2) of one grey gas (or band)."""
    ew = np.minimum(eps_wall, _EPS_CAP)
    eb = np.minimum(eps_bed, _EPS_CAP)
    Gw = ew * wall_area / (1.0 - ew)
    Gb = eb * bed_area / (1.0 - eb)
    Ggw = eps_gas * wall_area
    Ggb = eps_gas * bed_area
    Gwb = bed_area * (1.0 - eps_gas)
    # [Gw + Ggw + Gwb, -Gwb; -Gwb, Gb + Ggb + Gwb] [Jw, Jb] = [Gw Ew + Ggw Eg, Gb Eb + Ggb Eg]
    a11 = Gw + Ggw + Gwb
    a22 = Gb + Ggb + Gwb
    r1 = Gw * Ew + Ggw * Eg
    r2 = Gb * Eb + Ggb * Eg
    det = a11 * a22 - Gwb * Gwb
    # A surface of zero area (an empty kiln has no bed chord, a full one no exposed wall)
    # drops out of the network: its radiosity multiplies zero conductances only, and the
    # other node exchanges with the gas alone (without this, det = 0 gives 0/0).
    if np.all(det > 0):  # both surfaces present (the same values as below, fewer operations)
        Jw = (r1 * a22 + Gwb * r2) / det
        Jb = (a11 * r2 + Gwb * r1) / det
    else:
        with np.errstate(invalid="ignore", divide="ignore"):
            Jw = np.where(det > 0, (r1 * a22 + Gwb * r2) / det, r1 / np.where(a11 > 0, a11, 1.0))
            Jb = np.where(det > 0, (a11 * r2 + Gwb * r1) / det, r2 / np.where(a22 > 0, a22, 1.0))
    # net absorbed = sum of inflows to the radiosity node except the surface one
    return Ggw * (Eg - Jw), Ggb * (Eg - Jb), Gwb * (Jw - Jb)


def freeboard_radiation_paths(
    t_gas,
    t_wall,
    t_bed,
    eps_gas,
    eps_wall,
    eps_bed,
    wall_area,
    bed_area,
    bands=None,
):
    r"""The radiation of the freeboard network split by path (W/m): gas -> exposed wall, gas
    -> bed surface and exposed wall -> bed surface (direct, through the gas).

    ``bands``: None for one grey gas of emissivity ``eps_gas`` (as
    :func:`freeboard_radiation`), or a :class:`~rotarykiln.heat.gas_radiation.WsggBands` for
    the non-grey exchange of :func:`freeboard_radiation_bands` (``eps_gas`` then ignored).
    The net heat absorbed by the wall is ``gas_wall - wall_bed``, by the bed
    ``gas_bed + wall_bed``.

    Parameters
    ----------
    t_gas, t_wall, t_bed : float or array, K
    eps_gas : float or array, -
        Grey gas emissivity (unused with ``bands``).
    eps_wall, eps_bed : float or array, -
        Grey surface emissivities in (0, 1].
    wall_area, bed_area : float or array, m2/m
    bands : WsggBands or None, -
        The grey gases of a WSGG model at the gas state, or None (one grey gas).

    Returns
    -------
    gas_wall, gas_bed, wall_bed : float or array, W/m
        The three path flows; their signs follow the temperature differences.

    Examples
    --------
    >>> gw, gb, wb = freeboard_radiation_paths(1000.0, 1200.0, 900.0, 0.0, 0.8, 1.0, 2.0, 0.5)
    >>> abs(float(gw)), float(gb), round(float(wb), 0)
    (0.0, 0.0, 37825.0)

    References
    ----------
    H.C. Hottel, A.F. Sarofim, Radiative Transfer (1967), the enclosure network; M.F. Modest,
    Radiative Heat Transfer, 3rd ed. (2013), section 11.10.
    """
    s = STEFAN_BOLTZMANN
    tg, tw, tb = (np.asarray(t, dtype=float) for t in (t_gas, t_wall, t_bed))
    if bands is None:
        return _network(
            s * tg**4, s * tw**4, s * tb**4, eps_gas, eps_wall, eps_bed, wall_area, bed_area
        )
    return _band_paths(tg, tw, tb, bands, eps_wall, eps_bed, wall_area, bed_area)


def _band_paths(tg, tw, tb, bands, eps_wall, eps_bed, wall_area, bed_area, soot=None):
    s = STEFAN_BOLTZMANN
    ag, aw, ab = bands.weights(tg), bands.weights(tw), bands.weights(tb)
    eps = bands.emissivity
    if soot is not None:  # grey soot in every grey gas and in the windows
        eps = eps + soot - eps * soot
    eps = np.minimum(eps, EPS_BAND_MAX)
    Eg, Ew, Eb = s * tg**4, s * tw**4, s * tb**4
    gw, gb, wb = _network(ag * Eg, aw * Ew, ab * Eb, eps, eps_wall, eps_bed, wall_area, bed_area)
    gw, gb, wb = gw.sum(axis=0), gb.sum(axis=0), wb.sum(axis=0)
    # the windows (clear gas, weight 1 - sum a_i): the surfaces see each other through them
    cg, cw, cb = 1.0 - ag.sum(axis=0), 1.0 - aw.sum(axis=0), 1.0 - ab.sum(axis=0)
    eps0 = 0.0 if soot is None else np.minimum(soot, EPS_BAND_MAX)
    g0w, g0b, w0b = _network(
        cg * Eg, cw * Ew, cb * Eb, eps0, eps_wall, eps_bed, wall_area, bed_area
    )
    return gw + g0w, gb + g0b, wb + w0b


def freeboard_radiation_bands(
    t_gas,
    t_wall,
    t_bed,
    bands,
    eps_wall,
    eps_bed,
    wall_area,
    bed_area,
    *,
    soot=None,
    check=True,
):
    r"""Net radiative heat absorbed by the exposed wall and the bed surface, non-grey gas.

    The grey network of :func:`freeboard_radiation` solved once for every grey gas of a WSGG
    model and once for its windows (the clear gas), and summed (Modest 2013, section 11.10):
    in grey gas *i* (emissivity :math:`\varepsilon_i = 1 - e^{-\kappa_i pL}`) the gas emits
    :math:`a_i(T_g)\sigma T_g^4` and each surface :math:`a_i(T_s)\sigma T_s^4`; in the windows
    (weight :math:`1 - \sum_i a_i(T)`) the gas is transparent. The weights at the surface
    temperature make the gas absorb the surface radiation with the absorptivity
    :math:`\alpha_g(T_s) = \sum_i a_i(T_s)\varepsilon_i` (Hottel's absorptivity in WSGG form),
    not with its emissivity at the gas temperature; and the gas radiation that a grey
    surface reflects stays in the bands the gas absorbs. With grey surfaces and one band of
    weight 1 it is :func:`freeboard_radiation`.

    Parameters
    ----------
    t_gas, t_wall, t_bed : float or array, K
    bands : :class:`~rotarykiln.heat.gas_radiation.WsggBands`, -
        The grey gases at the gas state (emissivities shaped ``(n_gases,) + cells``).
    eps_wall, eps_bed : float or array, -
        Grey surface emissivities in (0, 1].
    wall_area, bed_area : float or array, m2/m
    soot : float or array, optional
        Emissivity of grey soot (-), added to every grey gas and to the windows.
    check : bool

    Returns
    -------
    q_wall, q_bed : float or array, W/m
        Net heat absorbed; the gas loses ``q_wall + q_bed``.

    Examples
    --------
    Gas at 1100 K over surfaces at 950 K: the non-grey exchange passes less than the grey
    gas of the same emissivity (the gas absorbs the cooler surfaces' radiation more
    strongly than it emits at its own temperature).

    >>> from rotarykiln.heat.gas_radiation import wsgg_bands
    >>> b = wsgg_bands("johansson2011", 0.079 * 101325, 0.039 * 101325, 0.33)
    >>> eg = float(b.total(1100.0))
    >>> grey = sum(freeboard_radiation(1100.0, 950.0, 950.0, eg, 0.85, 0.9, 1.0, 0.3))
    >>> banded = sum(freeboard_radiation_bands(1100.0, 950.0, 950.0, b, 0.85, 0.9, 1.0, 0.3))
    >>> round(float(banded / grey), 2)
    0.78

    References
    ----------
    M.F. Modest, Radiative Heat Transfer, 3rd ed. (2013), sections 11.10 and 19.4 (WSGG in
    enclosures); H.C. Hottel, A.F. Sarofim, Radiative Transfer (1967); closures.md 3b.
    """
    if check:
        check_range("eps_wall", eps_wall, 0.0, 1.0, closed_high=True)
        check_range("eps_bed", eps_bed, 0.0, 1.0, closed_high=True)
        check_positive("t_gas", t_gas, "K")
        check_positive("t_wall", t_wall, "K")
        check_positive("t_bed", t_bed, "K")
        check_nonnegative("wall_area", wall_area, "m2/m")
        check_nonnegative("bed_area", bed_area, "m2/m")
    tg, tw, tb = (np.asarray(t, dtype=float) for t in (t_gas, t_wall, t_bed))
    gw, gb, wb = _band_paths(tg, tw, tb, bands, eps_wall, eps_bed, wall_area, bed_area, soot)
    return gw - wb, gb + wb
