r"""Residence-time effects on the conversion of a reacting kiln: plug flow vs segregated flow.

The bed's residence time distribution comes from :mod:`rotarykiln.rtd`: by default the open-open
axial dispersion model (seed 003 eq. 14) with :math:`\tau = L/u_s` (the kiln's solids space
time),

.. math:: E(t) = \frac{1}{2\tau}\sqrt{\frac{Pe}{\pi\theta}}
          \exp\!\left[-\frac{Pe\,(1 - \theta)^2}{4\,\theta}\right],\qquad
          \theta = t/\tau,\quad Pe = \frac{u_s L}{D}

with the dispersion coefficient of Sherritt et al. (2003)
(:func:`rotarykiln.rtd.correlations.sherritt_dispersion`, no lifters in seed 004's kilns);
``chemistry.peclet`` overrides Pe, and a case ``rtd:`` section chooses the model and the
correlation as for ``rotarykiln run`` (:func:`rotarykiln.commands.model_runs.peclet_from_case`).

Each residence-time class :math:`\tau'` crosses the kiln at :math:`L/\tau'` through the
converged kiln's temperature, CO2 and heat-input profiles (frozen: a segregated parcel does not
change them), with the plug-flow equations of :mod:`rotarykiln.chemistry.plugflow`. In the kiln
coordinate z all classes, and the plug-flow class at :math:`\tau = L/u_s`, form one vector ODE
integrated in one batch
(:func:`rotarykiln.chemistry.segregated.batch_plug_flow_conversion`); the outlet conversion is
the RTD average (:func:`rotarykiln.chemistry.segregated.kiln_segregated_conversion`).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from rotarykiln.chemistry.ratelaws import MOISTURE
from rotarykiln.chemistry.segregated import SegregatedResult, kiln_segregated_conversion
from rotarykiln.errors import InputError
from rotarykiln.rtd.correlations import sherritt_dispersion
from rotarykiln.rtd.dispersion import get_model

__all__ = ["KilnRTD", "ResidenceTimeEffects", "residence_time_effects"]

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class KilnRTD:
    """An RTD of :mod:`rotarykiln.rtd` as an object with ``exitage(t)``, ``mean``, ``variance``.

    Examples
    --------
    >>> rtd = KilnRTD("open-open", 1000.0, 50.0)
    >>> round(rtd.mean, 1), round(float(rtd.exitage(1000.0)) * 1000, 3)
    (1040.0, 1.995)
    """

    model: str
    tau: float
    peclet: float

    def exitage(self, t):
        return get_model(self.model).exit_age(t, self.tau, self.peclet)

    @property
    def mean(self) -> float:
        return float(get_model(self.model).moments(self.tau, self.peclet)[0])

    @property
    def variance(self) -> float:
        return float(get_model(self.model).moments(self.tau, self.peclet)[1])


@dataclass(frozen=True)
class ResidenceTimeEffects:
    """Plug-flow and segregated-flow conversion of ``species`` in a solved kiln.

    ``kiln_conversion``: the coupled kiln solution (plug flow with the energy balance);
    ``frozen_plug_conversion``: plug flow at :math:`\tau = L/u_s` through the frozen profiles
    (an ODE integration, in the batch of the RTD classes: its difference from
    ``kiln_conversion`` is the discretisation error of the kiln grid);
    ``plug``: plug flow through the frozen profiles at the mean residence time of the RTD;
    ``segregated``: the RTD average; ``peclet``, ``dispersion`` (m2/s); ``result``
    (:class:`~rotarykiln.chemistry.segregated.SegregatedResult`); ``name``: the kiln's case.
    """

    species: str
    kiln_conversion: float
    frozen_plug_conversion: float
    peclet: float
    dispersion: float
    result: SegregatedResult
    name: str = ""

    def summary(self) -> dict:
        r = self.result
        return {
            "rtd_species": self.species,
            "rtd_peclet": self.peclet,
            "rtd_dispersion_m2_s": self.dispersion,
            "rtd_mean_residence_time_s": r.mean_residence_time,
            "conversion_kiln_plug_flow": self.kiln_conversion,
            "conversion_plug_flow_frozen_profiles": self.frozen_plug_conversion,
            "conversion_plug_flow_at_mean_rtd": r.plug,
            "conversion_segregated_flow": r.segregated,
        }

    def plot(self, ax=None):
        """X(tau) over the RTD (:meth:`SegregatedResult.plot`) titled with the species and the
        Peclet number; returns the Figure."""
        if ax is None:
            import matplotlib.pyplot as plt

            _, ax = plt.subplots(figsize=(6.4, 4.6))
        self.result.plot(ax)
        title = f"{self.species} over the RTD (Pe = {self.peclet:.0f})"
        ax.set_title(f"{self.name}: {title}" if self.name else title, fontsize="medium")
        ax.figure.tight_layout()
        return ax.figure


def fed_reactant(kiln) -> str | None:
    """The first fed bed species (moisture aside) that a reaction consumes, or None."""
    for r in kiln.chemistry.mechanism.reactions:
        if r.basis != MOISTURE and kiln.feed.flows.get(r.basis, 0) > 0:
            return r.basis
    return None


def _reactant(sol, kiln) -> str:
    name = fed_reactant(kiln)
    if name is None:
        raise InputError(
            "chemistry.reactions",
            kiln.chemistry.mechanism.names,
            "a reaction consuming a fed bed species",
        )
    return name


def residence_time_effects(
    kiln,
    sol,
    species: str | None = None,
    n_tau: int = 24,
    *,
    peclet: float | None = None,
    model: str = "open-open",
):
    r"""Plug vs segregated conversion of the kiln ``sol`` over its predicted RTD.

    The conversion of each age class of the bed, integrated along the solved temperature and
    gas profiles, weighted by the axial-dispersion RTD of the bed (mean: the solution's
    residence time):

    .. math:: \bar X = \int_0^\infty E(t)\,X(t)\,dt

    Parameters
    ----------
    kiln : Kiln
        The kiln solved.
    sol : KilnSolution
        Its steady solution.
    species : str, optional
        The fed reactant (default: the first one a reaction consumes).
    n_tau : int
        Number of age classes (the number of RTD classes).
    peclet : float, optional
        The bed's Peclet number, dimensionless (a case's ``chemistry.peclet`` or its
        ``rtd:`` section, :func:`rotarykiln.commands.kiln_runs.bed_peclet`); None: from the
        Sherritt et al. (2003) dispersion correlation with the kiln's fill.
    model : str
        The RTD's boundary conditions (:mod:`rotarykiln.rtd.dispersion`).

    Returns
    -------
    ResidenceTimeEffects
        Plug and segregated conversions (fraction), the Peclet number and dispersion (m2/s).

    Examples
    --------
    >>> import warnings
    >>> from rotarykiln.api import load_case
    >>> from rotarykiln.kiln.from_case import kiln_from_case
    >>> from rotarykiln.kiln.steady.solve import solve_kiln
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     kiln, _ = kiln_from_case(load_case("limestone_calcination"))
    ...     sol = solve_kiln(kiln, 20)
    ...     eff = residence_time_effects(kiln, sol, n_tau=6, peclet=20.0)
    >>> eff.peclet, bool(0 <= eff.result.segregated <= 1)
    (20.0, True)

    References
    ----------
    O. Levenspiel, Chemical Reaction Engineering, 3rd ed. (1999), ch. 11 and 13 (segregated
    flow); R.G. Sherritt et al., Chem. Eng. Sci. 58 (2003) 401 (dispersion in rotary drums).
    """
    species = species or _reactant(sol, kiln)
    tau = sol.residence_time
    if peclet is None:
        dispersion = float(
            sherritt_dispersion(
                kiln.drum.omega, 2 * kiln.drum.radius, kiln.bed.particle_diameter, kiln.bed.fill
            )
        )
        peclet = kiln.drum.length**2 / (tau * dispersion)
    pe = float(peclet)
    dispersion = kiln.drum.length**2 / (pe * tau)
    rtd = KilnRTD(model, tau, pe)
    z = sol.z
    fl = sol.fluxes
    gas = sol.gas_flows
    names = list(gas)
    mm = np.array([kiln.chemistry.mechanism.species[s].molar_mass for s in names])
    out = slice(None, -1) if kiln.gas.counter_current else slice(1, None)  # each cell's gas outlet
    moles = np.array([gas[s][out] for s in names]).T / mm
    x = moles / moles.sum(-1, keepdims=True)
    pp = {s: (z, kiln.gas.pressure * x[:, i]) for i, s in enumerate(names)}
    inputs = {
        "drying_conductance": (z, fl["h_gb"] * _chord(kiln)),
        "bed_heat_input": (
            z,
            fl["q_gas_bed_conv"] + fl["q_rad_to_bed"] + fl["q_covered_wall_bed"],
        ),
        "steam_mass_flow": kiln.chemistry.steam_flow
        if kiln.chemistry.steam_flow is not None
        else (z, gas.get("H2O", np.zeros(len(z) + 1))[out]),
    }
    t_max = rtd.mean + 8 * np.sqrt(rtd.variance)
    log.info(
        "residence-time effects of %s: %s RTD, Pe = %.3g, %d classes", species, model, pe, n_tau
    )
    res = kiln_segregated_conversion(
        kiln.chemistry.mechanism,
        kiln.feed.flows,
        species,
        kiln.drum.length,
        rtd,
        (z, sol.t_bed),
        (z, sol.t_gas),
        pp,
        inputs,
        n_tau=n_tau,
        t_max=t_max,
        n=801,
        extra_residence_times=[tau],
    )
    return ResidenceTimeEffects(
        species,
        float(sol.conversion(species)[-1]),
        float(res.class_conversion[-1]),
        float(pe),
        float(dispersion),
        res,
        str(getattr(sol, "name", "") or ""),
    )


def _chord(kiln) -> float:
    from rotarykiln.geometry import CrossSection

    return float(CrossSection.from_fill(kiln.bed.fill, kiln.drum.radius).chord)
