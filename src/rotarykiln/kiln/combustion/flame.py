r"""The burner of a direct-fired kiln: its streams, its flame and where the fuel burns.

A burner at the gas inlet end fires ``fuel`` with a primary air stream (through the burner,
mixed with the fuel in the nozzle fluid) and a secondary air stream (around it: from the cooler
or the hood). :func:`fire` turns those inputs into what the kiln's gas balance needs:

- the **products** of complete combustion of all the fuel with all the air (GRI-Mech 3.0
  thermochemistry, water as vapour; by elements,
  :func:`rotarykiln.materials.combustion.complete_combustion`, without Cantera per case; a
  rich mixture by Cantera's equilibrium at 1200 K, :func:`rotarykiln.materials.gas.burn_fuel`):
  their property table, mass flow, the temperature of the unburnt mixture (the streams mixed
  at constant enthalpy), the heat of combustion at that state and the adiabatic temperature of
  the fully mixed products;
- the **heating values** of the fuel input, LHV and HHV (W), for the energy balance sheet
  (:func:`rotarykiln.materials.gas.fuel_data`);
- the **jet numbers** of the burner (when the nozzle diameter is given): Thring-Newby
  equivalent nozzle diameter :math:`d_e = 2\dot m_0/\sqrt{\pi\rho_a \dot G_0}`, the
  Thring-Newby parameter :math:`\theta = (1 + \dot m_a/\dot m_0)\,d_e/D` (close to the
  Craya-Curtet number; recirculation below about 0.75), the distance over which the jet
  entrains all the secondary air :math:`x_s = d_e(\dot m_0 + \dot m_a)/(C_e \dot m_0)`
  (Ricou-Spalding, :math:`C_e = 0.32`), the recirculation-zone length
  :math:`x_w = (R - d_e/2)/0.2`, and the flame length of Hawthorne, Weddell & Hottel for the
  nozzle fluid (fuel + primary air)

  .. math:: \frac{L_f}{d_0} = \frac{5.3}{C_T}\sqrt{\frac{T_F}{\alpha_T T_N}
            \left[C_T + (1 - C_T)\frac{M_s}{M_N}\right]}

  with :math:`C_T` the mole fraction of nozzle fluid in its stoichiometric mixture with air
  (1 when the nozzle fluid is already lean), :math:`T_F` its adiabatic flame temperature,
  :math:`\alpha_T = 1` (:func:`rotarykiln.heat.flames.hawthorne_flame_length`);
- the **dissociation** of the products (``products: equilibrium``, the default): their
  dissociation heat at equilibrium (:mod:`rotarykiln.materials.dissociation`; interpolated
  from the fuel and oxidiser's table over the equivalence ratio when every air stream has one
  composition, :func:`rotarykiln.materials.combustion.dissociation_table`), carried by the
  kiln gas, and the equilibrium adiabatic temperature; ``complete`` keeps the frozen products;
- **where the fuel burns**, by the combustion model:

  - ``instant`` (default): the fuel burns completely where it enters (Hanein et al. 2017, the
    SimCem kiln): the gas enters at the adiabatic temperature of the fully mixed products. It
    is the upper bound of the mixed-cup gas temperature the mixing model allows;
  - ``stirred``: the recirculation zone of a confined jet (Thring-Newby parameter below
    0.75: flames.md section 7's recommended default) as a well-stirred reactor: the fuel burns
    out inside it, and its gas is mixed over the recirculation length :math:`x_w` (given as
    ``recirculation_length`` or from the nozzle) by an axial conductance strong enough for a
    zone Peclet number of 0.1; plug flow beyond. It needs :math:`x_w`;
  - ``burnout``: mixing-limited burn-out along the flame, the self-similar jet profile of
    flames.md section 2, with :math:`\xi = x/L_f` and :math:`m = 1.4`

    .. math:: X_b(\xi) = \xi^{1+m} + \xi\frac{1+m}{m}(1 - \xi^m),\qquad
              q'(x) = Q\,\frac{dX_b}{dx} = \frac{Q}{L_f}\frac{1+m}{m}(1 - \xi^m)

    (:func:`rotarykiln.heat.flames.burnout_fraction`), the heat released into the mixed gas,
    which enters at the temperature of the unburnt mixture. It needs the flame length
    (``flame_length``, or the nozzle diameter for the Hawthorne-Weddell-Hottel length).

References
----------
T. Hanein, F.P. Glasser, M.N. Bannerman, Adv. Appl. Ceram. 116 (2017) 207 (instant burn-out);
M.W. Thring, M.P. Newby, 4th Symp. Combust. (1953) 789 (equivalent nozzle, recirculation);
F.P. Ricou, D.B. Spalding, J. Fluid Mech. 11 (1961) 21 (entrainment 0.32);
W.R. Hawthorne, D.S. Weddell, H.C. Hottel, 3rd Symp. Combust. (1949) 266 (flame length);
flames.md sections 1, 2 and 7 of the project's reference notes.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from rotarykiln.errors import InputError, check_positive
from rotarykiln.heat.flames import burnout_fraction, hawthorne_flame_length
from rotarykiln.materials.combustion import (
    complete_combustion,
    dissociated_adiabatic_temperature,
    dissociation_table,
    equivalence_ratio,
    mixing_temperature,
    table_pair,
)
from rotarykiln.materials.dissociation import (
    DISSOCIATION_SPECIES,
    dissociation_heat,
    equilibrium_adiabatic_temperature,
)
from rotarykiln.materials.gas import (
    AIR,
    AIR_MOLAR_MASS,
    AIR_O2,
    R_UNIVERSAL,
    T_REF,
    BurntGas,
    burn_fuel,
    molar_mass,
    parse_composition,
)

__all__ = [
    "AirStream",
    "mixed_oxidiser",
    "Burner",
    "Flame",
    "fire",
    "COMBUSTION_MODELS",
]

#: How the fuel burns along the kiln (docs/flames.md).
COMBUSTION_MODELS = ("instant", "burnout", "stirred", "particles")
#: Shares of the fuel's heat whose release distance the particles model reports (summary).
RELEASE_SHARES = (0.9, 0.99)
#: Peclet number u x_w / D of a stirred recirculation zone: well mixed (D = 10 u x_w).
STIRRED_PECLET = 0.1
PRODUCT_MODELS = ("equilibrium", "complete")
ENTRAINMENT = 0.32  # Ricou & Spalding (1961), far field
JET_SPREAD = 0.2  # half-width growth rate of a round jet, flames.md section 2
H2O_VAPORISATION = 44.004e3  # J/mol at 298.15 K


@dataclass(frozen=True)
class AirStream:
    """An oxidiser stream into the burner end: ``flow`` (kg/s), ``temperature`` (K) and
    ``composition`` by mole (default :data:`~rotarykiln.materials.gas.AIR`; O2-enriched air,
    pure O2, recirculated flue gas with its O2)."""

    flow: float
    temperature: float = T_REF
    composition: str = AIR

    def __post_init__(self):
        if not np.isfinite(self.flow) or self.flow < 0:
            raise InputError("burner.air.flow", self.flow, ">= 0 kg/s")
        check_positive("burner.air.temperature", self.temperature, "K")

    @property
    def molar_mass(self) -> float:
        """Molar mass of the stream, kg/mol."""
        return AIR_MOLAR_MASS if self.composition == AIR else molar_mass(self.composition)

    @property
    def o2_fraction(self) -> float:
        """O2 mole fraction of the stream, -."""
        return AIR_O2 if self.composition == AIR else _o2_fraction(self.composition)

    @property
    def moles(self) -> float:
        """Molar flow, mol/s."""
        return self.flow / self.molar_mass


def _o2_fraction(composition: str) -> float:
    x = dict(parse_composition(composition))
    return float(x.get("O2", 0.0)) / float(sum(x.values()))


def mixed_oxidiser(streams) -> str:
    r"""The composition by mole of oxidiser streams mixed, as Cantera text.

    .. math:: x_k = \frac{\sum_s \dot n_s x_{k,s}}{\sum_s \dot n_s}

    Parameters
    ----------
    streams : sequence of AirStream
        The streams (their flows, kg/s, and compositions by mole).

    Returns
    -------
    str
        Mole fractions, dimensionless (:data:`~rotarykiln.materials.gas.AIR` itself when every
        stream that flows is air).

    Examples
    --------
    >>> o2 = AirStream(0.031999, 298.15, "O2:1")  # 1 mol/s
    >>> mixed_oxidiser((AirStream(1.0), o2)) == AIR, mixed_oxidiser((AirStream(1.0),)) == AIR
    (False, True)

    References
    ----------
    Ideal-gas mixing by moles (e.g. S.R. Turns, An Introduction to Combustion, 3rd ed. (2012),
    ch. 2).
    """
    flowing = [s for s in streams if s.flow > 0]
    if all(s.composition == AIR for s in flowing):
        return AIR
    moles: dict[str, float] = {}
    for s in flowing:
        for name, x in parse_composition(s.composition):
            moles[name] = moles.get(name, 0.0) + s.moles * x
    total = sum(moles.values())
    return ", ".join(f"{k}:{v / total:.12g}" for k, v in sorted(moles.items()))


@dataclass(frozen=True)
class Burner:
    """Burner inputs in SI units.

    ``fuel``: composition by mole (``"CH4:1"``); ``fuel_flow`` (kg/s); ``fuel_temperature`` (K);
    ``primary_air``, ``secondary_air`` (:class:`AirStream`); ``nozzle_diameter`` (m, of the
    nozzle carrying fuel and primary air; None if unknown); ``combustion`` (one of
    :data:`COMBUSTION_MODELS`); ``flame_length`` (m, an override of the computed length);
    ``entrainment`` (-, Ricou-Spalding constant); ``ingress_air`` (:class:`AirStream`, air
    leaking in at the feed end) and ``ingress_at_burner`` (True when the burner is at the feed
    end, a co-current kiln: the ingress then joins the burner's air; otherwise it mixes into the
    exhaust leaving the feed end, outside the kiln's gas balance); ``products``
    (``equilibrium``: the products dissociate at equilibrium, their dissociation heat carried
    by the gas, :mod:`rotarykiln.materials.dissociation`; ``complete``: frozen complete
    combustion products); ``fired``: solid and liquid fuels
    (:class:`~rotarykiln.kiln.combustion.fired_fuels.FiredFuel`) fired with or without the
    gaseous fuel (``fuel_flow`` may then be 0).
    """

    fuel: str
    fuel_flow: float
    primary_air: AirStream
    secondary_air: AirStream = AirStream(0.0)
    fuel_temperature: float = T_REF
    nozzle_diameter: float | None = None
    combustion: str = "instant"
    flame_length: float | None = None
    entrainment: float = ENTRAINMENT
    ingress_air: AirStream = AirStream(0.0)
    ingress_at_burner: bool = False
    products: str = "equilibrium"
    recirculation_length: float | None = None
    fired: tuple = ()

    def __post_init__(self):
        if self.fired:
            if not np.isfinite(self.fuel_flow) or self.fuel_flow < 0:
                raise InputError("burner.fuel_flow", self.fuel_flow, ">= 0 kg/s")
        else:
            check_positive("burner.fuel_flow", self.fuel_flow, "kg/s")
        if self.combustion == "particles" and not any(f.state == "solid" for f in self.fired):
            raise InputError(
                "burner.combustion", "particles", "a burner firing a solid fuel (solid_fuels)"
            )
        check_positive("burner.fuel_temperature", self.fuel_temperature, "K")
        if self.air_flow <= 0:
            raise InputError(
                "burner.primary_air.flow", self.primary_air.flow, "> 0 kg/s (a fuel needs air)"
            )
        if self.combustion not in COMBUSTION_MODELS:
            raise InputError("burner.combustion", self.combustion, " or ".join(COMBUSTION_MODELS))
        if self.products not in PRODUCT_MODELS:
            raise InputError("burner.products", self.products, " or ".join(PRODUCT_MODELS))
        if self.nozzle_diameter is not None:
            check_positive("burner.nozzle_diameter", self.nozzle_diameter, "m")
        if self.flame_length is not None:
            check_positive("burner.flame_length", self.flame_length, "m")
        if self.recirculation_length is not None:
            check_positive("burner.recirculation_length", self.recirculation_length, "m")
        check_positive("burner.entrainment", self.entrainment)

    @property
    def air_flow(self) -> float:
        """Primary plus secondary air, kg/s."""
        return self.primary_air.flow + self.secondary_air.flow

    @property
    def flame_air(self) -> tuple[AirStream, ...]:
        """The air streams that burn the fuel: primary, secondary and an ingress at the
        burner end."""
        extra = (self.ingress_air,) if self.ingress_at_burner else ()
        return (self.primary_air, self.secondary_air, *extra)

    @property
    def exhaust_ingress(self) -> AirStream:
        """The air that mixes into the exhaust outside the kiln (none: a zero flow)."""
        return AirStream(0.0) if self.ingress_at_burner else self.ingress_air


@dataclass(frozen=True)
class Flame:
    """What the kiln's gas balance needs from the burner (see the module docstring).

    ``products`` (:class:`~rotarykiln.materials.gas.BurntGas`: table, mass flow, unburnt
    mixture temperature, heat of combustion ``heat_release`` W, adiabatic temperature);
    ``fuel_lhv``, ``fuel_hhv`` (W, heating values of the fuel input at 298.15 K);
    ``sensible_input`` (W, enthalpy of the streams above 298.15 K); ``excess_air`` (-, air
    over stoichiometric air) and ``primary_excess_air`` (-, primary air only); jet numbers
    (None without a nozzle diameter): ``equivalent_diameter`` (m), ``nozzle_velocity`` (m/s),
    ``thring_newby`` (-), ``entrainment_length`` (m), ``recirculation_length`` (m),
    ``recirculating`` (bool); ``flame_length`` (m, given, or Hawthorne-Weddell-Hottel, or
    None); ``combustion`` (model name); with ``combustion: particles`` the solid fuels'
    burn-out per fuel (``fired_burnout``), the cumulative heat release against the distance
    from the burner (``release_table``) and the burning particles' absorption coefficient
    (1/m) at the same distances (``particle_absorption``).
    """

    burner: Burner
    products: BurntGas
    fuel_lhv: float
    fuel_hhv: float
    sensible_input: float
    excess_air: float
    primary_excess_air: float
    equivalent_diameter: float | None
    nozzle_velocity: float | None
    thring_newby: float | None
    entrainment_length: float | None
    recirculation_length: float | None
    recirculating: bool | None
    flame_length: float | None
    combustion: str
    dissociation: object = None
    equilibrium_temperature: float | None = None
    ash_flow: float = 0.0
    fired_burnout: dict | None = None
    release_table: object = None
    particle_absorption: tuple | None = None
    o2_demand: float | None = None
    nozzle_flow: float | None = None

    @property
    def adiabatic_temperature(self) -> float:
        """Adiabatic temperature of the fully mixed products, K: at equilibrium (dissociated)
        with ``products: equilibrium``, frozen otherwise."""
        if self.equilibrium_temperature is not None:
            return self.equilibrium_temperature
        return self.products.adiabatic_temperature

    @property
    def burns_at_inlet(self) -> bool:
        """Whether the fuel's heat enters with the gas (``instant``, ``stirred``: the products
        at their adiabatic temperature) rather than released along the kiln (``burnout``)."""
        return self.combustion in ("instant", "stirred")

    @property
    def inlet_temperature(self) -> float:
        """Temperature at which the gas enters the kiln's gas balance, K."""
        if self.burns_at_inlet:
            return self.adiabatic_temperature
        return self.products.inlet_temperature

    def stirred_zone(self, length: float, counter_current: bool):
        r"""(z_start, z_end, K) of the ``stirred`` model's recirculation zone, or None.

        The zone is the recirculation length from the burner end (``recirculation_length``
        of the burner, or Thring-Newby's :math:`x_w`), at most the kiln; K (W m/K) is the axial
        conductance of a well-stirred gas, :math:`\dot m c_p x_w / Pe` with Pe =
        :data:`STIRRED_PECLET`, the products' c_p at the adiabatic temperature.
        """
        if self.combustion != "stirred":
            return None
        x_w = min(float(self.recirculation_length), length)
        p = self.products
        k = p.mass_flow * float(p.table.cp(self.adiabatic_temperature)) * x_w / STIRRED_PECLET
        return (length - x_w, length, k) if counter_current else (0.0, x_w, k)

    @property
    def heat_release(self) -> float:
        """Heat released inside the kiln's gas balance, W (0 for instant burn-out)."""
        return 0.0 if self.burns_at_inlet else self.products.heat_release

    def release_profile(self, length: float, counter_current: bool):
        """Weights of the heat release over cells (callable of cell centres z, m), or None."""
        if self.burns_at_inlet:
            return None
        if self.release_table is not None:
            from rotarykiln.kiln.combustion.fired_fuels import ReleaseTable

            return ReleaseTable(*self.release_table, length, counter_current)
        return BurnoutProfile(length, float(self.flame_length), counter_current)

    def release_distance(self, share: float) -> float | None:
        """Distance from the burner (m) within which the share ``share`` (-, in (0, 1]) of the
        fuel's heat is released, from the particles model's cumulative release
        (``release_table``, linear between its points); None for the other models.

        The length of a solid-fuel flame is read off this burn-out: 90 % and 99 % of the heat
        are in the run summary (``heat_released_90pct_m``, ``heat_released_99pct_m``).
        """
        if self.release_table is None:
            return None
        if not 0.0 < share <= 1.0:
            raise InputError("share", share, "a fraction in (0, 1]")
        x, cumulative = (np.asarray(v, dtype=float) for v in self.release_table)
        k = int(np.searchsorted(cumulative, share))  # first point at or past the share
        if k == 0:
            return float(x[0])
        c0, c1 = cumulative[k - 1], cumulative[k]
        return float(x[k - 1] + (x[k] - x[k - 1]) * (share - c0) / (c1 - c0))

    def summary(self) -> dict:
        """The burner's figures, SI units, for the run summary."""
        out = {
            "combustion_model": self.combustion,
            "fuel_lhv_input_W": self.fuel_lhv,
            "fuel_hhv_input_W": self.fuel_hhv,
            "excess_air": self.excess_air,
            "primary_excess_air": self.primary_excess_air,
            "adiabatic_temperature_K": self.adiabatic_temperature,
            "adiabatic_temperature_frozen_K": self.products.adiabatic_temperature,
            "products_model": self.burner.products,
            "flue_gas_flow_kg_s": self.products.mass_flow,
        }
        for key, value in (
            ("flame_length_m", self.flame_length),
            ("equivalent_nozzle_diameter_m", self.equivalent_diameter),
            ("nozzle_velocity_m_s", self.nozzle_velocity),
            ("thring_newby_parameter", self.thring_newby),
            ("entrainment_length_m", self.entrainment_length),
            ("recirculation_length_m", self.recirculation_length),
        ):
            if value is not None:
                out[key] = value
        if self.release_table is not None:
            for share in RELEASE_SHARES:
                out[f"heat_released_{round(100 * share)}pct_m"] = self.release_distance(share)
        if self.burner.fired:
            out["ash_to_bed_kg_s"] = self.ash_flow
            comp = dict(self.products.composition)
            out["SO2_mole_fraction_wet"] = comp.get("SO2", 0.0)
            for label, x in (self.fired_burnout or {}).items():
                out[f"burnout_{label}"] = x
        return out


