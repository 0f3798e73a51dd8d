"""Named rate laws usable from reaction YAML files, evaluated on many kiln cells at once.

Each rate law maps a :class:`RateContext` (the state of ``n`` cells) and its parameters to the
consumption rate of the reaction's basis species, kg/(s m), shape ``(n,)``. The physics lives in
:mod:`~rotarykiln.chemistry.drying`, :mod:`~rotarykiln.chemistry.calcination`,
:mod:`~rotarykiln.chemistry.activation` and :mod:`~rotarykiln.chemistry.pyrolysis`; this module only
adapts them to the cell state. Laws and the extra inputs they read:

=========================  ===========================================  ========================
law                        model                                        cell inputs needed
=========================  ===========================================  ========================
boiling_drying             seed 004 below T_boil + boiling heat sink    drying_conductance W/mK
                           (default: reaction ``drying``)               (bed_outlet_temperature)
ahmad_drying               critical-moisture drying (seed 004)          drying_conductance W/mK
heat_limited_drying        all bed heat evaporates at T_boil            bed_heat_input W/m
luisser_calcination        Luisser rate (seed 004), no equilibrium      bed_mass_flow_in
equilibrium_calcination    Luisser x (1 - p_CO2/p_eq), Baker p_eq       bed_mass_flow_in, p_CO2
                           [p_CO2 of the bed's voids: ``co2_pressure``]
ortiz_activation           Ortiz et al. steam activation, onset T       steam_mass_flow kg/s
wen_yen                    kerogen 5-rate scheme, step 1..5             bed_mass_flow_in (3-5)
arrhenius                  A (T/T_ref)^b exp(-E/RT) m'_basis prod p^n   (none)
mass_action                A exp(-E/RT) prod rho_i^n_i (Mastorakos form)  (none)
                           [x Lea-Parker melt fraction: ``melt``]
carbonate_equilibrium      A exp(-E/RT) m'_basis (1 - p_CO2/p_eq),      p_CO2
                           Holland & Powell p_eq (calcite, dolomite...)
=========================  ===========================================  ========================
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from rotarykiln.chemistry.activation import onset_window, ortiz_activation_rate
from rotarykiln.chemistry.calcination import R_GAS, calcination_rate_with_equilibrium
from rotarykiln.chemistry.drying import (
    LATENT_HEAT_AHMAD,
    ahmad_critical_moisture_drying_rate,
    boiling_drying_rate,
    heat_limited_drying_rate,
    water_boiling_temperature,
)
from rotarykiln.chemistry.pyrolysis import _R_KCAL, WEN_YEN_PARAMETERS
from rotarykiln.errors import InputError

__all__ = ["RateLaw", "RateContext", "RATE_LAWS", "register_rate_law", "MOISTURE"]

MOISTURE = "H2O(l)"
ATM = 101325.0


class RateContext:
    """The state of ``n`` cells as rate laws see it (built by the mechanism).

    Attributes
    ----------
    T_bed, T_gas : ndarray
        K, shape (n,).
    n : int
    """

    def __init__(self, state, species):
        self.state = state
        self.species = species
        self.T_bed = state.T_bed
        self.T_gas = state.T_gas
        self.n = state.T_bed.shape[0]
        flows = state.bed_mass_flow
        total = np.zeros(self.n)
        for v in flows.values():
            total = total + v
        self._total = total
        with np.errstate(divide="ignore", invalid="ignore"):
            self._holdup_per_flow = np.where(total > 0, state.bed_mass_per_length / total, 0.0)

    def flow(self, name: str) -> np.ndarray:
        """Bed mass flow of species ``name``, kg/s (0 if absent)."""
        v = self.state.bed_mass_flow.get(name)
        return np.zeros(self.n) if v is None else v

    def dry_flow(self) -> np.ndarray:
        """Bed mass flow without moisture, kg/s."""
        return self._total - self.flow(MOISTURE)

    def holdup(self, name: str) -> np.ndarray:
        """Mass of bed species ``name`` per kiln length, kg/m (all bed species move together)."""
        return self.flow(name) * self._holdup_per_flow

    def flow_in(self, name: str, law: str):
        """Inlet bed mass flow of ``name``, kg/s: the reference of conversions (one value, or
        one per cell when the cells belong to several kilns of a batch)."""
        ref = self.state.bed_mass_flow_in
        if name not in ref:
            raise InputError(
                f"cell_state.bed_mass_flow_in.{name}",
                "missing",
                f"given (rate law {law} needs the inlet flow of {name} as conversion reference)",
            )
        return ref[name]

    def p(self, name: str) -> np.ndarray:
        """Partial pressure of gas species ``name`` over the bed, Pa (0 if absent)."""
        v = self.state.partial_pressure.get(name)
        return np.zeros(self.n) if v is None else v

    def input(self, name: str, law: str) -> np.ndarray:
        """An extra cell input (``steam_mass_flow``, ``drying_conductance``, ``bed_heat_input``)."""
        if name not in self.state.inputs:
            raise InputError(
                f"cell_state.inputs.{name}", "missing", f"given (needed by rate law {law})"
            )
        return self.state.inputs[name]


@dataclass(frozen=True)
class RateLaw:
    """A named rate law: defaults of its parameters and the function evaluating it."""

    name: str
    defaults: dict
    func: Callable = field(repr=False)
    description: str = ""
    choices: dict = field(default_factory=dict)
    #: Order of the rate in the flow of its basis species, from the law's parameters: 1 for a
    #: rate proportional to the basis hold-up, the ``order`` of a shrinking-core law, 0 for a
    #: heat- or supply-limited law (the solver steps an order >= 1 reactant by Newton in its
    #: flow, one of lower order in the square root of its flow).
    flow_order: Callable[[dict], float] = field(default=lambda p: 1.0, repr=False)

    def validate_params(self, given: Mapping, where: str, basis: str) -> dict:
        """Merge ``given`` into the defaults; :class:`InputError` on unknown or bad values."""
        params = dict(self.defaults)
        for k, v in given.items():
            if k not in self.defaults:
                raise InputError(
                    f"{where}.{k}",
                    "given",
                    f"a parameter of {self.name} ({', '.join(self.defaults) or 'none'})",
                )
            d = self.defaults[k]
            if k in self.choices:
                if v not in self.choices[k]:
                    raise InputError(
                        f"{where}.{k}", v, f"one of {', '.join(map(str, self.choices[k]))}"
                    )
                params[k] = v
            elif isinstance(d, bool):
                if not isinstance(v, bool):
                    raise InputError(f"{where}.{k}", v, "true or false")
                params[k] = v
            elif isinstance(d, dict):
                if not isinstance(v, Mapping):
                    raise InputError(f"{where}.{k}", v, "a mapping species -> order")
                orders = {}
                for a, b in v.items():
                    ok = isinstance(b, int | float) and not isinstance(b, bool)
                    if not ok or not math.isfinite(b):
                        raise InputError(f"{where}.{k}.{a}", b, "a finite number (an order)")
                    orders[str(a)] = float(b)
                params[k] = orders
            else:
                if v is None and d is None:
                    continue
                try:
                    fv = float(v)
                except (TypeError, ValueError):
                    raise InputError(f"{where}.{k}", v, "a number (SI units)") from None
                if not np.isfinite(fv):
                    raise InputError(f"{where}.{k}", v, "finite")
                params[k] = fv
        for k in ("A", "K_e", "latent_heat", "critical_moisture"):
            if k in params and params[k] is not None and params[k] <= 0:
                raise InputError(f"{where}.{k}", params[k], "> 0")
        if self.name == "boiling_drying":
            _check_boiling_params(params, given, where)
        if self.name == "mass_action":
            _check_mass_action_params(params, where, basis)
        if self.name == "wen_yen":
            step = params["step"]
            if step not in (1.0, 2.0, 3.0, 4.0, 5.0):
                raise InputError(f"{where}.step", step, "one of 1, 2, 3, 4, 5")
            expected = "bitumen" if step == 2 else "kerogen"
            if basis != expected:
                raise InputError(
                    f"{where}.step",
                    int(step),
                    f"consistent with basis {basis} (step 2 consumes bitumen, others kerogen)",
                )
        return params


RATE_LAWS: dict[str, RateLaw] = {}


def register_rate_law(
    name: str,
    defaults: Mapping,
    description: str = "",
    choices: Mapping | None = None,
    flow_order: Callable[[dict], float] | float = 1.0,
):
    """Decorator registering ``func(ctx, basis, params) -> ndarray`` as a named rate law.

    ``flow_order``: the rate's order in the flow of its basis species (a number, or a function
    of the parameters), see :attr:`RateLaw.flow_order`.
    """
    order = flow_order if callable(flow_order) else (lambda p, v=float(flow_order): v)

    def deco(func):
        RATE_LAWS[name] = RateLaw(
            name, dict(defaults), func, description, dict(choices or {}), flow_order=order
        )
        return func

    return deco


def _conversion_ratio(ctx: RateContext, basis: str, law: str) -> np.ndarray:
    """1 - x = Q/Q_in, clipped to [0, 1]."""
    q_in = np.asarray(ctx.flow_in(basis, law))  # one value, or one per cell (a batch)
    fed = q_in > 0
    ratio = ctx.flow(basis) / np.where(fed, q_in, 1.0)
    return np.where(fed, np.clip(ratio, 0.0, 1.0), 0.0) * np.ones(ctx.n)


@register_rate_law(
    "ahmad_drying",
    {"critical_moisture": 0.1, "latent_heat": LATENT_HEAT_AHMAD, "cap": True},
    "Ahmad (2006) critical-moisture drying",
    flow_order=0.0,  # constant-rate period: set by the heat supply, not the moisture
)
def _ahmad_drying(ctx, basis, p):
    return np.asarray(
        ahmad_critical_moisture_drying_rate(
            ctx.input("drying_conductance", "ahmad_drying"),
            ctx.T_gas,
            ctx.T_bed,
            ctx.flow(basis),
            ctx.dry_flow(),
            p["critical_moisture"],
            p["latent_heat"],
            p["cap"],
        ),
        dtype=float,
    ) * np.ones(ctx.n)


def _check_mass_action_params(params: dict, where: str, basis: str) -> None:
    """``mass_action``: basis first order, every order >= 1, density > 0, melt width > 0."""
    orders = params["orders"]
    if orders and orders.get(basis) != 1.0:
        raise InputError(
            f"{where}.orders.{basis}", orders.get(basis, "missing"), "1 (the basis is first order)"
        )
    for name, n in orders.items():
        if n < 1.0:
            raise InputError(
                f"{where}.orders.{name}", n, ">= 1 (the rate must vanish with every reactant)"
            )
    for k in ("density", "melt_width"):
        if params[k] <= 0:
            raise InputError(f"{where}.{k}", params[k], "> 0")


def _check_boiling_params(params: dict, given: Mapping, where: str) -> None:
    """``boiling_drying``: positive stiffness, width and pressure; T_boil or pressure, not both.

    Resolves ``T_boil`` (K) from the pressure when it is not given (once, at load).
    """
    for k in ("k_boil", "width", "pressure"):
        if params[k] <= 0:
            raise InputError(f"{where}.{k}", params[k], "> 0")
    if params["T_boil"] is not None:
        if params["T_boil"] <= 0:
            raise InputError(f"{where}.T_boil", params["T_boil"], "> 0 K")
        if "pressure" in given:
            raise InputError(
                f"{where}.pressure",
                given["pressure"],
                "absent when T_boil is given (T_boil follows from the pressure otherwise)",
            )
    else:
        params["T_boil"] = water_boiling_temperature(params["pressure"], params["latent_heat"])


@register_rate_law(
    "boiling_drying",
    {
        "critical_moisture": 0.1,
        "latent_heat": LATENT_HEAT_AHMAD,
        "cap": True,
        "below_boiling": True,
        "T_boil": None,
        "pressure": 101325.0,
        "k_boil": 1.0e3,
        "width": 0.25,
    },
    "seed-004 drying below the boiling point; at it the bed is held and its heat evaporates",
    flow_order=0.0,
)
def _boiling_drying(ctx, basis, p):
    # T_boil given, or resolved from the pressure at load (Clausius-Clapeyron; 373.15 K at 1 atm)
    t_boil = p["T_boil"]
    if t_boil is None:  # a caller that bypassed validate_params
        t_boil = water_boiling_temperature(p["pressure"], p["latent_heat"])
    if p["below_boiling"]:
        conductance = ctx.input("drying_conductance", "boiling_drying")
    else:
        conductance = np.zeros(ctx.n)
    return np.asarray(
        boiling_drying_rate(
            conductance,
            ctx.T_gas,
            ctx.T_bed,
            ctx.flow(basis),
            ctx.dry_flow(),
            ctx.holdup(basis),
            p["critical_moisture"],
            p["latent_heat"],
            p["cap"],
            t_boil,
            p["k_boil"],
            p["width"],
            p["below_boiling"],
            # where the moisture leaves the cell, when the solver gives it (optional input)
            T_bed_out=ctx.state.inputs.get("bed_outlet_temperature"),
        ),
        dtype=float,
    ) * np.ones(ctx.n)


@register_rate_law(
    "heat_limited_drying",
    {"latent_heat": LATENT_HEAT_AHMAD, "T_boil": 373.15, "width": 1.0},
    "heat-transfer-limited drying at the boiling point",
    flow_order=0.0,
)
def _heat_limited_drying(ctx, basis, p):
    return np.asarray(
        heat_limited_drying_rate(
            ctx.input("bed_heat_input", "heat_limited_drying"),
            ctx.T_bed,
            ctx.flow(basis),
            p["latent_heat"],
            p["T_boil"],
            p["width"],
        ),
        dtype=float,
    ) * np.ones(ctx.n)


def _luisser_mass_rate(ctx, basis, p, law):
    ratio = _conversion_ratio(ctx, basis, law)
    k = p["A"] * np.exp(-p["E"] / (R_GAS * ctx.T_bed))
    m = ctx.holdup(basis)
    # m' k (1-x)^n / (1-x): the hold-up already carries one power of (1 - x)
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.where(ratio > 0, np.where(ratio > 0, ratio, 1.0) ** (p["order"] - 1.0), 0.0)
    return k * m * f


@register_rate_law(
    "luisser_calcination",
    {"A": 9.8e4, "E": 142000.0, "order": 0.5},
    "Luisser (2004) calcination rate quoted by Ahmad (2006), no equilibrium",
    flow_order=lambda p: p["order"],
)
def _luisser(ctx, basis, p):
    return _luisser_mass_rate(ctx, basis, p, "luisser_calcination")


#: Where the driving force of a carbonate's decomposition takes its CO2 partial pressure:
#: ``freeboard`` the gas over the bed (its local CO2), ``bed`` the gas in the bed's voids,
#: taken as the bed's own CO2 at the kiln's total pressure (1 atm).
CO2_PRESSURE_CHOICES = ("freeboard", "bed")


def _co2_pressure(ctx, p):
    """CO2 partial pressure the carbonate's driving force sees, Pa (``co2_pressure`` choice).

    ``bed``: a calcining bed of stones fills its voids with the CO2 it releases, the air of the
    freeboard displaced; the decomposition then needs the CO2 equilibrium pressure to exceed
    the total pressure, 1 atm: 1173.6 K (900.5 degC) with Baker's equilibrium, where lime kilns
    are said to calcine ("calcination >= about 900 degC (1 atm CO2)", cement_lime.md 4 and 6.2,
    LRK, LIMEW). The limiting case of a deep bed of large stones; ``freeboard`` the one of a
    thin layer of fine particles swept by the kiln gas.
    """
    if p.get("co2_pressure", "freeboard") == "bed":
        return np.full(ctx.n, ATM)
    return ctx.p("CO2")


@register_rate_law(
    "equilibrium_calcination",
    {"A": 9.8e4, "E": 142000.0, "order": 0.5, "equilibrium": "baker", "co2_pressure": "freeboard"},
    "Luisser rate times (1 - p_CO2/p_eq)",
    choices={"equilibrium": ("baker", "garcia_labiano"), "co2_pressure": CO2_PRESSURE_CHOICES},
    flow_order=lambda p: p["order"],
)
def _equilibrium_calcination(ctx, basis, p):
    base = _luisser_mass_rate(ctx, basis, p, "equilibrium_calcination")
    # reuse the public function for the driving force (conversion 0: pure driving-force factor)
    drive = calcination_rate_with_equilibrium(
        ctx.T_bed,
        np.zeros(ctx.n),
        _co2_pressure(ctx, p),
        A=1.0,
        E=0.0,
        order=0.0,
        equilibrium=p["equilibrium"],
    )
    return base * drive


@register_rate_law(
    "ortiz_activation",
    {"K_e": 6.005, "T_act": 8033.0, "T_on": 1073.0, "T_off": None, "width": 0.0},
    "Ortiz et al. (2003a) steam activation of charcoal",
)
def _ortiz(ctx, basis, p):
    return np.asarray(
        ortiz_activation_rate(
            ctx.T_bed,
            ctx.input("steam_mass_flow", "ortiz_activation"),
            ctx.holdup(basis),
            p["K_e"],
            p["T_act"],
            p["T_on"],
            p["T_off"],
            p["width"],
        ),
        dtype=float,
    ) * np.ones(ctx.n)


@register_rate_law("wen_yen", {"step": 1.0}, "Wen & Yen (1977) kerogen scheme, one step")
def _wen_yen(ctx, basis, p):
    step = int(p["step"])
    a, E = WEN_YEN_PARAMETERS[step - 1]
    k = np.exp(a - E / (_R_KCAL * ctx.T_bed)) / 60.0  # 1/min -> 1/s
    if step in (1, 2):
        return k * ctx.holdup(basis)
    # steps 3-5: k x1 x2 with x2 = bitumen / initial kerogen; in hold-up: k m'_K x2
    q_in = np.asarray(ctx.flow_in("kerogen", "wen_yen"))  # one value, or one per cell
    x2 = np.where(q_in > 0, ctx.flow("bitumen") / np.where(q_in > 0, q_in, 1.0), 0.0)
    return k * ctx.holdup("kerogen") * x2


@register_rate_law(
    "arrhenius",
    {
        "A": 1.0,
        "E": 0.0,
        "b": 0.0,
        "T_ref": 1.0,
        "temperature": "bed",
        "T_on": 0.0,
        "pressure_orders": {},
    },
    "r = A (T/T_ref)^b exp(-E/(R T)) m'_basis prod (p_j/1 atm)^n_j, for T >= T_on",
    choices={"temperature": ("bed", "gas")},
)
def _arrhenius(ctx, basis, p):
    T = ctx.T_bed if p["temperature"] == "bed" else ctx.T_gas
    r = p["A"] * (T / p["T_ref"]) ** p["b"] * np.exp(-p["E"] / (R_GAS * T)) * ctx.holdup(basis)
    for gas, order in p["pressure_orders"].items():
        r = r * np.maximum(ctx.p(gas) / ATM, 0.0) ** order
    if p["T_on"] > 0:
        r = r * onset_window(T, p["T_on"])
    return r


def _bed_fractions(ctx) -> tuple[np.ndarray, np.ndarray]:
    """Total bed flow (kg/s, > 0 guarded) and its reciprocal, shape (n,)."""
    total = ctx._total
    fed = total > 0
    return total, np.where(fed, 1.0 / np.where(fed, total, 1.0), 0.0)


def _melt_fraction(ctx, width: float) -> np.ndarray:
    """Lea-Parker melt fraction of every cell's bed, from its oxides (ignited basis)."""
    from rotarykiln.chemistry.clinker import bed_oxide_flows, lea_parker_melt_fraction

    ox = bed_oxide_flows(ctx.state.bed_mass_flow, ctx.species)
    ign = sum(np.asarray(v, dtype=float) * np.ones(ctx.n) for v in ox.values())
    ok = ign > 0
    inv = np.where(ok, 1.0 / np.where(ok, ign, 1.0), 0.0)

    def w(name):
        return np.clip(np.asarray(ox[name], dtype=float) * inv, 0.0, 1.0)

    return np.asarray(
        lea_parker_melt_fraction(
            ctx.T_bed, w("Al2O3"), w("Fe2O3"), w("MgO"), w("K2O"), w("Na2O"), width
        ),
        dtype=float,
    ) * np.ones(ctx.n)


