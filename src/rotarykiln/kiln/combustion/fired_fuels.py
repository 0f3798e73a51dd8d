r"""Solid and liquid fuels in the burner: their products, heat, ash and where they burn.

A burner may fire, besides (or instead of) a gaseous fuel, solid fuels (coal, petroleum coke,
alternative fuels) and liquid fuels (fuel oil), each by its analyses
(:class:`~rotarykiln.chemistry.solid_fuels.SolidFuel`) and its as-fired flow. Their
combustion is complete, by elements, with the burner's air streams (water as vapour):

.. math::
    \mathrm{C \to CO_2},\quad \mathrm{H \to \tfrac12 H_2O},\quad
    \mathrm{S \to SO_2},\quad \mathrm{N \to \tfrac12 N_2},\quad
    \text{moisture} \to \mathrm{H_2O(g)},\quad \text{ash} \to \text{bed}

and a gaseous fuel fired with them burns by its elements the same way. The heat of
combustion is the sum of the fuels' lower heating values on the as-fired basis (measured, or
Channiwala-Parikh from the ultimate analysis): the LHV already pays for evaporating the
moisture and the water formed, so the products carry their water as vapour from 298.15 K. The
products' properties are those of the kiln's own gas species
(:mod:`rotarykiln.kiln.gas_mixture`; SO2 from its NIST Shomate c_p), so the kiln's gas enters
with exactly the energy the fuels release. Chlorine is not followed: its mass joins the ash.
The ash (with the chlorine) falls into the bed and joins the product, where the fuel burns.

Where the fuel burns, the ``particles`` combustion model: the burn-out of the pulverised fuel
(:func:`rotarykiln.chemistry.fuel_burnout.pulverised_fuel_burnout`: drying, Kobayashi
devolatilisation, Baum-Street char burn-out with kinetic and diffusion limits over the size
classes) along the kiln from the burner, carried by the gas at the flame's adiabatic
temperature and mean velocity in the kiln section, in the O2 of the products (excess air).
The heat is released as the particles burn out (its profile is the cumulative burn-out); a
liquid fuel, whose droplets evaporate and burn in the gas, has no particles and burns by the
mixing-limited flame (``burnout`` with a flame length). A fuel that does not burn out inside
the kiln is refused: its unburnt char is not followed.

References
----------
ASTM D3180 (analysis bases); S.A. Channiwala, P.P. Parikh, Fuel 81 (2002) 1051 (HHV);
H. Kobayashi, J.B. Howard, A.F. Sarofim, 16th Symp. Combust. (1977) 411; M.M. Baum,
P.J. Street, Combust. Sci. Technol. 3 (1971) 231; NIST Chemistry WebBook (SO2 Shomate, Chase
1998); team source folder reference/cement_lime.md 5.1-5.7.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np

from rotarykiln.errors import InputError, check_positive
from rotarykiln.materials.gas import T_REF, parse_composition

__all__ = [
    "FiredFuel",
    "FUEL_STATES",
    "ProductsTable",
    "burn_fired_fuels",
    "entrained_o2_share",
    "fired_jet",
    "particle_release",
]

FUEL_STATES = ("solid", "liquid")
#: Specific heat of a fuel fed above 298.15 K, J/(kg K): coal about 1.25 kJ/(kg K) near
#: 300-400 K (Merrick, Fuel 62 (1983) 540), heavy fuel oil about 2.0 kJ/(kg K) near 400 K
#: (e.g. Perry's Handbook, 8th ed., petroleum fractions).
SPECIFIC_HEAT = {"solid": 1250.0, "liquid": 2000.0}
#: Burn-out at the kiln's end below which a fuel is refused (its char not followed).
BURNOUT_REQUIRED = 0.999
#: Absorption efficiency of burning coal and char particles, Q_abs: 1, the large-particle
#: limit (cement_lime.md 5.5: Q_abs about 1 [TEXTBOOK, Modest]; OpenFOAM's coal tutorial sets
#: the particle emissivity to 1 [SEEN: OFT]). Scattering is not counted.
PARTICLE_ABSORPTION = 1.0
#: Products of complete combustion, by element (mol of product per mol of element).
_PRODUCT_OF = {"C": ("CO2", 1.0), "H": ("H2O", 0.5), "S": ("SO2", 1.0), "N": ("N2", 0.5)}
_ATOMIC = {"C": 0.012011, "H": 0.001008, "O": 0.015999, "N": 0.014007, "S": 0.03206}
_M_H2O = 0.018015


@dataclass(frozen=True, eq=False)
class FiredFuel:
    """A solid or liquid fuel fired by the burner.

    ``fuel`` (:class:`~rotarykiln.chemistry.solid_fuels.SolidFuel`, its analyses), ``flow``
    (kg/s, as fired), ``state`` (``solid`` or ``liquid``), ``size`` (a
    :class:`~rotarykiln.chemistry.fuel_burnout.ParticleSizeDistribution`; a solid fuel's
    fineness, needed by the ``particles`` model), ``specific_heat`` (J/(kg K), for a fuel fed
    hot; default :data:`SPECIFIC_HEAT`), ``label`` (its name in messages).
    """

    fuel: object
    flow: float
    state: str = "solid"
    size: object = None
    specific_heat: float | None = None
    label: str = "fuel"

    def __post_init__(self):
        check_positive(f"burner.{self.label}.flow", self.flow, "kg/s")
        if self.state not in FUEL_STATES:
            raise InputError(f"burner.{self.label}.state", self.state, " or ".join(FUEL_STATES))
        if self.specific_heat is not None:
            check_positive(f"burner.{self.label}.specific_heat", self.specific_heat, "J/(kg K)")

    @property
    def cp(self) -> float:
        """Specific heat of the fuel fed, J/(kg K)."""
        return SPECIFIC_HEAT[self.state] if self.specific_heat is None else self.specific_heat

    @cached_property
    def as_fired(self) -> dict[str, float]:
        """As-fired mass fractions C, H, O, N, S, Cl, ash, moisture (sum 1)."""
        return dict(self.fuel.as_fired())

    @property
    def lhv(self) -> float:
        """Lower heating value as fired, J/kg."""
        return float(self.fuel.lhv("ar"))

    @property
    def hhv(self) -> float:
        """Higher heating value as fired, J/kg."""
        return float(self.fuel.hhv("ar"))

    @property
    def ash_flow(self) -> float:
        """Ash (with the fuel's chlorine) falling into the bed, kg/s."""
        a = self.as_fired
        return self.flow * (a.get("ash", 0.0) + a.get("Cl", 0.0))

    def element_moles(self) -> dict[str, float]:
        """Elements fed (mol/s): C, H, O, N, S of the combustible and of the moisture."""
        a = self.as_fired
        out = {e: self.flow * a.get(e, 0.0) / m for e, m in _ATOMIC.items()}
        water = self.flow * a.get("moisture", 0.0) / _M_H2O
        out["H"] += 2.0 * water
        out["O"] += water
        return out


@dataclass(frozen=True)
class ProductsTable:
    """Enthalpy and c_p of a gas of fixed species mass flows from the kiln's species tables
    (the interface of :class:`~rotarykiln.materials.gas.GasPropertyTable` a flame needs).

    ``names`` (gas species), ``mass_fractions`` (-)."""

    names: tuple[str, ...]
    mass_fractions: tuple[float, ...]

    @cached_property
    def _mixture(self):
        from rotarykiln.kiln.gas_mixture import mixture_of

        return mixture_of(self.names)

    @property
    def composition(self) -> tuple[tuple[str, float], ...]:
        from rotarykiln.chemistry.species import default_species

        sp = default_species()
        n = [w / sp[s].molar_mass for s, w in zip(self.names, self.mass_fractions, strict=True)]
        total = sum(n)
        return tuple((s, v / total) for s, v in zip(self.names, n, strict=True))

    def enthalpy(self, T):
        """Sensible enthalpy above 298.15 K, J/kg."""
        T = np.asarray(T, dtype=float)
        h = self._mixture.species_enthalpy(np.atleast_1d(T)) @ np.asarray(self.mass_fractions)
        return h.reshape(T.shape)

    def cp(self, T):
        """Specific heat, J/(kg K)."""
        T = np.asarray(T, dtype=float)
        c = self._mixture.species_cp(np.atleast_1d(T)) @ np.asarray(self.mass_fractions)
        return c.reshape(T.shape)

    def _enthalpy_at(self, T: float) -> float:
        return float(self.enthalpy(np.array([T]))[0])


def _gas_fuel_elements(fuel, flow: float) -> dict[str, float]:
    """Elements (mol/s) of ``flow`` kg/s of a gaseous fuel of composition ``fuel``."""
    from rotarykiln.materials.gas import gri30, molar_mass

    x = dict(parse_composition(fuel))
    total = sum(x.values())
    moles = flow / molar_mass(fuel)
    gas = gri30()
    out = dict.fromkeys(("C", "H", "O", "N", "S", "Ar"), 0.0)
    for name, xi in x.items():
        for element, count in gas.species(name).composition.items():
            out[element] = out.get(element, 0.0) + moles * xi / total * count
    return out


def burn_fired_fuels(burner):
    r"""Products of a burner firing solid or liquid fuels (and a gaseous fuel), burnt completely.

    .. math:: \dot m_p\,[h_p(T_{ad}) - h_p(T_{in})] = \sum_f \dot m_f\,\mathrm{LHV}_f,\qquad
              \dot m_p\,h_p(T_{in}) = \sum_s \dot m_s h_s(T_s) + \sum_f \dot m_f c_{p,f}
              (T_f - 298.15)

    (:math:`h` sensible above 298.15 K, the kiln's gas species tables).

    Parameters
    ----------
    burner : Burner
        The burner (:class:`~rotarykiln.kiln.combustion.flame.Burner`) with ``fired`` fuels.

    Returns
    -------
    tuple
        (:class:`~rotarykiln.materials.gas.BurntGas` of the products, LHV and HHV input (W),
        O2 needed (mol/s), ash to the bed (kg/s)).

    Raises
    ------
    InputError
        Too little air to burn the fuels completely (the air ratio named).

    Examples
    --------
    Pittsburgh No. 8, 1 kg/s with 10 % excess air:

    >>> from rotarykiln.chemistry.solid_fuels import load_kiln_fuel
    >>> from rotarykiln.kiln.combustion.flame import AirStream, Burner
    >>> coal = FiredFuel(load_kiln_fuel("pittsburgh_8"), 1.0)
    >>> b = Burner("CH4:1", 0.0, AirStream(11.5), fired=(coal,))
    >>> p, lhv, hhv, o2, ash = burn_fired_fuels(b)
    >>> round(lhv / 1e6, 2), round(ash, 4), round(p.adiabatic_temperature, -1)
    (30.1, 0.0921, 2260.0)

    References
    ----------
    See the module docstring.
    """
    from rotarykiln.chemistry.species import default_species
    from rotarykiln.materials.gas import BurntGas, fuel_data

    sp = default_species()
    elements = dict.fromkeys(("C", "H", "O", "N", "S", "Ar"), 0.0)
    lhv = hhv = ash = 0.0
    sensible = 0.0
    for f in burner.fired:
        for e, n in f.element_moles().items():
            elements[e] += n
        lhv += f.flow * f.lhv
        hhv += f.flow * f.hhv
        ash += f.ash_flow
        sensible += f.flow * f.cp * (burner.fuel_temperature - T_REF)
    fuel_mass = sum(f.flow for f in burner.fired)
    if burner.fuel_flow > 0:
        for e, n in _gas_fuel_elements(burner.fuel, burner.fuel_flow).items():
            elements[e] = elements.get(e, 0.0) + n
        _, _, lhv_g, hhv_g = fuel_data(parse_composition(burner.fuel))
        lhv += burner.fuel_flow * lhv_g
        hhv += burner.fuel_flow * hhv_g
        fuel_mass += burner.fuel_flow
        sensible += burner.fuel_flow * float(
            _gas_table(burner.fuel).enthalpy(burner.fuel_temperature)
        )
    # the oxidiser streams, by species (mol/s), and their sensible enthalpy
    moles: dict[str, float] = {}
    for s in burner.flame_air:
        if s.flow <= 0:
            continue
        x = dict(parse_composition(s.composition))
        unknown = [k for k in x if k not in sp.names or sp[k].phase != "gas"]
        if unknown:
            raise InputError(
                "burner.air.composition", ", ".join(unknown), "species of the kiln's gas table"
            )
        # by the kiln's own molar masses, so that the products hold the streams' mass exactly
        mm = sum(xi * sp[k].molar_mass for k, xi in x.items())
        for name, xi in x.items():
            moles[name] = moles.get(name, 0.0) + s.flow / mm * xi
        sensible += s.flow * float(_gas_table(s.composition).enthalpy(s.temperature))
    o2_needed = elements["C"] + elements["H"] / 4.0 + elements["S"] - elements["O"] / 2.0
    o2_supplied = moles.get("O2", 0.0)
    if o2_needed <= 0:
        raise InputError("burner.fuels", "no combustible", "a fuel with C, H or S to burn")
    if o2_supplied < o2_needed:
        raise InputError(
            "burner.primary_air.flow",
            f"air ratio {o2_supplied / o2_needed:.4g}",
            ">= 1 (enough air to burn the solid and liquid fuels completely; a substoichiometric "
            "flame of them is not modelled)",
        )
    products = {k: v for k, v in moles.items() if k != "O2"}
    products["O2"] = o2_supplied - o2_needed
    for e, (name, per) in _PRODUCT_OF.items():
        products[name] = products.get(name, 0.0) + per * elements[e]
    products["AR"] = products.get("AR", 0.0) + elements.get("Ar", 0.0)
    names = tuple(k for k, v in products.items() if v > 0)
    mass = np.array([products[k] * sp[k].molar_mass for k in names])
    m_products = float(mass.sum())
    table = ProductsTable(names, tuple(float(w) for w in mass / m_products))
    # mass check: fuels + oxidiser - ash = products (to round-off)
    m_in = fuel_mass + sum(s.flow for s in burner.flame_air) - ash
    if abs(m_in - m_products) > 1e-9 * m_in:
        raise InputError(
            "burner.fuels",
            f"products {m_products:.6g} kg/s against {m_in:.6g} kg/s fed",
            "an analysis whose elements add up to its mass (C, H, O, N, S, Cl, ash, moisture)",
        )
    t_in = _temperature(table, sensible / m_products)
    t_ad = _temperature(table, (sensible + lhv) / m_products)
    comp = table.composition
    return (
        BurntGas(comp, m_products, t_in, t_ad, lhv, table),
        lhv,
        hhv,
        o2_needed,
        ash,
    )


@lru_cache(maxsize=64)
def _gas_table(composition: str):
    from rotarykiln.materials.gas import gas_table

    return gas_table(composition)


def _temperature(table: ProductsTable, h: float) -> float:
    """Temperature (K) at which ``table`` holds the sensible enthalpy ``h`` (J/kg)."""
    from scipy.optimize import brentq

    lo, hi = 200.0, 3200.0
    f = lambda T: table._enthalpy_at(T) - h  # noqa: E731
    if f(lo) > 0 or f(hi) < 0:
        raise InputError(
            "burner.fuels",
            f"{h:.6g} J/kg of products",
            "a flame between 200 and 3200 K (more air, or less fuel)",
        )
    return float(brentq(f, lo, hi, xtol=1e-10))


def particle_release(flame, kiln_diameter: float, kiln_length: float):
    r"""Where the solid fuels release their heat: the burn-out of their particles along the
    kiln from the burner (module docstring, ``particles`` model).

    With the burner's nozzle diameter given (:func:`fired_jet`), the heat released by
    :math:`x` is at most the share of the fuels' O2 demand that the jet has entrained by then
    (:func:`entrained_o2_share`): the flame is as long as the slower of the particles' burn-out
    and the jet's mixing.

    The particles travel with the gas at the flame's adiabatic temperature :math:`T_{ad}`, at
    the mean velocity of the products in the kiln's section :math:`u = \dot m_p/(\rho(T_{ad})
    \pi D^2/4)`, in the products' O2 (:math:`p_{O_2} = x_{O_2} p`). The heat released up to
    :math:`x` from the burner is that of the fuels' burn-out there; a liquid fuel burns with
    the first.

    Parameters
    ----------
    flame : Flame
        The burner's flame (its products and fired fuels).
    kiln_diameter, kiln_length : float, m

    Returns
    -------
    (tuple, dict, tuple)
        (distances from the burner (m), cumulative release (-)), the table of
        :class:`ReleaseTable`; per fuel its burn-out at the kiln's end (-); and the
        absorption coefficient of the burning particles at the same distances (1/m):
        :math:`\kappa_p = \sum Q_{abs} N_i \pi d_i^2/4` over the fuels and their size
        classes, :math:`N_i` the class's particles fed per second over :math:`u \pi D^2/4`,
        :math:`d_i` their burning diameter, :math:`Q_{abs}` = ``PARTICLE_ABSORPTION``.

    Raises
    ------
    InputError
        A solid fuel without a size distribution, or one that does not burn out in the kiln.

    Examples
    --------
    Pittsburgh No. 8 ground to R90 = 12 % in a 2.6 m x 60 m kiln, 10 % excess air at 650 K:

    >>> from rotarykiln.chemistry.fuel_burnout import (
    ...     ParticleSizeDistribution, rosin_rammler_x_prime)
    >>> from rotarykiln.chemistry.solid_fuels import load_kiln_fuel
    >>> from rotarykiln.kiln.combustion.flame import AirStream, Burner, fire
    >>> psd = ParticleSizeDistribution.rosin_rammler(rosin_rammler_x_prime(90e-6, 0.12, 1.1), 1.1)
    >>> coal = FiredFuel(load_kiln_fuel("pittsburgh_8"), 0.643, size=psd, label="coal")
    >>> b = Burner("CH4:1", 0.0, AirStream(0.707), AirStream(6.36, 650.0), fired=(coal,),
    ...            combustion="particles")
    >>> (x, released), ends, kappa = particle_release(fire(b, 2.6, 60.0), 2.6, 60.0)
    >>> ends["coal"] > 0.999, released[-1], bool(np.all(np.diff(released) >= 0))
    (True, 1.0, True)
    >>> round(kappa[0], 2), kappa[-1]  # 1/m: at the burner, and burnt out at the far end
    (1.21, 0.0)

    References
    ----------
    H. Kobayashi, J.B. Howard, A.F. Sarofim, 16th Symp. Combust. (1977) 411; M.M. Baum,
    P.J. Street, Combust. Sci. Technol. 3 (1971) 231 (as in
    :func:`rotarykiln.chemistry.fuel_burnout.pulverised_fuel_burnout`).
    """
    from rotarykiln.chemistry.fuel_burnout import pulverised_fuel_burnout
    from rotarykiln.heat.gas_radiation import particle_absorption_coefficient
    from rotarykiln.materials.gas import R_UNIVERSAL

    p = flame.products
    t = float(flame.adiabatic_temperature)
    mm = sum(x * _molar(s) for s, x in p.composition)
    rho = 101325.0 * mm / (R_UNIVERSAL * t)
    u = p.mass_flow / (rho * np.pi * kiln_diameter**2 / 4.0)
    x_o2 = dict(p.composition).get("O2", 0.0)
    x = np.linspace(0.0, kiln_length, 401)
    released = np.zeros_like(x)
    kappa = np.zeros_like(x)
    total = 0.0
    ends: dict[str, float] = {}
    liquid = 0.0
    for f in flame.burner.fired:
        if f.state == "liquid":
            liquid += f.flow * f.lhv
            ends[f.label] = 1.0
            continue
        if f.size is None:
            raise InputError(
                f"burner.{f.label}.fineness",
                None,
                "given (the particles model burns a solid fuel by its particle sizes)",
            )
        r = pulverised_fuel_burnout(f.fuel, f.size, f.flow, x, t, x_o2 * 101325.0, velocity=u)
        q = np.asarray(r.cumulative_heat_release, dtype=float)
        ends[f.label] = float(r.burnout[-1])
        if ends[f.label] < BURNOUT_REQUIRED:
            raise InputError(
                f"burner.{f.label}.fineness",
                f"burn-out {ends[f.label]:.4g} at the kiln's end",
                f">= {BURNOUT_REQUIRED}: the char burns in the products' O2, here "
                f"{100.0 * x_o2:.2g} mol% (more excess air or a finer grind; the unburnt char "
                "is not followed)",
            )
        released += q
        total += float(q[-1])
        density = r.particle_number_flow / (u * np.pi * kiln_diameter**2 / 4.0)  # 1/m3
        kappa += particle_absorption_coefficient(density, r.particle_diameter, PARTICLE_ABSORPTION)
    if flame.burner.fuel_flow > 0 or liquid > 0:
        # gaseous and liquid fuels burn in the gas, as the mixing-limited flame
        from rotarykiln.heat.flames import burnout_fraction

        if flame.flame_length is None:
            raise InputError(
                "burner.flame_length",
                None,
                "given (with the particles model a gaseous or liquid fuel burns along it)",
            )
        xb = burnout_fraction(np.minimum(x / float(flame.flame_length), 1.0))
        released = released + (flame.heat_release - total) * xb
    if flame.entrainment_length is not None and flame.o2_demand is not None:
        # the jet burns its fuels no faster than it entrains the O2 they need
        share = entrained_o2_share(flame.burner, _jet_of(flame), flame.o2_demand, x)
        if share[-1] < 1.0:
            raise InputError(
                "burner.nozzle_diameter",
                f"{flame.burner.nozzle_diameter:g} m",
                f"a nozzle whose jet takes in the O2 its fuels need within the kiln's "
                f"{kiln_length:g} m (it holds {100.0 * share[-1]:.3g} % of it there: a smaller "
                "nozzle, or more primary air)",
            )
        released = np.minimum(released, released[-1] * share)
    cumulative = released / released[-1]
    table = (tuple(float(v) for v in x), tuple(float(v) for v in cumulative))
    return table, ends, tuple(float(v) for v in kappa)


def fired_jet(burner, kiln_diameter: float) -> dict:
    r"""Jet numbers of a burner firing solid or liquid fuels through a nozzle of diameter
    :math:`d_0` (``burner.nozzle_diameter``): the primary air carries the fuels (nozzle fluid
    :math:`\dot m_0` = primary air + fuels, at the primary air's velocity
    :math:`u_0 = \dot V_p/(\pi d_0^2/4)` at its temperature, a gaseous fuel's volume added),
    the Thring-Newby equivalent nozzle and Ricou-Spalding entrainment of the secondary air
    :math:`\dot m_a` at density :math:`\rho_a`:

    .. math:: d_e = \frac{2\dot m_0}{\sqrt{\pi\rho_a \dot G_0}},\quad
              \dot G_0 = \dot m_0 u_0,\quad
              x_s = \frac{d_e(\dot m_0 + \dot m_a)}{C_e \dot m_0},\quad
              \theta = \Big(1 + \frac{\dot m_a}{\dot m_0}\Big)\frac{d_e}{D}

    Parameters
    ----------
    burner : Burner
        With ``nozzle_diameter`` (m), ``entrainment`` :math:`C_e` (-), its fired fuels (kg/s).
    kiln_diameter : float
        Free diameter D, m.

    Returns
    -------
    dict
        ``equivalent_diameter`` (m), ``nozzle_velocity`` (m/s), ``thring_newby`` (-),
        ``entrainment_length`` (m), ``recirculating`` (bool, theta < 0.75), and the nozzle
        fluid's mass flow ``nozzle_flow`` (kg/s).

    Examples
    --------
    >>> from rotarykiln.chemistry.solid_fuels import load_kiln_fuel
    >>> from rotarykiln.kiln.combustion.flame import AirStream, Burner
    >>> coal = FiredFuel(load_kiln_fuel("pittsburgh_8"), 2.3, label="coal")
    >>> b = Burner("CH4:1", 0.0, AirStream(1.84), AirStream(24.6, 1323.15), fired=(coal,),
    ...            nozzle_diameter=0.3)
    >>> j = fired_jet(b, 4.4)
    >>> round(j["nozzle_velocity"], 1), round(j["equivalent_diameter"], 3)  # m/s, m
    (22.0, 0.948)
    >>> round(j["entrainment_length"], 1)  # m: all the secondary air in the jet
    20.6

    References
    ----------
    M.W. Thring, M.P. Newby, 4th Symp. Combust. (1953) 789; F.P. Ricou, D.B. Spalding, J.
    Fluid Mech. 11 (1961) 21; flames.md section 2 of the project's reference notes.
    """
    from rotarykiln.materials.gas import R_UNIVERSAL

    p, sec = burner.primary_air, burner.secondary_air
    d0 = float(burner.nozzle_diameter)
    fuels = sum(f.flow for f in burner.fired) + burner.fuel_flow
    m0 = p.flow + fuels
    volume = p.moles * R_UNIVERSAL * p.temperature / 101325.0  # m3/s of primary air
    if burner.fuel_flow > 0:
        from rotarykiln.materials.gas import molar_mass

        moles = burner.fuel_flow / molar_mass(burner.fuel)
        volume += moles * R_UNIVERSAL * burner.fuel_temperature / 101325.0
    u0 = volume / (np.pi * d0**2 / 4.0)
    if sec.flow > 0:
        rho_a = 101325.0 * sec.molar_mass / (R_UNIVERSAL * sec.temperature)
    else:
        rho_a = 101325.0 * p.molar_mass / (R_UNIVERSAL * p.temperature)
    de = 2.0 * m0 / np.sqrt(np.pi * rho_a * m0 * u0)
    theta = (1.0 + sec.flow / m0) * de / kiln_diameter
    x_s = de * (m0 + sec.flow) / (burner.entrainment * m0)
    return dict(
        equivalent_diameter=float(de),
        nozzle_velocity=float(u0),
        thring_newby=float(theta),
        entrainment_length=float(x_s),
        recirculating=bool(theta < 0.75),
        nozzle_flow=float(m0),
    )


def entrained_o2_share(burner, jet: dict, o2_needed: float, x) -> np.ndarray:
    r"""Share of the fuels' O2 demand that their jet holds at the distances ``x`` from the
    burner: the primary air's O2 and that of the secondary air entrained so far,
    Ricou-Spalding :math:`\dot m_j = C_e \dot m_0 x/d_e` (the jet's mass flow, its excess
    over the nozzle fluid the secondary air taken in, all of it from :math:`x_s`):

    .. math:: s(x) = \min\Big(1, \frac{\dot n_{O_2,p} + \dot n_{O_2,a}\,
              \mathrm{clip}\big((C_e x/d_e - 1)\dot m_0/\dot m_a, 0, 1\big)}
              {\dot n_{O_2,needed}}\Big)

    The heat a fuel can release by :math:`x` is at most :math:`s(x)` of its heat (fast
    chemistry in the jet, about the same heat per mol of O2 for every fuel: Thornton's rule).

    Parameters
    ----------
    burner : Burner
        Its primary and secondary air (and an air ingress at the burner end, counted with the
        secondary air), and the entrainment constant :math:`C_e` (-).
    jet : dict
        :func:`fired_jet`'s numbers (``equivalent_diameter`` m, ``nozzle_flow`` kg/s).
    o2_needed : float, mol/s
        The fuels' O2 demand, mol/s.
    x : array
        Distances from the burner, m.

    Returns
    -------
    array
        The share (-) at ``x``, nondecreasing, at most 1.

    Examples
    --------
    >>> from rotarykiln.kiln.combustion.flame import AirStream, Burner
    >>> b = Burner("CH4:1", 0.001, AirStream(0.0015), AirStream(0.0165))
    >>> jet = {"equivalent_diameter": 0.05, "nozzle_flow": 0.0025}
    >>> need = 2 * 0.001 / 0.016043  # mol/s of O2 for CH4
    >>> entrained_o2_share(b, jet, need, [0.0, 0.5, 2.0]).round(3).tolist()
    [0.087, 0.406, 1.0]

    References
    ----------
    F.P. Ricou, D.B. Spalding, J. Fluid Mech. 11 (1961) 21; flames.md section 2 (the
    two-stream form); W.M. Thornton, Philos. Mag. 33 (1917) 196 (heat per O2 consumed).
    """
    p = burner.primary_air
    around = [a for a in burner.flame_air if a is not p]
    o2_p = p.moles * p.o2_fraction
    o2_a = sum(a.moles * a.o2_fraction for a in around)
    m_a = sum(a.flow for a in around)
    m0, de = jet["nozzle_flow"], jet["equivalent_diameter"]
    x = np.asarray(x, dtype=float)
    if m_a > 0:
        taken = np.clip((burner.entrainment * x / de - 1.0) * m0 / m_a, 0.0, 1.0)
    else:
        taken = np.zeros_like(x)
    return np.minimum((o2_p + o2_a * taken) / o2_needed, 1.0)


def _jet_of(flame) -> dict:
    return dict(
        equivalent_diameter=flame.equivalent_diameter,
        nozzle_flow=flame.nozzle_flow,
    )


def _molar(species: str) -> float:
    from rotarykiln.chemistry.species import default_species

    return default_species()[species].molar_mass


@dataclass(frozen=True)
class ReleaseTable:
    """Heat-release weights per cell from a cumulative release table against the distance
    from the burner (picklable callable of the cell centres z, m)."""

    distance: tuple
    cumulative: tuple
    length: float
    counter_current: bool

    def __call__(self, z):
        from rotarykiln.kiln.combustion.flame import distance_from_burner

        x = distance_from_burner(z, self.length, self.counter_current)
        xb = np.interp(x, self.distance, self.cumulative)
        return np.abs(np.diff(xb)) + 0.0
