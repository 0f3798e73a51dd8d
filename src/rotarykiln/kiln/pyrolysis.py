r"""The indirectly heated wood-pyrolysis kiln of rotaryPyrolysis (Pichler et al. 2021) as a Kiln.

:func:`rotary_pyrolysis_kiln` builds the default case of the rotaryPyrolysis script (its
inputs: ``data/rotary_pyrolysis/README.md``; docs/pyrolysis.md): a 2 m drum of 0.4 m heated
through its wall by a co-current flue-gas jacket (175 kg/h entering at 833.15 K), 30 kg/h of
wood chips with 0.1 % moisture, a co-current N2 sweep of 1 kg/h, the built-in wood mechanism
(:func:`rotarykiln.chemistry.biomass.wood_pyrolysis_mechanism`), the bed depth from the Saeman
(Kramers) equation with a 25 mm dam solved in the Newton system, and optionally the bed's axial
dispersion at the script's Peclet number 5 inside the balances.

The bed volume: :class:`ConstantVolumeBed` keeps the volumetric flow of the fresh feed along
the kiln, as the script does (the chips keep their size while they lose mass); the bed's bulk
density then falls with the mass that leaves, and the hold-up of each species per metre is
:math:`m'_i = \dot m_i A_{bed}/\dot V_0`. With ``shrinkage`` the volume flow falls with the conversion of the
wood (:class:`ConstantVolumeBed`).

Departures from the script that are physics, not choices of the case (docs/pyrolysis.md):
moisture dries at the Chan et al. rate on the moisture itself (the script multiplies it by the
moisture fraction) and does not block pyrolysis; char c_p with the -6.85e-4 T^2 term; the
freeboard gas is a grey participating medium with the WSGG emissivity of its H2O and CO2 (the
script's gas is black while the wall and bed see each other fully); the heat transfer closures
are those of rotarykiln with their physical inputs (Tscheng & Watkinson with the true fill and
rad/s; Li et al. 2005 with its own film thickness; gas properties from the tables).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotarykiln.chemistry.biomass import tar_escape_fraction, wood_pyrolysis_mechanism
from rotarykiln.kiln.bed.depth import KramersBed
from rotarykiln.kiln.inputs import Bed, Chemistry, Closures, Drum, Feed, GasInlet, Kiln, Wall
from rotarykiln.kiln.wall.jacket import Jacket

__all__ = [
    "PYROLYSIS_CLOSURES",
    "ConstantVolumeBed",
    "ROTARY_PYROLYSIS",
    "rotary_pyrolysis_kiln",
    "char_yield",
    "mean_residence_time",
    "segregated_yields",
]

#: Inputs of the rotaryPyrolysis default case (SI; the script's values, docs/pyrolysis.md).
ROTARY_PYROLYSIS = {
    "length": 2.0,  # m
    "radius": 0.20,  # m, inner
    "slope_deg": 3.0,
    "speed_rpm": 2.0,
    "repose_deg": 37.0,  # dynamic angle of repose
    "dam_height": 0.025,  # m
    "feed": 30.0 / 3600.0,  # kg/s, wet wood
    "moisture": 0.001,  # mass fraction, wet basis
    "feed_temperature": 298.15,  # K
    "particle_density": 650.0,  # kg/m3
    "porosity": 0.57,  # bed void fraction
    "particle_diameter": 0.015,  # m
    "water_density": 1000.0,  # kg/m3 (volume of the moisture, as the script)
    "n2_flow": 1.0 / 3600.0,  # kg/s, co-current sweep
    "gas_temperature": 298.15,  # K
    "pressure": 1.013e5,  # Pa
    "jacket_flow": 175.0 / 3600.0,  # kg/s flue gas, co-current
    "jacket_temperature": 833.15,  # K
    "jacket_cp": 1226.9,  # J/(kg K), the script's c_p at the inlet, frozen
    "casing_u": 2.5,  # W/(m2 K) on the drum perimeter 2 pi R
    "ambient_temperature": 298.15,  # K
    "wall_emissivity": 0.65,
    "bed_emissivity": 0.82,
    "bed_conductivity": 0.11,  # W/(m K)
    "peclet": 5.0,
}


#: Closures of the default case: rotarykiln's defaults (Tscheng & Watkinson 1979 convection,
#: grey WSGG radiation) with the covered wall by penetration theory (Wachters & Kramers 1964).
#: Li et al. (2005)'s gas film was fitted for 0.16-1 mm sand; extrapolated to 15 mm chips it is
#: a 1.4 mm stagnant gas layer (h about 25 W/(m2 K)) that ignores the radiation across the
#: gap (4 sigma T^3 about 60-130 W/(m2 K) at 650-830 K): docs/pyrolysis.md shows all three.
PYROLYSIS_CLOSURES = Closures(covered_wall="wachters_kramers1964")


@dataclass(frozen=True)
class ConstantVolumeBed(KramersBed):
    r"""A Kramers bed whose volumetric flow is the fresh feed's all along the kiln (the chips
    keep their size as they lose mass, as in the rotaryPyrolysis script), or shrinks with the
    conversion of the feed species by the fraction ``shrinkage`` at full conversion:

    .. math:: \dot V = \dot V_0\,[1 - s\,X],\qquad
              X = 1 - \sum_{i\,\in\,feed}\dot m_i / \dot m_0

    ``volume_flow0``: the fresh feed's volumetric flow, m3/s; ``feed``: the fed species and
    their flows (kg/s); ``shrinkage`` s (-, in [0, 1)), e.g. 0.3 for wood chips that lose about a
    third of their volume when charred [EXT].

    Examples
    --------
    >>> bed = ConstantVolumeBed(0.2, 0.2094, 0.0524, 0.6458, 279.5, 0.025, volume_flow0=3e-5)
    >>> float(bed.volume_flow(("wood",), np.array([[0.001]]))[0])
    3e-05
    """

    volume_flow0: float = 0.0
    feed: tuple = ()
    shrinkage: float = 0.0

    def volume_flow(self, names, qb):
        """Volumetric flow (m3/s) at the faces from the bed species flows ``qb`` (kg/s)."""
        qb = np.asarray(qb, dtype=float)
        if self.shrinkage == 0.0:
            return np.full(qb.shape[:-1], self.volume_flow0)
        fed = dict(self.feed)
        total = sum(fed.values())
        mask = np.array([n in fed for n in names], dtype=float)
        conversion = 1.0 - (np.maximum(qb, 0.0) * mask).sum(-1) / total
        return self.volume_flow0 * (1.0 - self.shrinkage * np.clip(conversion, 0.0, 1.0))


def rotary_pyrolysis_kiln(
    *,
    dispersion: bool = True,
    peclet: float | None = None,
    jacket_htc: float | str = "wall_at_gas",
    shrinkage: float = 0.0,
    freeboard_cracking: bool = False,
    closures: Closures | None = None,
    **overrides,
) -> Kiln:
    """The rotaryPyrolysis default case as a :class:`~rotarykiln.kiln.inputs.kiln.Kiln` heated by a jacket.

    Parameters
    ----------
    dispersion : bool
        Axial dispersion of the bed inside the balances at ``peclet`` (default the script's 5,
        :math:`D = u L / Pe` with the mean solids speed :math:`u = L/\\tau`); False: plug flow.
    peclet : float, optional
        Bed Peclet number (default 5).
    jacket_htc : float or str
        Jacket gas to drum coefficient: ``"wall_at_gas"`` (the script: the wall at the flue-gas
        temperature), ``"annulus"`` (:func:`~rotarykiln.kiln.wall.jacket.annulus_heat_transfer_coefficient`
        with a 50 mm gap, an assumption: the script has no jacket geometry) or W/(m2 K).
    shrinkage : float
        Fraction of the bed volume lost at full conversion (:class:`ConstantVolumeBed`); 0
        (default): the fresh feed's volume all along (the script).
    freeboard_cracking : bool
        Crack the tar vapour in the freeboard (the script does not).
    closures : Closures, optional
        Default :data:`PYROLYSIS_CLOSURES` (Tscheng & Watkinson convection, penetration
        theory at the covered wall, grey WSGG radiation).
    **overrides
        Values of :data:`ROTARY_PYROLYSIS` to change (SI).

    Examples
    --------
    >>> k = rotary_pyrolysis_kiln(dispersion=False)
    >>> round(k.feed.flows["wood"] * 3600, 2), k.gas.counter_current, k.wall.jacket.inlet_temperature
    (29.97, False, 833.15)
    """
    p = {**ROTARY_PYROLYSIS, **overrides}
    unknown = set(overrides) - set(ROTARY_PYROLYSIS)
    if unknown:
        from rotarykiln.errors import InputError

        raise InputError(
            f"rotary_pyrolysis.{sorted(unknown)[0]}", "given", "a key of ROTARY_PYROLYSIS"
        )
    L, R = p["length"], p["radius"]
    omega = p["speed_rpm"] * 2.0 * np.pi / 60.0
    X = p["moisture"]
    feed = p["feed"]
    eps = p["porosity"]
    rho_b = p["particle_density"] * (1.0 - eps)
    q0 = feed * (1.0 - X) / rho_b + feed * X / (p["water_density"] * (1.0 - eps))
    bed = ConstantVolumeBed(
        R,
        omega,
        np.radians(p["slope_deg"]),
        np.radians(p["repose_deg"]),
        rho_b,
        p["dam_height"],
        volume_flow0=q0,
        feed=(("wood", feed * (1.0 - X)), ("H2O(l)", feed * X)),
        shrinkage=float(shrinkage),
    )
    mech = wood_pyrolysis_mechanism(
        tar_escape_fraction(p["speed_rpm"]), freeboard_cracking=freeboard_cracking
    )
    jacket = Jacket(
        p["jacket_flow"],
        p["jacket_temperature"],
        cp=p["jacket_cp"],
        counter_current=False,
        htc=jacket_htc,
        casing_u=p["casing_u"],
    )
    # seed of the bed depth solve: the fill and speed of the fresh feed's Saeman profile
    z = np.linspace(0.0, L, 201)
    h = _saeman_depth(bed, L, z, q0)
    from rotarykiln.geometry import CrossSection

    area = CrossSection.from_depth(h, R).bed_area
    volume = float(np.trapezoid(area, z))
    tau = volume / q0
    fill = float(np.mean(area)) / (np.pi * R**2)
    kiln = Kiln(
        drum=Drum(L, R, omega),
        bed=Bed(
            fill=fill,
            velocity=L / tau,
            bulk_density=rho_b,
            conductivity=p["bed_conductivity"],
            emissivity=p["bed_emissivity"],
            particle_diameter=p["particle_diameter"],
            depth=bed,
        ),
        feed=Feed({"wood": feed * (1.0 - X), "H2O(l)": feed * X}, p["feed_temperature"]),
        gas=GasInlet(
            {"N2": p["n2_flow"]},
            p["gas_temperature"],
            pressure=p["pressure"],
            counter_current=False,
        ),
        chemistry=Chemistry(mech),
        wall=Wall(
            jacket=jacket,
            ambient_temperature=p["ambient_temperature"],
            emissivity=p["wall_emissivity"],
        ),
        closures=closures or PYROLYSIS_CLOSURES,
        name="rotaryPyrolysis default case (Pichler et al. 2021)",
    )
    if dispersion:
        pe = p["peclet"] if peclet is None else peclet
        kiln = kiln.replace(bed__dispersion=L * L / tau / pe)
    return kiln


def _saeman_depth(bed: KramersBed, length, z, q):
    """Bed depth (m) at ``z`` for the constant volumetric flow ``q``: the Saeman equation
    integrated from the dam (z = L) towards the feed (the stable direction)."""
    from scipy.integrate import solve_ivp

    sol = solve_ivp(
        lambda s, h: [-bed.slope_of_depth(h[0], q)],
        (0.0, length),
        [bed.dam_height],
        dense_output=True,
        rtol=1e-10,
        atol=1e-12,
    )
    return sol.sol(length - np.asarray(z))[0]


def mean_residence_time(kiln, solution) -> float:
    r"""Mean solids residence time (s) of a solved pyrolysis kiln:
    :math:`\tau = \int A_{bed}\,dz / \dot V` with the bed's volume flow law (the
    :class:`~rotarykiln.kiln.inputs.kiln.Kiln` solution's own figure assumes a constant bulk
    density)."""
    from rotarykiln.kiln.residual import KilnResidual

    x = solution.fluxes["x"]
    res = KilnResidual(kiln, x.shape[0])
    geo = res.geometry(x)
    tb, tg, qb, qg = res.faces(x)
    v = res.volume_flow(qb)
    vm = 0.5 * (v[1:] + v[:-1])
    return float(np.sum(geo.bed_area / vm) * res.dz)


def char_yield(solution, feed: float | None = None) -> float:
    """Char at the outlet over the wet feed, -."""
    feed = feed if feed is not None else sum(solution.feed.values())
    return float(solution.bed_flows["char"][-1] / feed)


def segregated_yields(kiln, solution, peclet: float = 5.0, n_classes: int = 200) -> dict:
    r"""Outlet bed composition of the RTD classes in segregated flow, as the rotaryPyrolysis
    script treats its particle classes: every class crosses the converged kiln's bed
    temperature profile (frozen, shared by all classes) at its own speed.

    The bed reactions of the wood mechanism are first order, so a class of residence-time
    factor :math:`\theta` leaves each cell with :math:`m_{out} = \exp(\theta\,\Delta t\,K(T))\,
    m_{in}`, :math:`\Delta t = A_{bed}\Delta z/\dot V` the plug-flow time in the cell and
    :math:`K(T)` the rate matrix of the mechanism at the cell's bed temperature. Classes are
    ``n_classes`` intervals of the closed-closed axial dispersion RTD at ``peclet``
    (:func:`rotarykiln.rtd.dispersion.closed_closed_cdf`, mean :math:`\tau`), each at its
    mean :math:`\theta`, weighted by its share of the feed.

    Parameters
    ----------
    kiln : Kiln
        A pyrolysis kiln whose reactions use the ``arrhenius`` law (bed phase).
    solution : KilnSolution
        Its converged solution (normally without dispersion: the classes carry the RTD).
    peclet : float
    n_classes : int

    Returns
    -------
    dict
        Bed species -> outlet mass flow over the total feed (-), for the RTD average
        (``"rtd"``) and the plug-flow class (``"plug"``).
    """
    from scipy.linalg import expm

    from rotarykiln.kiln.residual import KilnResidual
    from rotarykiln.rtd.dispersion import closed_closed_cdf

    x = solution.fluxes["x"]
    res = KilnResidual(kiln, x.shape[0])
    geo = res.geometry(x)
    _, _, qb, _ = res.faces(x)
    v = res.volume_flow(qb)
    dt = geo.bed_area * res.dz / (0.5 * (v[1:] + v[:-1]))  # s per cell, mean class
    tau = float(dt.sum())
    sp = kiln.chemistry.mechanism.species
    names = [s for s in sp.bed_names]
    idx = {s: i for i, s in enumerate(names)}
    T = solution.t_bed  # cell means, K
    K = np.zeros((T.size, len(names), len(names)))
    R = 8.314462618
    for r in kiln.chemistry.mechanism.reactions:
        if r.phase != "bed" or r.law.name != "arrhenius":
            continue
        k = r.params["A"] * np.exp(-r.params["E"] / (R * T))
        b = idx[r.basis]
        for s, i in idx.items():
            K[:, i, b] += r.mass_stoichiometry[sp.index(s)] * k
    m0 = np.zeros(len(names))
    for s, q in kiln.feed.flows.items():
        m0[idx[s]] = q
    m0 = m0 / m0.sum()
    edges = np.concatenate([[0.0], np.geomspace(0.02, 8.0, n_classes - 1), [np.inf]])
    cdf = np.concatenate([[0.0], closed_closed_cdf(edges[1:-1] * tau, tau, peclet), [1.0]])
    w = np.diff(cdf)
    mid = np.concatenate([0.5 * (edges[1:-2] + edges[2:-1]), [edges[-2] * 1.2]])
    mid = np.concatenate([[0.5 * edges[1]], mid])[: w.size]

    # eigen-decomposition of each cell's rate matrix: exp(theta dt K) for all classes at once
    # (expm where the eigenvectors are ill-conditioned)
    modes = []
    for j in range(T.size):
        lam, V = np.linalg.eig(K[j])
        if np.linalg.cond(V) < 1e8:
            modes.append((lam, V, np.linalg.inv(V)))
        else:
            modes.append(None)

    def outlet(theta):
        th = np.atleast_1d(np.asarray(theta, dtype=float))
        m = np.broadcast_to(m0, (th.size, m0.size)).astype(complex)
        for j in range(T.size):
            if modes[j] is None:
                E = expm(th[:, None, None] * dt[j] * K[j][None])
                m = np.einsum("cij,cj->ci", E, m)
            else:
                lam, V, Vi = modes[j]
                m = (np.exp(np.outer(th * dt[j], lam)) * (m @ Vi.T)) @ V.T
        return m.real

    m_cls = outlet(mid)
    avg = (w[:, None] * m_cls).sum(0) / w.sum()
    plug = outlet(np.array([1.0]))[0]
    return {
        "rtd": dict(zip(names, avg, strict=True)),
        "plug": dict(zip(names, plug, strict=True)),
        "tau": tau,
        "classes": n_classes,
    }