@register_rate_law(
    "mass_action",
    {"A": 1.0, "E": 0.0, "orders": {}, "density": 1500.0, "melt": "none", "melt_width": 20.0},
    "r = A exp(-E/RT) prod rho_i^n_i [mol/(m3 s)], rho_i = density w_i; x Lea-Parker melt",
    choices={"melt": ("none", "lea_parker")},
    flow_order=1.0,  # first order in the basis (checked at load)
)
def _mass_action(ctx, basis, p):
    r"""Mass action on bed concentrations (Mastorakos et al. 1999 form), per kiln length.

    The reaction extent per bed volume (mol/(m3 s), per mole of basis: write the basis with
    coefficient -1) is :math:`A e^{-E/RT_b}\prod_i \rho_i^{n_i}` with :math:`\rho_i = \rho_b w_i`
    (kg/m3 of bed, :math:`w_i` the bed mass fractions, :math:`\rho_b` = ``density``); times
    the bed cross-section :math:`m'/\rho_b` and the basis molar mass it is the basis consumption
    in kg/(s m). ``orders`` must give the basis the order 1 and every other reactant an order
    >= 1, so the rate vanishes with any reactant (no negative flows with the kiln's implicit
    upwind cells) and stays a polynomial in the flows (smooth for Newton). ``melt:
    lea_parker`` multiplies by the Lea-Parker melt fraction of the cell's own oxides at the bed
    temperature (:func:`~rotarykiln.chemistry.clinker.lea_parker_melt_fraction`, zero below
    1338 degC - ``melt_width``).
    """
    rho_b = p["density"]
    _, inv = _bed_fractions(ctx)
    orders = dict(p["orders"]) or {basis: 1.0}
    r = p["A"] * np.exp(-p["E"] / (R_GAS * ctx.T_bed))
    for name, n in orders.items():
        r = r * (rho_b * ctx.flow(name) * inv) ** n
    area = ctx.state.bed_mass_per_length / rho_b  # bed cross-section, m2
    r = r * area * ctx.species[basis].molar_mass
    if p["melt"] == "lea_parker":
        r = r * _melt_fraction(ctx, p["melt_width"])
    return r


