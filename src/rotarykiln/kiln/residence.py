r"""Residence-time effects on the conversion of a reacting kiln: plug flow vs segregated flow.

The bed's residence time distribution is the open-open axial dispersion model (Levenspiel;
seed 003 eq. 14) with :math:`\tau = L/u`:

.. math:: E(t) = \frac{1}{2}\sqrt{\frac{Pe}{\pi\,\tau\,t}}
          \exp\!\left[-\frac{Pe\,(\tau - t)^2}{4\,\tau\,t}\right],\qquad Pe = \frac{u L}{D}

and the dispersion coefficient comes from the correlation of Sherritt et al. (2003) (seed 003
eq. 16, SI units, fill X < 0.5):

.. math:: D = 0.0011\,(N/N_c)^{0.39}\,D_k^{1.15}\,d_p^{0.46}\,X^{-0.43}

Each residence-time class :math:`\tau'` crosses the kiln at :math:`L/\tau'` through the
converged kiln's temperature, CO2 and heat-input profiles (frozen: a segregated parcel does not
change them); its conversion is integrated by :func:`rotarykiln.chemistry.plugflow` and the
outlet conversion is the RTD average (:func:`rotarykiln.chemistry.segregated`).

The RTD package of the project (``rotarykiln.rtd``) was not on main when this was written: the
open-open E(t) and the Sherritt correlation are local here and should be replaced by it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotarykiln.chemistry.ratelaws import MOISTURE
from rotarykiln.chemistry.segregated import SegregatedResult, kiln_segregated_conversion
from rotarykiln.errors import InputError, check_positive
from rotarykiln.regimes import critical_speed

__all__ = [
    "sherritt_dispersion_coefficient",
    "open_open_dispersion_rtd",
    "OpenOpenDispersion",
    "ResidenceTimeEffects",
    "residence_time_effects",
]


def sherritt_dispersion_coefficient(omega, radius, particle_diameter, fill):
    r"""Axial dispersion coefficient of the bed, Sherritt et al. (2003), m2/s.

    .. math:: D = 0.0011\,(\omega/\omega_c)^{0.39}\,(2R)^{1.15}\,d_p^{0.46}\,X^{-0.43},
              \quad \omega_c = \sqrt{g/R}

    Parameters
    ----------
    omega : float or array
        Rotation rate, rad/s.
    radius : float or array
        Kiln inner radius, m.
    particle_diameter : float or array
        m.
    fill : float or array
        Hold-up volume fraction, - (valid < 0.5).

    Returns
    -------
    float or ndarray
        m2/s.

    Examples
    --------
    Seed 003's sand benchmark (D = 0.1013 m, 3 rpm, d_p 0.55 mm, X = 0.081): 1.7e-6 m2/s.

    >>> round(sherritt_dispersion_coefficient(3 * np.pi / 30, 0.1013 / 2, 0.55e-3, 0.081) * 1e6, 1)
    1.7

    References
    ----------
    R.G. Sherritt, J. Chaouki, A.K. Mehrotra, L.A. Behie, Axial dispersion in the
    three-dimensional mixing of particles in a rotating drum reactor, Chem. Eng. Sci. 58
    (2003) 401-415 (eq. 16 of seed 003).
    """
    check_positive("rtd.fill", fill)
    check_positive("rtd.particle_diameter", particle_diameter, "m")
    ratio = np.asarray(omega) / critical_speed(radius)
    d = 0.0011 * ratio**0.39 * (2 * np.asarray(radius)) ** 1.15
    d = d * np.asarray(particle_diameter) ** 0.46 * np.asarray(fill) ** -0.43
    return d if np.ndim(d) else float(d)


def open_open_dispersion_rtd(t, tau, peclet):
    r"""Exit-age distribution of the open-open axial dispersion model, 1/s.

    .. math:: E(t) = \frac{1}{2}\sqrt{\frac{Pe}{\pi\tau t}}
              \exp\!\left[-\frac{Pe(\tau - t)^2}{4\tau t}\right]

    Mean :math:`\tau(1 + 2/Pe)`, variance :math:`\tau^2(2/Pe + 8/Pe^2)`.

    Parameters
    ----------
    t : array
        Time, s (>= 0; E = 0 at t = 0).
    tau : float
        Space time L/u, s.
    peclet : float
        uL/D, -.

    Examples
    --------
    >>> t = np.linspace(0, 5000, 20001)
    >>> E = open_open_dispersion_rtd(t, 1000.0, 50.0)
    >>> round(float(np.trapezoid(E, t)), 4), round(float(np.trapezoid(t * E, t)), 1)
    (1.0, 1040.0)
    """
    check_positive("rtd.tau", tau, "s")
    check_positive("rtd.peclet", peclet)
    t = np.asarray(t, dtype=float)
    ts = np.where(t > 0, t, 1.0)
    e = (
        0.5
        * np.sqrt(peclet / (np.pi * tau * ts))
        * np.exp(-peclet * (tau - ts) ** 2 / (4 * tau * ts))
    )
    return np.where(t > 0, e, 0.0)


@dataclass(frozen=True)
class OpenOpenDispersion:
    """RTD object in the rtdpy vocabulary: ``exitage(t)``, ``mean``, ``variance``."""

    tau: float
    peclet: float

    def exitage(self, t):
        return open_open_dispersion_rtd(t, self.tau, self.peclet)

    @property
    def mean(self) -> float:
        return self.tau * (1 + 2 / self.peclet)

    @property
    def variance(self) -> float:
        return self.tau**2 * (2 / self.peclet + 8 / self.peclet**2)


@dataclass(frozen=True)
class ResidenceTimeEffects:
    """Plug-flow and segregated-flow conversion of ``species`` in a solved kiln.

    ``kiln_conversion``: the coupled kiln solution (plug flow with the energy balance);
    ``plug``: plug flow through the frozen profiles at the mean residence time of the RTD;
    ``segregated``: the RTD average; ``peclet``, ``dispersion`` (m2/s); ``result``
    (:class:`~rotarykiln.chemistry.segregated.SegregatedResult`).
    """

    species: str
    kiln_conversion: float
    peclet: float
    dispersion: float
    result: SegregatedResult

    def summary(self) -> dict:
        r = self.result
        return {
            "rtd_species": self.species,
            "rtd_peclet": self.peclet,
            "rtd_dispersion_m2_s": self.dispersion,
            "rtd_mean_residence_time_s": r.mean_residence_time,
            "conversion_kiln_plug_flow": self.kiln_conversion,
            "conversion_plug_flow_at_mean_rtd": r.plug,
            "conversion_segregated_flow": r.segregated,
        }

    def plot(self, ax=None):
        ax = self.result.plot(ax)
        ax.set_title(f"{self.species}: Pe = {self.peclet:.0f}")
        return ax


def _reactant(sol, kiln) -> str:
    mech = kiln.mechanism
    bases = [r.basis for r in mech.reactions if r.basis != MOISTURE]
    for b in bases:
        if kiln.feed.get(b, 0) > 0:
            return b
    raise InputError("chemistry.reactions", mech.names, "a reaction consuming a fed bed species")


def residence_time_effects(case, kiln, sol, species: str | None = None, n_tau: int = 24):
    """Plug vs segregated conversion of the kiln ``sol`` over its dispersion RTD.

    ``case.chemistry.peclet`` overrides the Sherritt correlation.
    """
    species = species or _reactant(sol, kiln)
    dispersion = sherritt_dispersion_coefficient(
        kiln.omega, kiln.radius, kiln.particle_diameter, kiln.fill
    )
    pe = getattr(case.chemistry, "peclet", None) if case is not None else None
    if pe is None:
        pe = kiln.bed_velocity * kiln.length / dispersion
    rtd = OpenOpenDispersion(kiln.residence_time, float(pe))
    z = sol.z
    fl = sol.fluxes
    gas = sol.gas_flows
    names = list(gas)
    mm = np.array([kiln.mechanism.species[s].molar_mass for s in names])
    moles = np.array([gas[s][:-1] for s in names]).T / mm
    x = moles / moles.sum(-1, keepdims=True)
    pp = {s: (z, kiln.pressure * x[:, i]) for i, s in enumerate(names)}
    inputs = {
        "drying_conductance": (z, fl["h_gb"] * _chord(kiln)),
        "bed_heat_input": (
            z,
            fl["q_gas_bed_conv"] + fl["q_rad_to_bed"] + fl["q_covered_wall_bed"],
        ),
        "steam_mass_flow": kiln.steam_flow
        if kiln.steam_flow is not None
        else (z, gas.get("H2O", np.zeros(len(z) + 1))[:-1]),
    }
    t_max = rtd.mean + 8 * np.sqrt(rtd.variance)
    res = kiln_segregated_conversion(
        kiln.mechanism,
        kiln.feed,
        species,
        kiln.length,
        rtd,
        (z, sol.t_bed),
        (z, sol.t_gas),
        pp,
        inputs,
        n_tau=n_tau,
        t_max=t_max,
        n=801,
    )
    return ResidenceTimeEffects(
        species, float(sol.conversion(species)[-1]), float(pe), float(dispersion), res
    )


def _chord(kiln) -> float:
    from rotarykiln.geometry import CrossSection

    return float(CrossSection.from_fill(kiln.fill, kiln.radius).chord)
