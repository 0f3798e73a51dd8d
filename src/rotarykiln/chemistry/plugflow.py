"""Plug-flow (0-D Lagrangian) integration of the bed reactions along a given temperature history.

No kiln solver is needed: the bed temperature (and optionally the gas temperature, the CO2/H2O
partial pressures and the extra rate-law inputs) are given as functions of the axial position z
(or as tabulated arrays). The bed moves at a constant velocity v (seed 004 assumption 1), so the
residence time is t = z/v and the species mass flows obey

.. math:: \\frac{dQ_i}{dz} = \\dot w_i(T(z), Q, m' = \\textstyle\\sum_j Q_j / v), \\qquad
          Q_i(0) = Q_{i,in}

with :math:`\\dot w_i` the production rates of :meth:`Mechanism.rates` (kg/(s m)). Gas species
produced or consumed are accumulated as released flows (kg/s).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pandas as pd

from rotarykiln.chemistry.balance import check_stream_balance
from rotarykiln.chemistry.mechanism import CellState, Mechanism
from rotarykiln.errors import ConvergenceError, InputError, check_nonnegative, check_positive
from rotarykiln.tables import with_units

__all__ = ["PlugFlowResult", "integrate_plug_flow", "as_profile"]


def as_profile(field: str, value) -> Callable[[float], float]:
    """Turn a constant, a callable f(z) or a tabulated pair (z, values) into a callable of z.

    Tabulated profiles are interpolated linearly and held constant beyond their ends.
    """
    if callable(value):
        return value
    if isinstance(value, tuple | list) and len(value) == 2 and np.ndim(value[0]) == 1:
        z = np.asarray(value[0], dtype=float)
        v = np.asarray(value[1], dtype=float)
        if z.shape != v.shape or z.size < 2 or np.any(np.diff(z) <= 0):
            raise InputError(
                field, "tabulated profile", "(z, values) of equal length >= 2, z increasing"
            )
        if not np.all(np.isfinite(v)):
            raise InputError(field, "non-finite value", "finite values")
        return lambda x: np.interp(x, z, v)
    try:
        c = float(value)
    except (TypeError, ValueError):
        raise InputError(field, value, "a number, a callable of z or a (z, values) pair") from None
    if not np.isfinite(c):
        raise InputError(field, value, "finite")
    return lambda x: c


@dataclass(frozen=True)
class PlugFlowResult:
    """Bed composition along a plug-flow path.

    Attributes
    ----------
    z : ndarray
        Position, m.
    t : ndarray
        Residence time, s.
    T_bed : ndarray
        K.
    bed_species : tuple of str
    bed_mass_flow : ndarray
        (n, n_bed) kg/s.
    gas_species : tuple of str
    gas_released : ndarray
        (n, n_gas) cumulative mass given to the gas, kg/s (negative: taken from the gas).
    heat_absorbed : ndarray
        Cumulative heat absorbed by the reactions, W.
    bed_mass_flow_in : dict
    success : bool
    message : str
    """

    z: np.ndarray
    t: np.ndarray
    T_bed: np.ndarray
    bed_species: tuple[str, ...]
    bed_mass_flow: np.ndarray
    gas_species: tuple[str, ...]
    gas_released: np.ndarray
    heat_absorbed: np.ndarray
    bed_mass_flow_in: dict
    success: bool = True
    message: str = ""

    def flow(self, name: str) -> np.ndarray:
        """Mass flow of a bed species (kg/s) or released flow of a gas species along z."""
        if name in self.bed_species:
            return self.bed_mass_flow[:, self.bed_species.index(name)]
        if name in self.gas_species:
            return self.gas_released[:, self.gas_species.index(name)]
        raise InputError(
            "species", name, f"one of {', '.join(self.bed_species + self.gas_species)}"
        )

    def conversion(self, name: str) -> np.ndarray:
        """Conversion 1 - Q/Q_in of a bed species along z, [-]."""
        q_in = self.bed_mass_flow_in.get(name, 0.0)
        if q_in <= 0:
            raise InputError("conversion species", name, "a bed species with a positive inlet flow")
        return 1.0 - self.flow(name) / q_in

    def burn_off(self) -> np.ndarray:
        """Burn-off of seed 004 on a dry basis, 100 (Q_dry,in - Q_dry)/Q_dry,in, %.

        Moisture is excluded (notes 004, section 8.3).
        """
        idx = [i for i, s in enumerate(self.bed_species) if s != "H2O(l)"]
        qin = sum(v for k, v in self.bed_mass_flow_in.items() if k != "H2O(l)")
        return 100.0 * (qin - self.bed_mass_flow[:, idx].sum(axis=1)) / qin

    def element_balance(self, species=None) -> dict[str, float]:
        """Relative element residual between inlet and outlet (bed out + gas released)."""
        out = {s: float(self.bed_mass_flow[-1, i]) for i, s in enumerate(self.bed_species)}
        gas_in = {}
        for j, g in enumerate(self.gas_species):
            v = float(self.gas_released[-1, j])
            if v >= 0:
                out[g] = v
            else:
                gas_in[g] = -v
        return check_stream_balance({**self.bed_mass_flow_in, **gas_in}, out, species, rtol=np.inf)

    def to_frame(self) -> pd.DataFrame:
        cols = {"z_m": self.z, "t_s": self.t, "T_bed_K": self.T_bed}
        for i, s in enumerate(self.bed_species):
            cols[f"bed_{s}_kg_s"] = self.bed_mass_flow[:, i]
        for j, g in enumerate(self.gas_species):
            cols[f"released_{g}_kg_s"] = self.gas_released[:, j]
        cols["heat_absorbed_W"] = self.heat_absorbed
        import pandas as pd

        return with_units(pd.DataFrame(cols), "chemistry.plugflow")

    def plot(self, ax=None):
        """Bed species flows against residence time; returns the Figure."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots()
        for i, s in enumerate(self.bed_species):
            if np.any(self.bed_mass_flow[:, i] > 0):
                ax.plot(self.t, self.bed_mass_flow[:, i], label=s)
        ax.set_xlabel("residence time (s)")
        ax.set_ylabel("bed mass flow (kg/s)")
        ax.legend()
        return ax.figure