@register_rate_law(
    "carbonate_equilibrium",
    {"A": 9.8e4, "E": 142000.0, "carbonate": "calcite", "co2_pressure": "freeboard"},
    "r = A exp(-E/RT) m'_basis max(0, 1 - p_CO2/p_eq), p_eq of Holland & Powell (2011)",
    choices={
        "carbonate": ("calcite", "magnesite", "dolomite_half", "dolomite_full"),
        "co2_pressure": CO2_PRESSURE_CHOICES,
    },
)
def _carbonate_equilibrium(ctx, basis, p):
    r"""First-order decomposition of a carbonate driven by its CO2 equilibrium.

    :math:`r = A e^{-E/RT_b}\,m'_{basis}\,\max(0, 1 - p_{CO_2}/p_{eq}(T_b))`, kg/(s m), with
    :math:`p_{eq}` of :func:`~rotarykiln.chemistry.lime.holland_powell_co2_equilibrium_pressure`
    (evaluated with T held in the data's 273-2000 K range). First order in the basis hold-up, so
    it also runs on a carbonate made in the kiln (the CaCO3 of half-calcined dolomite), which a
    conversion-based law (fed reactants only) cannot.
    """
    from rotarykiln.chemistry.lime import holland_powell_co2_equilibrium_pressure  # scipy

    T = np.clip(ctx.T_bed, 300.0, 2000.0)
    peq = np.asarray(holland_powell_co2_equilibrium_pressure(T, p["carbonate"]), dtype=float)
    drive = np.maximum(1.0 - _co2_pressure(ctx, p) / np.maximum(peq, 1e-300), 0.0)
    k = p["A"] * np.exp(-p["E"] / (R_GAS * ctx.T_bed))
    return k * ctx.holdup(basis) * drive
