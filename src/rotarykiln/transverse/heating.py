r"""Solid-to-solid heating of shale by hot ash in a bed cell (Van Puyvelde 1999, eqs 9.1-9.7).

Particles exchange heat only by natural convection with the gas of their cell (taken at the
mean solids temperature of the cell) and by radiation from hot ash to cold shale, scaled by the
extent of mixing of the cell; no particle-particle conduction, no wall or freeboard exchange.

Natural convection from a sphere, eq 9.2 as reconstructed from the garbled OCR (the Churchill
form quoted by Thomas 1992, with :math:`\tilde L = \pi d_p/2` and the conduction limit
:math:`a^2 = \pi` for spheres):

.. math::

    Nu_{\tilde L} = \frac{h\tilde L}{k} = \left[1.77 + 0.331\,b\,Ra_{\tilde L}^{1/6}\right]^2,
    \qquad b = \frac{1.17}{\left[1 + (0.5/Pr)^{9/16}\right]^{8/27}}

Radiation to shale class i (eq 9.5), with the extent of mixing :math:`l/l_f` of the cell:

.. math::

    Q_{r,i} = \sigma\,\varepsilon\,A_{Rad}\,\frac{l}{l_f}\,\frac{A_{sh,i}}{A_{sh}}
              \left(\bar T_{ash}^4 - T_{sh,i}^4\right), \qquad A_{Rad} = \min(A_{ash}, A_{sh})

Energy balance of a cell (:func:`cell_heat_exchange`): ``balance="pairwise"`` (default) puts
the gas at the conductance-weighted mean temperature, so the convective gains and losses cancel
exactly, and gives every joule the shale receives by radiation from the ash classes in
proportion to their area. ``balance="smaller"`` is the thesis's rule: gas at the mass-weighted
mean temperature, ash-side radiation by eq 9.5 with the roles swapped, and the side of larger
magnitude scaled down to the smaller. Both conserve energy; "smaller" transfers less heat.
Over a time step every exchange is integrated exponentially (conductance
:math:`G = C(1 - e^{-hA\Delta t/C})/\Delta t`) so that no class overshoots the temperature it
relaxes to, whatever the step.
"""

from __future__ import annotations

import numpy as np

from rotarykiln.errors import InputError, check_nonnegative, check_positive, check_range

__all__ = [
    "STEFAN_BOLTZMANN",
    "air_properties",
    "cell_heat_exchange",
    "natural_convection_coefficient",
    "radiation_to_shale",
    "thomas_sphere_nusselt",
]

STEFAN_BOLTZMANN = 5.670374419e-8
G = 9.80665


def air_properties(temperature, pressure: float = 101325.0):
    r"""Conductivity, kinematic viscosity, diffusivity and Prandtl number of air.

    Sutherland laws: :math:`\mu = 1.716\times10^{-5}(T/273.15)^{1.5}\,383.55/(T + 110.4)`,
    :math:`k = 0.0241\,(T/273.15)^{1.5}\,467.15/(T + 194)`; ideal gas; c_p from a linear fit
    (1005 J/(kg K) at 300 K, 1140 at 1000 K). The thesis does not name its gas or its property
    source; air is assumed.

    Parameters
    ----------
    temperature : float or array, K
    pressure : float, Pa

    Returns
    -------
    tuple of float or array
        k [W/(m K)], nu [m2/s], alpha [m2/s], Pr [-].

    Examples
    --------
    >>> k, nu, a, pr = air_properties(300.0)
    >>> round(float(k), 4), round(float(nu) * 1e6, 1), round(float(pr), 2)
    (0.0262, 15.7, 0.71)

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, ch. 9 (air
    properties for eqs 9.1-9.2).
    """
    t = np.asarray(temperature, dtype=float)
    check_positive("temperature", t, "K")
    mu = 1.716e-5 * (t / 273.15) ** 1.5 * (273.15 + 110.4) / (t + 110.4)
    k = 0.0241 * (t / 273.15) ** 1.5 * (273.15 + 194.0) / (t + 194.0)
    rho = pressure / (287.05 * t)
    cp = 1005.0 + (t - 300.0) * (135.0 / 700.0)
    nu = mu / rho
    alpha = k / (rho * cp)
    return k, nu, alpha, nu / alpha