def integrate_plug_flow(
    mechanism: Mechanism,
    bed_mass_flow_in: Mapping[str, float],
    length: float,
    velocity: float,
    T_bed,
    T_gas=None,
    partial_pressure: Mapping | None = None,
    inputs: Mapping | None = None,
    n_points: int = 201,
    rtol: float = 1e-8,
    method: str = "LSODA",
) -> PlugFlowResult:
    r"""Integrate the bed reactions along a plug-flow path with a given temperature profile.

    .. math:: \frac{dQ_i}{dz} = \dot w_i\big(T_b(z), T_g(z), Q, p(z)\big),\quad t = z/v

    Parameters
    ----------
    mechanism : Mechanism
    bed_mass_flow_in : mapping
        Bed species -> inlet mass flow, kg/s.
    length : float
        Path length, m.
    velocity : float
        Bed axial velocity, m/s (residence time = length/velocity).
    T_bed : float, callable of z [m] or (z, T) arrays
        Bed temperature, K.
    T_gas : same types, optional
        Gas temperature, K (default: the bed temperature).
    partial_pressure : mapping, optional
        Gas species -> partial pressure (Pa) as float, callable of z or (z, p) arrays.
    inputs : mapping, optional
        Extra rate-law inputs (``steam_mass_flow`` kg/s, ``drying_conductance`` W/(m K),
        ``bed_heat_input`` W/m), same types.
    n_points : int
        Output points along z.
    rtol : float, -
        Relative tolerance of the ODE solver.
    method : str
        :func:`scipy.integrate.solve_ivp` method.

    Returns
    -------
    PlugFlowResult

    Examples
    --------
    >>> mech = Mechanism.builtin("calcination_luisser")
    >>> res = integrate_plug_flow(mech, {"CaCO3": 0.01}, 0.5, 0.01, 1100.0)   # 50 s at 1100 K
    >>> round(float(res.conversion("CaCO3")[-1]), 3)    # 1 - (1 - k t/2)^2, k = 0.0177 1/s
    0.69

    References
    ----------
    Levenspiel, O. (1999) Chemical Reaction Engineering, 3rd ed., ch. 13-14 (plug flow); rate laws
    as referenced by each :class:`~rotarykiln.chemistry.reaction.Reaction`.
    """
    sp = mechanism.species
    check_positive("plug_flow.length", length, "m")
    check_positive("plug_flow.velocity", velocity, "m/s")
    if not isinstance(bed_mass_flow_in, Mapping) or not bed_mass_flow_in:
        raise InputError(
            "plug_flow.bed_mass_flow_in", bed_mass_flow_in, "a mapping bed species -> kg/s"
        )
    bed = sp.bed_names
    gas = sp.gas_names
    q0 = np.zeros(len(bed))
    for name, v in bed_mass_flow_in.items():
        if name not in bed:
            raise InputError(
                f"plug_flow.bed_mass_flow_in.{name}", name, f"a bed species ({', '.join(bed)})"
            )
        check_nonnegative(f"plug_flow.bed_mass_flow_in.{name}", v, "kg/s")
        q0[bed.index(name)] = float(v)
    qtot = q0.sum()
    check_positive("plug_flow.bed_mass_flow_in (total)", qtot, "kg/s")
    fTb = as_profile("plug_flow.T_bed", T_bed)
    fTg = fTb if T_gas is None else as_profile("plug_flow.T_gas", T_gas)
    z_check = np.linspace(0.0, float(length), 11)
    check_positive("plug_flow.T_bed", [float(fTb(z)) for z in z_check], "K")
    check_positive("plug_flow.T_gas", [float(fTg(z)) for z in z_check], "K")
    fp = {
        k: as_profile(f"plug_flow.partial_pressure.{k}", v)
        for k, v in (partial_pressure or {}).items()
    }
    for k in fp:
        if k not in gas:
            raise InputError(f"plug_flow.partial_pressure.{k}", k, "a gas species")
    fin = {k: as_profile(f"plug_flow.inputs.{k}", v) for k, v in (inputs or {}).items()}
    ref = {k: float(v) for k, v in bed_mass_flow_in.items()}
    ib = [sp.index(s) for s in bed]
    ig = [sp.index(s) for s in gas]
    nb = len(bed)

    def state_at(z, q):
        q = np.maximum(q, 0.0)
        return CellState(
            T_bed=np.array([float(fTb(z))]),
            T_gas=np.array([float(fTg(z))]),
            bed_mass_flow={s: q[i : i + 1] for i, s in enumerate(bed)},
            bed_mass_per_length=np.array([q.sum() / velocity]),
            partial_pressure={k: np.array([float(f(z))]) for k, f in fp.items()},
            bed_mass_flow_in=ref,
            inputs={k: np.array([float(f(z))]) for k, f in fin.items()},
        )

    def rhs(z, y):
        out = mechanism.rates(state_at(z, y[:nb]))
        w = out.production[0]
        return np.concatenate([w[ib], w[ig], out.heat_absorbed])

    y0 = np.concatenate([q0, np.zeros(len(gas)), [0.0]])
    z_eval = np.linspace(0.0, float(length), int(n_points))
    from scipy.integrate import solve_ivp

    sol = solve_ivp(
        rhs,
        (0.0, float(length)),
        y0,
        method=method,
        t_eval=z_eval,
        rtol=rtol,
        atol=1e-12 * qtot,
        max_step=float(length) / 100.0,
    )
    if not sol.success:
        raise ConvergenceError(
            f"plug-flow integration failed: {sol.message}",
            where_z=float(sol.t[-1]) if sol.t.size else 0.0,
        )
    Tb = np.array([float(fTb(z)) for z in sol.t])
    return PlugFlowResult(
        z=sol.t,
        t=sol.t / velocity,
        T_bed=Tb,
        bed_species=bed,
        bed_mass_flow=np.maximum(sol.y[:nb].T, 0.0),
        gas_species=gas,
        gas_released=sol.y[nb : nb + len(gas)].T,
        heat_absorbed=sol.y[-1],
        bed_mass_flow_in=ref,
        success=True,
        message=str(sol.message),
    )