@dataclass(frozen=True)
class BurnoutProfile:
    """Heat-release weights of the ``burnout`` model per cell (picklable callable of z)."""

    length: float
    flame_length: float
    counter_current: bool

    def __call__(self, z):
        x = distance_from_burner(z, self.length, self.counter_current)
        xb = burnout_fraction(x / self.flame_length)
        return np.abs(np.diff(xb)) + 0.0


def distance_from_burner(z, length: float, counter_current: bool) -> np.ndarray:
    """Distance (m) from the burner of the cell faces around the cell centres ``z`` (m): the
    burner at z = ``length`` (counter-current) or at z = 0."""
    z = np.asarray(z, dtype=float)
    if z.size == 1:
        edges = np.array([0.0, length])
    else:
        mid = 0.5 * (z[1:] + z[:-1])
        edges = np.concatenate([[0.0], mid, [length]])
    return (length - edges) if counter_current else edges


@lru_cache(maxsize=64)
def _fuel_data(fuel: tuple[tuple[str, float], ...]):
    """Molar mass (kg/mol), O2 demand (mol/mol), LHV and HHV (J/kg) of a fuel at 298.15 K
    (:func:`rotarykiln.materials.gas.fuel_data`: computed once per fuel, cached)."""
    from rotarykiln.materials.gas import fuel_data

    return fuel_data(fuel)