def thomas_sphere_nusselt(rayleigh, prandtl):
    r"""Natural-convection Nusselt number of a sphere on :math:`\tilde L = \pi d/2` (eq 9.2).

    .. math:: Nu = \left[1.77 + 0.331\,b\,Ra^{1/6}\right]^2, \quad
              b = 1.17/\left[1 + (0.5/Pr)^{9/16}\right]^{8/27}

    Parameters
    ----------
    rayleigh : float or array, -
        Rayleigh number on :math:`\tilde L`, >= 0.
    prandtl : float or array, -

    Returns
    -------
    float or array, -

    Notes
    -----
    Reconstructed (the OCR lost the square and the Greek letters); 0.331·1.17 = 0.387 and
    1.77² = π identify the Churchill-Chu form on the half-perimeter length. Valid Ra < ~1e11.

    Examples
    --------
    >>> round(float(thomas_sphere_nusselt(0.0, 0.7)), 4)
    3.1329

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eq 9.2
    (reconstructed as the Churchill-Chu form: Churchill, S. W., Chu, H. H. S. (1975) Int. J. Heat
    Mass Transfer 18, 1049).
    """
    check_nonnegative("rayleigh", rayleigh)
    check_positive("prandtl", prandtl)
    return _thomas_sphere_nusselt(rayleigh, prandtl)


def _thomas_sphere_nusselt(rayleigh, prandtl):
    ra = np.asarray(rayleigh, dtype=float)
    b = 1.17 / (1.0 + (0.5 / np.asarray(prandtl, dtype=float)) ** (9.0 / 16.0)) ** (8.0 / 27.0)
    return (1.77 + 0.331 * b * ra ** (1.0 / 6.0)) ** 2


def natural_convection_coefficient(d_p, t_particle, t_gas):
    r"""Natural-convection coefficient of a particle in gas, eqs 9.1-9.2.

    .. math:: h = Nu\,k/\tilde L,\quad \tilde L = \pi d_p/2,\quad
              Ra = g\beta|T_p - T_g|\tilde L^3/(\nu\alpha),\quad \beta = 1/T_g

    Parameters
    ----------
    d_p : float or array, m
        Particle size.
    t_particle : float or array, K
    t_gas : float or array, K
        Gas temperature (the cell's mean solids temperature); properties of air at it.

    Returns
    -------
    float or array, W/(m2 K)

    Examples
    --------
    >>> round(float(natural_convection_coefficient(2e-3, 1050.0, 800.0)), 1)
    91.1

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eqs 9.1-9.2.
    """
    check_positive("d_p", d_p, "m")
    check_nonnegative("t_particle", t_particle, "K")
    check_positive("t_gas", t_gas, "K")
    return _natural_convection_coefficient(d_p, t_particle, t_gas)


def _natural_convection_coefficient(d_p, t_particle, t_gas):
    """:func:`natural_convection_coefficient` without the input checks (the grid's inner loop
    calls it every time step with arrays it built itself)."""
    t_g = np.asarray(t_gas, dtype=float)
    k, nu, alpha, pr = air_properties(t_g)
    length = 0.5 * np.pi * np.asarray(d_p, dtype=float)
    ra = G / t_g * np.abs(np.asarray(t_particle, dtype=float) - t_g) * length**3 / (nu * alpha)
    return _thomas_sphere_nusselt(ra, pr) * k / length


def radiation_to_shale(a_ash, t_ash_mean, a_shale_class, t_shale_class, extent, emissivity=0.9):
    r"""Radiative heat flow from the ash of a cell to one shale class, eq 9.5 [W].

    Parameters
    ----------
    a_ash : float or array, m2
        Total ash particle surface in the cell.
    t_ash_mean : float or array, K
        Mean ash temperature.
    a_shale_class : array, m2
        Surface of each shale class (last axis = classes).
    t_shale_class : array, K
        Temperature of each shale class.
    extent : float or array, -
        Extent of mixing of the cell, l/l_f in [0, 1].
    emissivity : float, -
        Soil emissivity (thesis 0.90).

    Returns
    -------
    array, W

    Examples
    --------
    >>> q = radiation_to_shale(1.0, 1000.0, np.array([0.5, 0.5]), np.array([500.0, 500.0]), 1.0)
    >>> round(float(q.sum()), 1)
    47843.8

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS, eq 9.5.
    """
    check_nonnegative("a_ash", a_ash, "m2")
    check_nonnegative("t_ash_mean", t_ash_mean, "K")
    check_nonnegative("a_shale_class", a_shale_class, "m2")
    check_nonnegative("t_shale_class", t_shale_class, "K")
    check_range("extent", extent, 0.0, 1.0, closed_low=True, closed_high=True)
    check_range("emissivity", emissivity, 0.0, 1.0, closed_high=True)
    return _radiation_to_shale(a_ash, t_ash_mean, a_shale_class, t_shale_class, extent, emissivity)


