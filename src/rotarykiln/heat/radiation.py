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

__all__ = ["STEFAN_BOLTZMANN", "freeboard_radiation"]

STEFAN_BOLTZMANN = 5.670374419e-8  # W/(m2 K4)
_EPS_CAP = 1.0 - 1e-9


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
    with np.errstate(invalid="ignore", divide="ignore"):
        Jw = np.where(det > 0, (r1 * a22 + Gwb * r2) / det, r1 / np.where(a11 > 0, a11, 1.0))
        Jb = np.where(det > 0, (a11 * r2 + Gwb * r1) / det, r2 / np.where(a22 > 0, a22, 1.0))
    # net absorbed = sum of inflows to the radiosity node except the surface one
    q_wall = Ggw * (Eg - Jw) + Gwb * (Jb - Jw)
    q_bed = Ggb * (Eg - Jb) + Gwb * (Jw - Jb)
    return q_wall, q_bed