def fire(burner: Burner, kiln_diameter: float, kiln_length: float | None = None) -> Flame:
    """Products, heating values, jet numbers and flame length of ``burner`` in a kiln.

    Parameters
    ----------
    burner : Burner
        Fuel, air streams and nozzle (SI units).
    kiln_diameter : float, m
        Inner diameter of the kiln.
    kiln_length : float, m, optional
        A flame override longer than the kiln is refused.

    Returns
    -------
    Flame
        Products, heating values (W), jet numbers and flame length (m) of the burner.

    Examples
    --------
    Barr's UBC pilot kiln, trial T4 (flows in normal litres per second, 0 degC):

    >>> n = 1e-3 / 0.022414  # mol per normal litre
    >>> b = Burner("CH4:1", 1.97 * n * 0.016043, AirStream(17.4 * n * AIR_MOLAR_MASS),
    ...            AirStream(43.0 * n * AIR_MOLAR_MASS), nozzle_diameter=0.04)
    >>> f = fire(b, 0.411)
    >>> round(f.fuel_lhv / 1e3, 1), round(f.products.adiabatic_temperature, -1)
    (70.5, 1090.0)
    >>> round(f.flame_length, 2), f.recirculating
    (0.64, True)

    References
    ----------
    See the module docstring.
    """
    check_positive("kiln.diameter", kiln_diameter, "m")
    if burner.fired:
        return _fire_fired(burner, kiln_diameter, kiln_length)
    fuel = parse_composition(burner.fuel)
    mm_fuel, o2_demand, lhv, hhv = _fuel_data(fuel)
    streams = _streams(burner.flame_air)
    products = complete_combustion(fuel, burner.fuel_flow, burner.fuel_temperature, streams)
    if products is None:  # rich: Cantera's equilibrium products at 1200 K
        air = sum(a.flow for a in burner.flame_air)
        t_air = mixing_temperature(streams)
        oxidiser = mixed_oxidiser(burner.flame_air)
        products = burn_fuel(fuel, burner.fuel_flow, air, burner.fuel_temperature, t_air, oxidiser)
        streams = None
    n_o2_needed = burner.fuel_flow / mm_fuel * o2_demand
    if n_o2_needed > 0:  # the air ratio: O2 supplied over O2 needed
        lam = sum(a.moles * a.o2_fraction for a in burner.flame_air) / n_o2_needed
        p = burner.primary_air
        lam_p = p.moles * p.o2_fraction / n_o2_needed
    else:
        lam = lam_p = float("inf")
    sensible = products.mass_flow * float(products.table.enthalpy(products.inlet_temperature))
    jet = dict.fromkeys(
        (
            "equivalent_diameter",
            "nozzle_velocity",
            "thring_newby",
            "entrainment_length",
            "recirculation_length",
            "recirculating",
        )
    )
    flame_length = burner.flame_length
    if burner.nozzle_diameter is not None:
        jet, hwh = _jet_numbers(burner, fuel, mm_fuel, lam_p, kiln_diameter)
        if flame_length is None:
            flame_length = hwh
    if burner.recirculation_length is not None:
        jet["recirculation_length"] = float(burner.recirculation_length)
    stirred, burnout = burner.combustion == "stirred", burner.combustion == "burnout"
    x_w = jet["recirculation_length"]
    _check_length("recirculation", burner.recirculation_length, x_w, stirred, kiln_length)
    _check_length("flame", burner.flame_length, flame_length, burnout, kiln_length)
    dissociation, t_eq = _dissociation_of(burner, products, fuel, streams)
    return Flame(
        burner=burner,
        products=products,
        dissociation=dissociation,
        equilibrium_temperature=t_eq,
        fuel_lhv=burner.fuel_flow * lhv,
        fuel_hhv=burner.fuel_flow * hhv,
        sensible_input=sensible,
        excess_air=lam - 1.0,
        primary_excess_air=lam_p - 1.0,
        flame_length=None if flame_length is None else float(flame_length),
        combustion=burner.combustion,
        **jet,
    )