def _radiation_to_shale(a_ash, t_ash_mean, a_shale_class, t_shale_class, extent, emissivity):
    """:func:`radiation_to_shale` without the input checks (inner loop of the grid)."""
    a_sh_cls = np.asarray(a_shale_class, dtype=float)
    a_sh = a_sh_cls.sum(axis=-1, keepdims=True)
    a_rad = np.minimum(np.asarray(a_ash, dtype=float)[..., None], a_sh)
    with np.errstate(invalid="ignore", divide="ignore"):
        share = np.where(a_sh > 0, a_sh_cls / a_sh, 0.0)
    t_ash = np.asarray(t_ash_mean, dtype=float)[..., None]
    e = np.asarray(extent, dtype=float)[..., None]
    return (
        STEFAN_BOLTZMANN
        * emissivity
        * a_rad
        * e
        * share
        * (t_ash**4 - np.asarray(t_shale_class, dtype=float) ** 4)
    )


def _relax(coeff, capacity, dt):
    """Exponentially integrated conductance C(1 - exp(-coeff dt/C))/dt (0 where C = 0)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        x = np.where(capacity > 0, coeff * dt / capacity, 0.0)
        g = np.where(x > 1e-12, -np.expm1(-x) / np.where(x > 0, x, 1.0), 1.0)
    return coeff * g


def cell_heat_exchange(
    mass,
    capacity,
    area,
    temperature,
    d_p,
    extent,
    dt,
    *,
    emissivity: float = 0.9,
    balance: str = "pairwise",
):
    """Heat gained by each (cell, material, class) over a time step [J]; sums to zero per cell.

    Parameters
    ----------
    mass : array (n, 2, K), kg
        Original mass of ash (index 0) and shale (index 1) per class and cell.
    capacity : array (n, 2, K), J/(kg K)
        Apparent heat capacity dH/dT of each element.
    area : array (n, 2, K), m2
        Particle surface of each element.
    temperature : array (n, 2, K), K
    d_p : array (K,), m
        Class sizes.
    extent : array (n,), -
        Extent of mixing l/l_f of each cell, in [0, 1].
    dt : float, s
    emissivity : float, -
    balance : {"pairwise", "smaller"}
        Energy-balancing rule (module docstring).

    Returns
    -------
    array (n, 2, K), J

    Examples
    --------
    >>> m = np.ones((1, 2, 1)); cp = np.full((1, 2, 1), 1000.0); a = np.full((1, 2, 1), 2.0)
    >>> t = np.array([[[1000.0]], [[500.0]]]).reshape(1, 2, 1)
    >>> q = cell_heat_exchange(m, cp, a, t, np.array([2e-3]), np.array([1.0]), 0.1)
    >>> round(float(q.sum()), 9), bool(q[0, 1, 0] > 0)
    (0.0, True)

    References
    ----------
    Van Puyvelde, D. R. (1999) Industrial Rotating Kiln Simulation, PhD thesis, UTS.
    """
    if balance not in ("pairwise", "smaller"):
        raise InputError("heating.balance", balance, "one of 'pairwise', 'smaller'")
    check_positive("dt", dt, "s")
    check_range("emissivity", emissivity, 0.0, 1.0, closed_high=True)
    cap = mass * capacity  # J/K
    m_tot = mass.sum(axis=(1, 2))
    with np.errstate(invalid="ignore", divide="ignore"):
        t_mean = np.where(m_tot > 0, (mass * temperature).sum(axis=(1, 2)) / m_tot, 300.0)
    h = _natural_convection_coefficient(
        d_p[None, None, :], temperature, np.maximum(t_mean, 200.0)[:, None, None]
    )
    g = _relax(h * area, cap, dt)
    if balance == "pairwise":
        gs = g.sum(axis=(1, 2))
        with np.errstate(invalid="ignore", divide="ignore"):
            t_gas = np.where(gs > 0, (g * temperature).sum(axis=(1, 2)) / gs, t_mean)
        q_conv = g * (t_gas[:, None, None] - temperature)
    else:
        q_conv = _balance_smaller(g * (t_mean[:, None, None] - temperature))

    # radiation ash (0) -> shale (1), scaled by the extent of mixing; evaluated on the
    # temperatures after convection (operator splitting: neither step overshoots)
    with np.errstate(invalid="ignore", divide="ignore"):
        temperature = np.where(
            cap > 0, temperature + q_conv * dt / np.where(cap > 0, cap, 1.0), temperature
        )
    a_ash = area[:, 0, :].sum(axis=1)
    a_sh = area[:, 1, :].sum(axis=1)
    c_ash = cap[:, 0, :].sum(axis=1)
    c_sh = cap[:, 1, :].sum(axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        t_ash = np.where(c_ash > 0, (cap[:, 0, :] * temperature[:, 0, :]).sum(1) / c_ash, 0.0)
        t_sh = np.where(c_sh > 0, (cap[:, 1, :] * temperature[:, 1, :]).sum(1) / c_sh, 0.0)
    active = (a_ash > 0) & (a_sh > 0) & (extent > 0)
    q_rad = np.zeros_like(temperature)
    if np.any(active):
        # eq 9.5 written as k_i (T_ash - T_i) with k_i = sigma eps A e share (Ta + Ti)(Ta^2 + Ti^2),
        # then k_i integrated exponentially over the step
        ta = t_ash[:, None]
        ti = temperature[:, 1, :]
        q_unit = _radiation_to_shale(a_ash, 1.0, area[:, 1, :], 0.0, extent, emissivity)
        k_rad = q_unit * (ta + ti) * (ta * ta + ti * ti)
        q_sh = _relax(k_rad, cap[:, 1, :], dt) * (ta - ti)
        if balance == "pairwise":
            safe = np.where(a_ash > 0, a_ash, 1.0)[:, None]
            q_ash = -q_sh.sum(axis=1)[:, None] * (area[:, 0, :] / safe)
        else:
            q_ash = _radiation_to_shale(
                a_sh, t_sh, area[:, 0, :], temperature[:, 0, :], extent, emissivity
            )
            gain, loss = q_sh.sum(axis=1), -q_ash.sum(axis=1)
            with np.errstate(invalid="ignore", divide="ignore"):
                small = np.where(np.abs(gain) < np.abs(loss), gain, loss)
                f_sh = np.where(gain != 0, small / gain, 0.0)
                f_ash = np.where(loss != 0, small / loss, 0.0)
            q_sh = q_sh * f_sh[:, None]
            q_ash = q_ash * f_ash[:, None]
        # the pair may not cross its common temperature within the step
        total = q_sh.sum(axis=1) * dt
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            c_pair = c_ash * c_sh / np.where(c_ash + c_sh > 0, c_ash + c_sh, 1.0)
            limit = np.abs(t_ash - t_sh) * c_pair
            big = np.abs(total) > limit
            scale = np.where(big, limit / np.where(total != 0, np.abs(total), 1.0), 1.0)
        scale = np.where(active, scale, 0.0)
        q_rad[:, 1, :] = q_sh * scale[:, None]
        q_rad[:, 0, :] = q_ash * scale[:, None]
    return (q_conv + q_rad) * dt


def _balance_smaller(q):
    """Scale the gains or the losses of each cell so that they cancel (thesis's rule)."""
    pos = np.where(q > 0, q, 0.0).sum(axis=(1, 2))
    neg = -np.where(q < 0, q, 0.0).sum(axis=(1, 2))
    with np.errstate(invalid="ignore", divide="ignore"):
        f_pos = np.where(pos > neg, neg / np.where(pos > 0, pos, 1), 1.0)
        f_neg = np.where(neg > pos, pos / np.where(neg > 0, neg, 1), 1.0)
    return np.where(q > 0, q * f_pos[:, None, None], q * f_neg[:, None, None])