def _streams(air) -> tuple[tuple[float, float, str], ...]:
    """(flow kg/s, temperature K, composition) of the air streams that flow."""
    return tuple((s.flow, s.temperature, s.composition) for s in air if s.flow > 0)


def _dissociation_of(burner: Burner, products, fuel=None, streams=None):
    """The dissociation heat of the products and their equilibrium adiabatic temperature (K),
    or (None, None) with ``products: complete``.

    Products by elements (``streams``: the oxidiser streams they were burnt with) take their
    dissociation heat from the fuel and oxidiser's table
    (:func:`~rotarykiln.materials.combustion.dissociation_table`) when every stream has one
    composition, else from Cantera for their composition; their equilibrium adiabatic
    temperature is the root on the kiln's splines
    (:func:`~rotarykiln.materials.combustion.dissociated_adiabatic_temperature`). Cantera's
    products (``streams`` None: a rich mixture, or solid and liquid fuels) are treated by
    Cantera alone: :func:`~rotarykiln.materials.dissociation.dissociation_heat` and
    :func:`~rotarykiln.materials.dissociation.equilibrium_adiabatic_temperature`."""
    if burner.products != "equilibrium":
        return None, None
    comp = tuple((k, x) for k, x in products.composition if k in DISSOCIATION_SPECIES)
    if streams is None:
        heat = dissociation_heat(comp)
        return heat, equilibrium_adiabatic_temperature(comp, products.adiabatic_temperature)
    oxidisers = {parse_composition(c) for _, _, c in streams}
    oxidiser = next(iter(oxidisers))
    if len(oxidisers) == 1 and table_pair(fuel, oxidiser):
        # lean within round-off (complete_combustion): phi at most 1
        phi = min(equivalence_ratio(fuel, burner.fuel_flow, streams), 1.0)
        heat = _table_heat(fuel, oxidiser, phi, comp)
    else:
        heat = dissociation_heat(comp)
    return heat, _equilibrium_temperature(products, heat)


@lru_cache(maxsize=256)
def _equilibrium_temperature(products, heat) -> float:
    """:func:`~rotarykiln.materials.combustion.dissociated_adiabatic_temperature`, kept per
    products and dissociation heat (objects kept by their own caches: the same case again)."""
    return dissociated_adiabatic_temperature(products, heat)


@lru_cache(maxsize=256)
def _table_heat(fuel, oxidiser, phi: float, composition):
    """The dissociation heat of products of ``composition`` at the equivalence ratio ``phi``
    from the table of ``fuel`` and ``oxidiser`` (one object per case, as Cantera's cache
    gives)."""
    return dissociation_table(fuel, oxidiser).heat(phi, composition)


def _check_length(what: str, given, value, needed: bool, kiln_length) -> None:
    """Refuse a ``burner.<what>_length`` override longer than the kiln, or a model that needs
    the length (``stirred``: recirculation, ``burnout``: flame) without it."""
    field = f"burner.{what}_length"
    model = "stirred" if what == "recirculation" else "burnout"
    if needed and value is None:
        accepted = f"given, or a burner.nozzle_diameter to compute it (the {model} model needs it)"
        raise InputError(field, None, accepted)
    if given is not None and kiln_length is not None and given > kiln_length:
        raise InputError(field, f"{given:.6g} m", f"<= the kiln length ({kiln_length:.6g} m)")


def _jet_numbers(burner: Burner, fuel, mm_fuel, lam_p, kiln_diameter):
    """Thring-Newby / Ricou-Spalding jet numbers and the HWH flame length (see the module)."""
    prim, sec = burner.primary_air, burner.secondary_air
    m0 = burner.fuel_flow + prim.flow
    n0 = burner.fuel_flow / mm_fuel + prim.moles
    mm0 = m0 / n0
    # nozzle-fluid temperature: fuel and primary air mixed at constant heat capacity per mole
    nf = burner.fuel_flow / mm_fuel
    na = prim.moles
    t0 = (nf * burner.fuel_temperature + na * burner.primary_air.temperature) / (nf + na)
    rho0 = 101325.0 * mm0 / (R_UNIVERSAL * t0)
    d0 = burner.nozzle_diameter
    u0 = m0 / (rho0 * np.pi * d0**2 / 4.0)
    t_s = burner.secondary_air.temperature if burner.secondary_air.flow > 0 else t0
    mm_s = sec.molar_mass if sec.flow > 0 else AIR_MOLAR_MASS
    rho_a = 101325.0 * mm_s / (R_UNIVERSAL * t_s)
    de = 2.0 * m0 / np.sqrt(np.pi * rho_a * m0 * u0)
    ma = burner.secondary_air.flow
    theta = (1.0 + ma / m0) * de / kiln_diameter
    x_s = de * (m0 + ma) / (burner.entrainment * m0)
    x_w = max(kiln_diameter / 2.0 - de / 2.0, 0.0) / JET_SPREAD
    # flame length of the nozzle fluid (fuel + primary air) burning with the surroundings
    if lam_p >= 1.0:
        c_t = 1.0
        t_f = _adiabatic(fuel, burner, ((prim.flow, t0, prim.composition),))
    else:
        # the surroundings (secondary air) supply the rest of the O2
        surround = sec if sec.flow > 0 else AirStream(0.0)
        n_add = (1.0 - lam_p) * (burner.fuel_flow / mm_fuel) * _fuel_data(fuel)[1]
        n_add /= surround.o2_fraction
        c_t = n0 / (n0 + n_add)
        m_add = n_add * surround.molar_mass
        oxidisers = ((prim.flow, t0, prim.composition), (m_add, t0, surround.composition))
        t_f = _adiabatic(fuel, burner, oxidisers)
    hwh = hawthorne_flame_length(d0, c_t, t_f, t0, mm_s, mm0)
    jet = dict(
        equivalent_diameter=float(de),
        nozzle_velocity=float(u0),
        thring_newby=float(theta),
        entrainment_length=float(x_s),
        recirculation_length=float(x_w),
        recirculating=bool(theta < 0.75),
    )
    return jet, hwh


def _adiabatic(fuel, burner: Burner, oxidisers) -> float:
    """Adiabatic temperature (frozen products, K) of the burner's fuel burnt with the
    ``oxidisers`` streams (flow kg/s, temperature K, composition): by elements, or with
    Cantera for a rich mixture."""
    b = complete_combustion(fuel, burner.fuel_flow, burner.fuel_temperature, oxidisers)
    if b is None:
        flowing = tuple(AirStream(*s) for s in oxidisers if s[0] > 0)
        b = burn_fuel(
            fuel,
            burner.fuel_flow,
            sum(s.flow for s in flowing),
            burner.fuel_temperature,
            mixing_temperature(oxidisers),
            mixed_oxidiser(flowing),
        )
    return b.adiabatic_temperature


def _fire_fired(burner: Burner, kiln_diameter: float, kiln_length: float | None) -> Flame:
    """:func:`fire` for a burner firing solid or liquid fuels
    (:mod:`rotarykiln.kiln.combustion.fired_fuels`): products by elements; with a nozzle
    diameter the jet numbers of the primary air carrying the fuels
    (:func:`~rotarykiln.kiln.combustion.fired_fuels.fired_jet`), whose entrainment limits the
    ``particles`` model's release, but no Hawthorne-Weddell-Hottel flame length (it does not
    hold for a particle-laden jet: give ``flame_length`` for the ``burnout`` model)."""
    import dataclasses

    from rotarykiln.kiln.combustion.fired_fuels import (
        burn_fired_fuels,
        fired_jet,
        particle_release,
    )

    products, lhv, hhv, o2_needed, ash = burn_fired_fuels(burner)
    lam = sum(a.moles * a.o2_fraction for a in burner.flame_air) / o2_needed
    p = burner.primary_air
    lam_p = p.moles * p.o2_fraction / o2_needed
    jet = dict.fromkeys(
        ("equivalent_diameter", "nozzle_velocity", "thring_newby", "entrainment_length")
    )
    jet["recirculating"] = None
    nozzle_flow = None
    if burner.nozzle_diameter is not None:
        jet = fired_jet(burner, kiln_diameter)
        nozzle_flow = jet.pop("nozzle_flow")
    x_w = burner.recirculation_length
    if burner.combustion == "stirred" and x_w is None and burner.nozzle_diameter is not None:
        x_w = max(kiln_diameter / 2.0 - burner.nozzle_diameter / 2.0, 0.0) / JET_SPREAD
    jet["recirculation_length"] = None if x_w is None else float(x_w)
    _check_length(
        "recirculation",
        burner.recirculation_length,
        x_w,
        burner.combustion == "stirred",
        kiln_length,
    )
    flame_length = burner.flame_length
    if burner.combustion == "burnout" and flame_length is None:
        raise InputError(
            "burner.flame_length", None, "given (the burnout model of a solid or liquid fuel)"
        )
    _check_length("flame", burner.flame_length, flame_length, False, kiln_length)
    dissociation, t_eq = _dissociation_of(burner, products)
    sensible = products.mass_flow * float(products.table.enthalpy(products.inlet_temperature))
    flame = Flame(
        burner=burner,
        products=products,
        dissociation=dissociation,
        equilibrium_temperature=t_eq,
        fuel_lhv=lhv,
        fuel_hhv=hhv,
        sensible_input=sensible,
        excess_air=lam - 1.0,
        primary_excess_air=lam_p - 1.0,
        flame_length=None if flame_length is None else float(flame_length),
        combustion=burner.combustion,
        ash_flow=ash,
        o2_demand=float(o2_needed),
        nozzle_flow=nozzle_flow,
        **jet,
    )
    if burner.combustion != "particles":
        return flame
    if kiln_length is None:
        raise InputError("kiln.length", None, "given (the particles model burns along the kiln)")
    table, ends, kappa = particle_release(flame, kiln_diameter, kiln_length)
    return dataclasses.replace(
        flame, release_table=table, fired_burnout=ends, particle_absorption=kappa
    )
