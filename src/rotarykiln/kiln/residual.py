r"""Residual of the kiln: energy and species balances of every cell, one Newton system.

Unknowns of cell ``j`` (last axis): 0 ``T_bed`` at face j+1 (solids outlet of the cell), 1
``T_gas`` at the cell's gas outlet (face j counter-current, face j+1 co-current), 2 the inner wall (with a lining: then each
lining interface and the shell, :mod:`rotarykiln.kiln.wall.lining`), then the mass flows of the
reacting bed species at face j+1 and of the reacting gas species at the gas outlet face, each divided by the
phase's total inlet flow (for bed reactants that are fed and never produced, the square root
of that ratio). Species that no reaction touches keep their inlet flow.

The cell-mean temperatures the closures see are the averages of the faces, the gas's weighted
towards its outlet face by the cell's transfer units (:meth:`KilnResidual.gas_mean`), so that a
cell of many transfer units (a large drum swept by little gas) cannot overshoot.

Balances of cell j (:math:`\Delta z`), with rates :math:`\dot w_i` (kg/(s m)) and heat
absorbed :math:`\dot q_r = \sum_r r_r \Delta H_r(T_b)` (W/m) from
:meth:`rotarykiln.chemistry.Mechanism.rates` at the cell-mean temperatures and the cell's outlet
flows (implicit upwind: flows never turn negative):

.. math::
    Q_{i,j+1} - Q_{i,j} = \Delta z\,\dot w_i,\qquad G_{k,j} - G_{k,j+1} = \Delta z\,\dot w_k

    \sum_i Q_i h_i(T_b)\Big|_j^{j+1} = \Delta z\Big(Q_{gb} + Q_{rb} + Q_{cw}
        - \dot q_r + \sum_{i\in bed} \dot w_i h_i(\bar T_b)\Big)

    \sum_k G_k h_k(T_g)\Big|_{j+1}^{j} = -\Delta z\Big(Q_{gw} + Q_{gb} + Q_{rw} + Q_{rb}
        - \sum_{k\in gas} \dot w_k h_k(\bar T_b)\Big)

    0 = Q_{gw} + Q_{rw} - Q_{cw} - U\pi D (T_w - T_a)

(with a lining, the wall rows of :class:`~rotarykiln.kiln.wall.lining.LinedWall` instead).
Freeboard (``phase: gas``) reactions (:mod:`rotarykiln.chemistry.gas_phase`) change the gas
species at the gas temperature and release :math:`-\Delta H_{298}\,r` into the gas balance
instead (the gas tables hold the sensible part), not into the bed. The
exchange terms come from :class:`rotarykiln.kiln.exchange.CrossSectionExchange`.
:math:`h_i` are sensible enthalpies (0 at 298.15 K): the gases the bed releases leave it at the
bed temperature and are heated to the gas temperature inside the gas balance. Every term
appears with the same value in the two balances it links, so the scheme is conservative:
species (and so elements) and energy telescope to the global balances.
"""

from __future__ import annotations

import copy
import dataclasses
import threading

import numpy as np

from rotarykiln.chemistry.mechanism import CellState as ChemState
from rotarykiln.kiln.bed.dispersion import dispersion_sources
from rotarykiln.kiln.exchange import (
    FLOW_KEYS,
    BulkBed,
    CrossSectionExchange,
    cell_report,
    gas_conductance,
    upwind_weight,
)
from rotarykiln.kiln.gas_mixture import MixtureGas, mixture_of, temperature_of_enthalpy
from rotarykiln.kiln.grid import cell_grid, release_per_cell
from rotarykiln.kiln.inputs import Kiln
from rotarykiln.kiln.inputs.boundary import FULL, BoundaryInputs, Scales
from rotarykiln.kiln.wall.lining import ConstantUWall, LinedWall
from rotarykiln.materials.gas import T_REF

__all__ = ["KilnResidual", "T_FLOOR", "RATE_FLOOR"]

T_FLOOR = 150.0  # K, temperatures are clipped here inside property evaluations
RATE_CAP_WIDTH = 5.0  # K, width of the smooth minimum of the rate-temperature continuation
#: Flow (over the feed) below which a reactant's rate law of order < 1 is regularised when
#: every species is an unknown (the transient).
RATE_FLOOR = 1e-6


def _capped(T, cap: float):
    """Smooth minimum of ``T`` and ``cap`` (K): ``T`` well below the cap, ``cap`` well above."""
    w = RATE_CAP_WIDTH
    return -w * np.logaddexp(-T / w, -cap / w)


_WORK = threading.local()


def cell_evaluations() -> int:
    """The cells (cells x stacked states) every :meth:`KilnResidual.evaluate` of this thread
    has evaluated so far: a count of work, the same on every run of the same solves (another
    thread's solves, as a threaded scheduler's, not counted).

    Examples
    --------
    >>> isinstance(cell_evaluations(), int)
    True
    """
    return getattr(_WORK, "cells", 0)


class KilnResidual:
    """Callable residual ``F(x)`` of a :class:`Kiln` on ``n`` equal cells.

    ``q_ref`` (W): the scale of the species rows (they are flows over the phase's inlet flow
    times ``q_ref``, so that they weigh like the energy rows); None: the reference heat of
    the kiln (:meth:`reference_heat`). ``every_species``: every bed and gas species is an
    unknown with its flow linear (the transient's unknowns), instead of the reacting ones
    only, the fed reactants as square roots (the steady Newton's). The inputs at the ends
    (:class:`~rotarykiln.kiln.inputs.boundary.BoundaryInputs`) and the continuation
    parameters (:class:`~rotarykiln.kiln.inputs.boundary.Scales`) are arguments of
    :meth:`evaluate`; nothing of the residual is set from outside.

    :func:`cell_evaluations` counts the cells the residuals evaluate in a thread (a work count
    the batched solver compares between its paths, never an input).
    """

    def __init__(
        self, kiln: Kiln, n_cells: int, *, q_ref: float | None = None, every_species=False
    ):
        self.kiln = k = kiln
        mech = k.chemistry.mechanism
        sp = mech.species
        S = mech.mass_stoichiometry  # (n_reactions, n_species)
        touched = np.any(S != 0.0, axis=0)
        self.species = sp
        # a burner's solid fuels drop their ash into the bed (kg/s, at 298.15 K)
        ash = float(getattr(k.firing.flame, "ash_flow", 0.0) or 0.0)
        self.bed_sources = {"ash": ash} if ash > 0 else {}
        self.bed_names = tuple(
            s
            for i, s in enumerate(sp.names)
            if sp[s].phase == "bed"
            and (touched[i] or k.feed.flows.get(s, 0) > 0 or s in self.bed_sources)
        )
        self.gas_names = tuple(
            s
            for i, s in enumerate(sp.names)
            if sp[s].phase == "gas" and (touched[i] or k.gas.flows.get(s, 0) > 0)
        )
        self.bed_var = tuple(s for s in self.bed_names if touched[sp.index(s)])
        self.gas_var = tuple(s for s in self.gas_names if touched[sp.index(s)])
        self.bed_pos = np.array([self.bed_names.index(s) for s in self.bed_var], dtype=int)
        self.gas_pos = np.array([self.gas_names.index(s) for s in self.gas_var], dtype=int)
        self.bed_idx = np.array([sp.index(s) for s in self.bed_names], dtype=int)
        self.gas_idx = np.array([sp.index(s) for s in self.gas_names], dtype=int)
        self.nb, self.ng = len(self.bed_var), len(self.gas_var)
        # reactants fed with the solids and never produced are solved for as sqrt(Q/S): the
        # order-1/2 calcination rate (~ sqrt Q) then becomes smooth and complete conversion
        # is reached without a singular Jacobian or negative flows
        made = np.any(S > 0.0, axis=0)
        self.sqrt_mask = np.array(
            [bool(k.feed.flows.get(s, 0) > 0 and not made[sp.index(s)]) for s in self.bed_var],
            dtype=bool,
        )
        self.bed_in = np.array([k.feed.flows.get(s, 0.0) for s in self.bed_names])
        self.gas_inlet = np.array([k.gas.flows.get(s, 0.0) for s in self.gas_names])
        self.bed_scale = float(self.bed_in.sum())
        self.gas_scale = float(self.gas_inlet.sum())
        self.cp_bed = np.array([k.bed.cp.get(s, sp[s].cp) for s in self.bed_names])
        self.disperses = np.isin(np.arange(len(self.bed_names)), self.bed_pos)
        # bed species with a temperature-dependent enthalpy (a library solid, phases included)
        self.solid_pos = [
            (i, k.bed.solids[s]) for i, s in enumerate(self.bed_names) if s in k.bed.solids
        ]
        # user species with a c_p(T) (chemistry/thermo.py) carry their own enthalpy
        self.solid_pos += [
            (i, sp[s].thermo)
            for i, s in enumerate(self.bed_names)
            if sp[s].thermo is not None and s not in k.bed.solids and s not in k.bed.cp
        ]
        flame = k.firing.flame
        self.mixture = mixture_of(
            self.gas_names, sp, flame.dissociation if flame is not None else None
        )
        self.flow_in = {s: float(k.feed.flows.get(s, 0.0)) for s in sp.bed_names}
        self.i_h2o = self.gas_names.index("H2O") if "H2O" in self.gas_names else None
        # grid, wall and exchange
        self.grid = g = cell_grid(
            k.drum.length,
            k.drum.radius,
            n_cells,
            k.fill_at,
            k.wall.layers,
            heat_release=k.firing.heat_release,
            heat_release_profile=k.firing.profile,
        )
        self.n, self.z_nodes, self.z, self.dz = g.n, g.z_nodes, g.z, g.dz
        self.bed_source, self.bed_source_faces = self._bed_sources()
        if k.wall.jacket is not None:
            self.wall = k.wall.jacket.wall(k, g)
        elif k.wall.layers:
            self.wall = LinedWall.of(k, g)
        else:
            self.wall = ConstantUWall(
                k.wall.loss_u, 2.0 * np.pi * k.drum.radius, k.wall.ambient_temperature
            )
        self.n_wall = self.wall.n_temperatures
        self.i_species = 2 + self.n_wall  # first species unknown
        self.nv = self.i_species + self.nb + self.ng
        # bed depth solved with the balances (kiln/bed/depth.py): one more unknown per cell
        self.depth = k.bed.depth
        if self.depth is not None:
            self.i_depth = self.nv
            self.nv += 1
        bed = k.bed.material or BulkBed(
            k.bed.bulk_density,
            float(np.mean(self.cp_bed)),
            k.bed.particle_diameter,
            k.bed.emissivity,
            k.bed.conductivity,
        )
        self.exchange = CrossSectionExchange.of(k, g, bed, k.gas.emissivity_law)
        # faces where each cell's gas leaves: j (counter-current) or j+1 (co-current)
        self.gas_out = slice(None, -1) if k.gas.counter_current else slice(1, None)
        # a burner's stirred recirculation zone: which neighbouring gas nodes mix, and K/dz
        self.stirred = None
        zone = k.firing.stirred_zone
        if zone is not None:
            z0, z1, k_mix = zone
            nodes = self.z_nodes[self.gas_out]
            inside = (nodes >= z0 - 1e-9 * k.drum.length) & (nodes <= z1 + 1e-9 * k.drum.length)
            self.stirred = ((inside[:-1] & inside[1:]).astype(float), k_mix / self.dz)
            self.stirred_cells = inside
        self.gas_in_face = -1 if k.gas.counter_current else 0
        # reactants fed and never made (the steady model's square-root unknowns): with every
        # species linear, their rate laws of order < 1 are made Lipschitz (:meth:`rates`)
        self.regularised = np.zeros(len(self.bed_names), dtype=bool)
        if every_species:
            self.regularised = np.array([s in self.bed_var for s in self.bed_names]) & np.isin(
                self.bed_names,
                [v for v, m in zip(self.bed_var, self.sqrt_mask, strict=True) if m],
            )
            self.bed_var, self.gas_var = self.bed_names, self.gas_names
            self.nb, self.ng = len(self.bed_names), len(self.gas_names)
            self.bed_pos = np.arange(self.nb)
            self.gas_pos = np.arange(self.ng)
            self.sqrt_mask = np.zeros(self.nb, dtype=bool)
            self.disperses = np.ones(self.nb, dtype=bool)
            self.nv = self.i_species + self.nb + self.ng
            if self.depth is not None:
                self.i_depth = self.nv
                self.nv += 1
        #: which unknowns act on their own cell's rows only (the wall's radial temperatures):
        #: one colour of the finite-difference Jacobian each, instead of three
        self.local = np.zeros(self.nv, dtype=bool)
        self.local[2 : self.i_species] = self.wall.local
        #: whether the kiln has reactions (without, the residual has no sources to evaluate)
        self.reacting = bool(mech.reactions)
        #: the inputs at the ends of the kiln's own inputs (the steady solve's)
        self.inputs = BoundaryInputs.of(k, self.bed_names, self.gas_names)
        self.q_ref = float(self.reference_heat() if q_ref is None else q_ref)

    def with_kiln(self, kiln: Kiln) -> KilnResidual:
        """The residual of ``kiln`` on this residual's cells, for a kiln that differs from this
        one's only in its boundary inputs (the fields a batch may vary:
        :data:`~rotarykiln.kiln.steady.batch.BOUNDARY_FIELDS`; the caller checks that, as
        :func:`~rotarykiln.kiln.steady.batch.same_structure` does): this residual's species,
        wall and closures with the kiln's inlet flows, release profile, rotation, inputs and
        reference heat, as ``KilnResidual(kiln, n)`` sets them, at a fraction of the cost (a
        study's thousand operating points of one kiln)."""
        new = copy.copy(self)
        new.kiln = k = kiln
        new.bed_in = np.array([k.feed.flows.get(s, 0.0) for s in self.bed_names])
        new.gas_inlet = np.array([k.gas.flows.get(s, 0.0) for s in self.gas_names])
        new.bed_scale = float(new.bed_in.sum())
        new.gas_scale = float(new.gas_inlet.sum())
        new.flow_in = {s: float(k.feed.flows.get(s, 0.0)) for s in self.species.bed_names}
        flame = k.firing.flame
        dissociation = flame.dissociation if flame is not None else None
        if dissociation is not self.mixture.dissociation:  # another burnt gas
            new.mixture = self.mixture.with_dissociation(dissociation)
        release = release_per_cell(k.firing.heat_release, k.firing.profile, self.z, self.dz)
        new.grid = dataclasses.replace(self.grid, heat_release=release)
        new.bed_source, new.bed_source_faces = new._bed_sources()
        new.exchange = dataclasses.replace(self.exchange, geometry=new.grid, omega=k.drum.omega)
        new.inputs = BoundaryInputs.of(k, self.bed_names, self.gas_names)
        new.q_ref = float(new.reference_heat())
        return new

    def with_mixture(self, mixture) -> KilnResidual:
        """This residual with its gas's property model ``mixture`` (a batch of kilns whose
        burnt gases differ: each case's own, :meth:`~rotarykiln.kiln.gas_mixture.CaseMixtures.
        take`)."""
        new = copy.copy(self)
        new.mixture = mixture
        return new

    def hottest_source(self) -> float:
        """The hottest heat source, K: the inlet gas with all the heat released in it, a
        heating jacket's inlet gas, or a heater zone's shell set-point (for the initial guess
        and the scale of the energy rows; a kiln heated through its shell starts warm, not at
        its cold sweep gas)."""
        k = self.kiln
        hot = k.gas.temperature
        if k.firing.heat_release > 0:
            target = float(self.mixture.species_enthalpy(k.gas.temperature) @ self.gas_inlet)
            hot = temperature_of_enthalpy(
                self.mixture, self.gas_inlet, target + k.firing.heat_release, 200.0, 3200.0, 601
            )
        jacket = k.wall.jacket
        if jacket is not None:
            hot = max(hot, float(jacket.inlet_temperature))
        set_points = [
            z.shell_temperature for z in k.wall.heaters if z.shell_temperature is not None
        ]
        return max([hot, *set_points])

    def reference_heat(self) -> float:
        """Reference heat flow (W) of the kiln: the larger of the heat the inlet gas gives up
        cooling from the hottest source to the feed temperature and the heat the feed takes
        up over the same span (at least 1 W); the scale of the residual's rows."""
        th, tf = self.hottest_source(), self.kiln.feed.temperature
        hg = self.mixture.species_enthalpy(np.array([th, tf]))
        span_g = float(self.gas_inlet @ (hg[0] - hg[1]))
        hb = self.bed_enthalpy(np.array([th, tf]))
        span_s = float(self.bed_in @ (hb[0] - hb[1]))
        return max(abs(span_g), abs(span_s), 1.0)

    # --- unpacking ---------------------------------------------------------------------------
    def _bed_sources(self):
        """What falls into the bed per cell, kg/(s m) (n, n_bed): a burner's ash where its
        fuel releases its heat (the burner's cell when it burns at the inlet); and its sum
        from the feed end to each face, kg/s (n + 1, n_bed), for the species whose flows are
        not unknowns (the others take it in their species rows)."""
        n, nb = self.n, len(self.bed_names)
        per_cell = np.zeros((n, nb))
        faces = np.zeros((n + 1, nb))
        if not self.bed_sources:
            return per_cell, faces
        k = self.kiln
        if k.firing.heat_release > 0:
            w = np.asarray(self.grid.heat_release, dtype=float) * self.dz
            w = w / w.sum()
        else:  # burnt at the burner: the ash falls into the burner's cell
            w = np.zeros(n)
            w[-1 if k.gas.counter_current else 0] = 1.0
        for name, flow in self.bed_sources.items():
            i = self.bed_names.index(name)
            per_cell[:, i] = flow * w / self.dz
            if name not in self.bed_var:
                faces[1:, i] = np.cumsum(flow * w)
        return per_cell, faces

    def faces(self, x, inputs: BoundaryInputs | None = None):
        """Face temperatures and species flows from the unknowns ``x`` (..., n, nv), with the
        inlet values of ``inputs`` (default the kiln's own)."""
        k, u = self.kiln, inputs or self.inputs
        batch = x.shape[:-2]
        n = self.n
        # filled in place (the same values as concatenating the inlets and the unknowns)
        tb = np.empty(batch + (n + 1,))
        tb[..., :1] = u.feed_temperature
        tb[..., 1:] = x[..., 0]
        tg = np.empty(batch + (n + 1,))
        tg[..., self.gas_out] = x[..., 1]
        tg[..., slice(n, None) if k.gas.counter_current else slice(None, 1)] = u.gas_temperature
        qb = np.empty(batch + (n + 1, len(self.bed_names)))
        qb[...] = u.feed
        if self.bed_sources:
            qb += self.bed_source_faces
        i0 = self.i_species
        xb = x[..., i0 : i0 + self.nb]
        qb[..., 1:, self.bed_pos] = np.where(self.sqrt_mask, xb * xb, xb) * self.bed_scale
        qg = np.empty(batch + (n + 1, len(self.gas_names)))
        qg[...] = u.gas
        xg = x[..., i0 + self.nb : i0 + self.nb + self.ng]
        qg[..., self.gas_out, self.gas_pos] = xg * self.gas_scale
        return tb, tg, qb, qg

    def bed_enthalpy(self, T):
        """Sensible enthalpy of each bed species at ``T`` (J/kg, 0 at 298.15 K), ``T.shape +
        (n_bed,)``: constant c_p, or a library solid's h(T)."""
        h = self.cp_bed * (np.asarray(T)[..., None] - T_REF)
        for i, solid in self.solid_pos:
            h[..., i] = solid.enthalpy(T)
        return h

    def depth_faces(self, x):
        """Bed depth at the faces (m): the unknowns, then the dam height at the discharge."""
        dam = np.broadcast_to(self.depth.dam_height, x.shape[:-2] + (1,))
        return np.concatenate([x[..., self.i_depth], dam], -1)

    def geometry(self, x):
        """Cell geometry: the fixed grid, or the cross-sections at the solved bed depth."""
        if self.depth is None:
            return self.grid
        h = self.depth_faces(x)
        return self.depth.geometry(self.grid, 0.5 * (h[..., 1:] + h[..., :-1]))

    def volume_flow(self, qb):
        """Volumetric bed flow (m3/s) of the species flows ``qb`` (kg/s, bed species on the
        last axis): the solved bed depth's volume law
        (:meth:`~rotarykiln.kiln.bed.depth.KramersBed.volume_flow`: the flow over the bulk
        density, or the fresh feed's volume), else the flow over the bulk density."""
        if self.depth is None:
            return qb.sum(-1) / self.kiln.bed.bulk_density
        return self.depth.volume_flow(self.bed_names, qb)

    def bed_density(self, qb):
        """Bulk density of the bed (kg/m3) at the species flows ``qb``: the kiln's, or that of
        the solved bed depth's volume law
        (:meth:`~rotarykiln.kiln.bed.depth.KramersBed.bed_density`)."""
        if self.depth is None:
            return self.kiln.bed.bulk_density
        return self.depth.bed_density(self.bed_names, qb)

    # --- closures -------------------------------------------------------------------------------
    def gas_state(self, g_mean, geo=None) -> MixtureGas:
        """The freeboard gas of the cells from their mean species flows (kg/s)."""
        k = self.kiln
        area = (geo or self.grid).freeboard_area
        return MixtureGas.of(self.mixture, g_mean, k.gas.pressure, area)

    def exchange_of(self, geo, omega: float | None = None):
        """The cross-section exchange on the geometry ``geo`` at the rotation ``omega``
        (rad/s; default the kiln's)."""
        changes = {}
        if geo is not self.grid:
            changes["geometry"] = geo
        if omega is not None and (np.ndim(omega) > 0 or omega != self.exchange.omega):
            changes["omega"] = omega
        return dataclasses.replace(self.exchange, **changes) if changes else self.exchange

    def coefficients(self, tg, tb, tw, g_mean, check=False, geo=None, omega=None):
        """Heat transfer coefficients (W/(m2 K)) and gas emissivity at cell means (at the
        rotation ``omega``, rad/s, default the kiln's: a batch's own per case)."""
        geo = geo or self.grid
        gas = self.gas_state(g_mean, geo)
        return self.exchange_of(geo, omega).coefficients(gas, tg, tb, tw, check=check)

    # --- chemistry ------------------------------------------------------------------------------
    def rates(
        self,
        tb,
        tg,
        qb_out,
        qg_out,
        q_bed_in,
        h_gb,
        geo=None,
        tb_out=None,
        *,
        scales: Scales = FULL,
        inputs: BoundaryInputs | None = None,
    ):
        r"""Production (..., n, n_species) kg/(s m) and heat absorbed (..., n) W/m.

        ``tb_out``: bed temperature at each cell's solids outlet face (K), for rate laws that
        hold the bed at a phase change (boiling drying); the cell mean when not given.
        With every species an unknown, the flow of each reactant fed and never made is seen
        by its rate law as :math:`q^2/(q + \epsilon)` (:math:`\epsilon` =
        :data:`RATE_FLOOR` x the feed): a rate of order 1/2 then stays Lipschitz as the
        reactant runs out (a square root has an infinite slope at complete conversion, which
        an implicit integrator's Newton iteration cannot follow). Above 100 epsilon the rate
        changes by < 1 %, and the stoichiometry (so every balance) is untouched.
        """
        k = self.kiln
        geo = geo or self.grid
        if self.regularised.any():
            q = np.maximum(qb_out, 0.0)
            eps = RATE_FLOOR * self.bed_scale
            qb_out = np.where(self.regularised, q * q / (q + eps), q)
        shape = tb.shape
        flat = int(np.prod(shape))
        if inputs is None or inputs is self.inputs:
            flow_in = self.flow_in
        elif np.ndim(inputs.feed) > 1:  # a batch of kilns: each cell its kiln's feed
            feed = inputs.feed
            flow_in = {
                s: np.broadcast_to(feed[..., i], shape).reshape(flat)
                for i, s in enumerate(self.bed_names)
            }
        else:
            flow_in = {s: float(q) for s, q in zip(self.bed_names, inputs.feed, strict=True)}
        qb = np.maximum(qb_out, 0.0).reshape(flat, -1)
        bed = {s: qb[:, i] for i, s in enumerate(self.bed_names)}
        if self.depth is None:
            velocity = k.bed.velocity
            if inputs is not None and inputs.bed_velocity is not None:
                velocity = np.broadcast_to(inputs.bed_velocity, shape).reshape(flat)
            holdup = qb.sum(-1) / velocity
        else:
            rho = self.bed_density(qb_out)
            holdup = (rho * np.broadcast_to(geo.bed_area, shape)).reshape(flat)
        xg = self.mixture.mole_fractions(qg_out).reshape(flat, -1)
        pp = {s: k.gas.pressure * xg[:, i] for i, s in enumerate(self.gas_names)}
        if k.chemistry.steam_flow is not None:
            steam = np.full(flat, k.chemistry.steam_flow)
        elif self.i_h2o is not None:
            steam = np.maximum(qg_out[..., self.i_h2o], 0.0).reshape(flat)
        else:
            steam = np.zeros(flat)
        cell_inputs = {
            "steam_mass_flow": steam,
            "drying_conductance": np.broadcast_to(h_gb * geo.chord, shape).reshape(flat),
            "bed_heat_input": q_bed_in.reshape(flat),
            "freeboard_area": np.broadcast_to(geo.freeboard_area, shape).reshape(flat),
            "bed_outlet_temperature": np.broadcast_to(
                tb if tb_out is None else tb_out, shape
            ).reshape(flat),
        }
        t_bed, t_gas = np.maximum(tb, T_FLOOR), np.maximum(tg, T_FLOOR)
        if np.isfinite(scales.rate_temperature_cap):
            t_bed, t_gas = (_capped(t, scales.rate_temperature_cap) for t in (t_bed, t_gas))
        st = ChemState(
            t_bed.reshape(flat),
            t_gas.reshape(flat),
            bed,
            holdup,
            pp,
            flow_in,
            cell_inputs,
        )
        out = self.kiln.chemistry.mechanism.rates(st)
        lam = scales.reaction
        prod = lam * out.production.reshape(shape + (-1,))
        heat = lam * out.heat_absorbed.reshape(shape)
        rate = lam * out.reaction_rate.reshape(shape + (-1,))
        heat_gas = lam * np.broadcast_to(out.heat_absorbed_gas, (flat,)).reshape(shape)
        prod_gp = lam * np.broadcast_to(out.production_gas_phase, (flat, prod.shape[-1]))
        return prod, heat, rate, heat_gas, prod_gp.reshape(prod.shape)

    # --- residual -------------------------------------------------------------------------------
    def evaluate(
        self,
        x,
        full: bool = False,
        *,
        scales: Scales = FULL,
        inputs: BoundaryInputs | None = None,
        heat_capacity_step: float | None = None,
    ):
        """Residual (..., n, nv): W per cell for the energy rows, scaled flows for species.

        ``scales``: the continuation parameters; ``inputs``: the inputs at the ends (default
        the kiln's own, :attr:`inputs`). With ``full``, also the per-cell fluxes, the
        production by the bed reactions, the reaction rates and the face values.

        ``heat_capacity_step`` (K, with ``full``; the transient's hold-ups): also the species
        enthalpies at the faces and their dh/dT at each cell's outlet face (the bed's face
        j+1, the gas's outlet face) by central differences of this step, evaluated in the
        same calls of the enthalpies as the residual's own (the same numbers as separate
        calls): a sixth item ``(h_bed_faces, cp_bed_outlets, h_gas_faces, cp_gas_outlets)``
        (J/kg and J/(kg K), species on the last axis). None (the steady solver's): the
        residual as without it, to the last bit.
        """
        dz = self.dz
        u = inputs or self.inputs
        _WORK.cells = getattr(_WORK, "cells", 0) + x.size // x.shape[-1]
        tb_n, tg_n, qb, qg = self.faces(x, u)
        tbn = np.maximum(tb_n, T_FLOOR)
        tgn = np.maximum(tg_n, T_FLOOR)
        tb = 0.5 * (tbn[..., :-1] + tbn[..., 1:])
        tl = np.maximum(x[..., 2 : 2 + self.n_wall], T_FLOOR)  # inner wall (.. shell)
        tw = tl[..., 0]
        if self.ng:
            g_mean = 0.5 * (np.maximum(qg[..., :-1, :], 0.0) + np.maximum(qg[..., 1:, :], 0.0))
        else:
            # no gas species solved for: every cell carries the inlet gas, whose composition
            # (mole fractions, partial pressures, the emissivity's grey gases) is then worked
            # out once and broadcast over the cells (the same numbers as cell by cell)
            g_mean = np.maximum(qg[..., :1, :], 0.0)
        geo = self.geometry(x)
        gas = self.gas_state(g_mean, geo)
        exchange = self.exchange_of(geo, u.omega)
        tg, co = self.gas_mean(tgn, tb, tw, g_mean, gas, exchange, geo, scales.radiation)
        if self.stirred is not None:
            # a stirred cell is a tank: its gas is at the temperature it leaves at, not the
            # mean of its faces (its inlet face may be the burner's products, unmixed)
            tg = np.where(self.stirred_cells, np.maximum(x[..., 1], T_FLOOR), tg)
        fl, co = exchange.flows(gas, tg, tb, tw, scales.radiation, co=co)
        q_gw, q_gb, q_cw, q_rw, q_rb = (fl[key] for key in FLOW_KEYS)
        wall_rows, q_loss = self.wall.balance(q_gw + q_rw - q_cw, tl)
        q_bed_in = q_gb + q_rb + q_cw
        m = tbn.shape[-1]
        cp_bed = cp_gas = ()
        if heat_capacity_step is not None:
            # the outlet faces' temperatures +- the step, after the residual's own points
            tb_out, tg_out = tbn[..., 1:], tgn[..., self.gas_out]
            step = heat_capacity_step
            cp_bed = (tb_out + step, tb_out - step)
            cp_gas = (tg_out + step, tg_out - step)
        if self.reacting:
            prod, heat, rate, heat_gas, prod_gp = self.rates(
                tb,
                tg,
                qb[..., 1:, :],
                qg[..., self.gas_out, :],
                q_bed_in,
                co["h_gb"],
                geo,
                tbn[..., 1:],
                scales=scales,
                inputs=u,
            )
            w_bed = prod[..., self.bed_idx][..., self.bed_pos]
            w_gas = prod[..., self.gas_idx]
            # what the bed releases (bed reactions) enters the gas at the bed temperature; a
            # freeboard reaction releases -dH_298 r into the gas, whose sensible tables do the
            # rest
            w_released = w_gas - prod_gp[..., self.gas_idx]
            w_gas = w_gas[..., self.gas_pos]
            # the enthalpies at the faces and at the cells' bed temperature, each in one call
            hb_both = self.bed_enthalpy(np.concatenate([tbn, tb, *cp_bed], -1))
            hb_nodes, hb_cell = hb_both[..., :m, :], hb_both[..., m : 2 * m - 1, :]
            hg_both = self.mixture.species_enthalpy(np.concatenate([tgn, tb, *cp_gas], -1))
            hg_nodes, hg_at_bed = hg_both[..., :m, :], hg_both[..., m : 2 * m - 1, :]
            s_bed = -heat + (prod[..., self.bed_idx] * hb_cell).sum(-1)
            s_gas = (w_released * hg_at_bed).sum(-1) - heat_gas
        else:
            # no reactions: no sources, and no enthalpies at the cells' bed temperature (the
            # same rows as with every rate zero, for a fraction of the work)
            w_bed = w_gas = 0.0
            if heat_capacity_step is None:
                hb_nodes = self.bed_enthalpy(tbn)
                if self.ng:
                    hg_nodes = self.mixture.species_enthalpy(tgn)
                else:  # a gas of one composition: its enthalpy flow from its own tables
                    hg_nodes, Hg = None, gas.enthalpy_flow(tgn)
            else:
                hb_both = self.bed_enthalpy(np.concatenate([tbn, *cp_bed], -1))
                hg_both = self.mixture.species_enthalpy(np.concatenate([tgn, *cp_gas], -1))
                hb_nodes, hg_nodes = hb_both[..., :m, :], hg_both[..., :m, :]
            s_bed = s_gas = 0.0
        release = self.release(scales, u)
        if self.kiln.firing.heat_release > 0:
            s_gas = s_gas + release
        Hb = (qb * hb_nodes).sum(-1)
        if hg_nodes is not None:
            Hg = (qg * hg_nodes).sum(-1)
        r_bed = Hb[..., 1:] - Hb[..., :-1] - dz * (q_bed_in + s_bed)
        disp_species = None
        if self.kiln.bed.dispersion > 0:
            rho = self.bed_density(0.5 * (qb[..., 1:, :] + qb[..., :-1, :]))
            holdup = rho * np.broadcast_to(geo.bed_area, tb.shape)
            disp = self.kiln.bed.dispersion if u.dispersion is None else u.dispersion
            disp_energy, disp_species = dispersion_sources(
                disp, holdup, qb, hb_nodes, dz, self.disperses
            )
            r_bed = r_bed - disp_energy
        sign = 1.0 if self.kiln.gas.counter_current else -1.0  # downstream minus upstream
        r_gas = sign * (Hg[..., :-1] - Hg[..., 1:]) + dz * (q_gw + q_gb + q_rw + q_rb - s_gas)
        if self.stirred is not None:
            r_gas = r_gas - self._stirred_gain(x[..., 1])
        parts = [r_bed[..., None], r_gas[..., None]] + [(dz * r)[..., None] for r in wall_rows]
        q_ref = self.q_ref
        if self.nb:
            qv = qb[..., self.bed_pos]
            net = qv[..., 1:, :] - qv[..., :-1, :] - dz * w_bed
            if self.bed_sources:
                net = net - dz * self.bed_source[:, self.bed_pos]
            if disp_species is not None:
                net = net - disp_species[..., self.bed_pos]
            rb = net / self.bed_scale
            parts.append(rb * q_ref)
        if self.ng:
            gv = qg[..., self.gas_pos]
            dg = sign * (gv[..., :-1, :] - gv[..., 1:, :])
            rg = (dg - dz * w_gas) / self.gas_scale
            parts.append(rg * q_ref)
        if self.depth is not None:
            q_vol = self.volume_flow(qb)
            rd = self.depth.residual(self.depth_faces(x), q_vol, dz)
            parts.append((rd * q_ref / self.depth.radius)[..., None])
        R = np.concatenate(parts, axis=-1)
        if not full:
            return R
        if not self.reacting:
            n_species, n_reactions = len(self.species.species), 0
            prod = prod_gp = np.zeros(tb.shape + (n_species,))
            rate = np.zeros(tb.shape + (n_reactions,))
            heat = heat_gas = np.zeros(tb.shape)
        chemistry = {
            "q_source_gas": np.broadcast_to(release, tg.shape) * 1.0,
            "q_reaction_absorbed": heat + heat_gas,
            "q_bed_chemistry": s_bed + np.zeros(tb.shape),
            "q_gas_chemistry": s_gas + np.zeros(tb.shape),
        }
        if self.kiln.wall.heaters or self.kiln.wall.jacket is not None:
            chemistry["q_electric_heating"] = self.wall.heating(tl)
        if self.depth is not None:
            chemistry["fill"] = geo.fill
            chemistry["bed_depth"] = geo.depth
        fluxes = cell_report(tb, tg, fl, q_loss, co, **chemistry)
        # production by the bed reactions (the solver's global balance prices it at T_bed)
        out = (R, fluxes, prod - prod_gp, rate, (tb_n, tg_n, qb, qg))
        if heat_capacity_step is None:
            return out
        # dh/dT at the outlet faces from the last 2 (n) points of each enthalpy call
        n2 = 2 * self.n
        c_b = (hb_both[..., -n2 : -self.n, :] - hb_both[..., -self.n :, :]) / (2 * step)
        c_g = (hg_both[..., -n2 : -self.n, :] - hg_both[..., -self.n :, :]) / (2 * step)
        return out + ((hb_nodes, c_b, hg_nodes, c_g),)

    def release(self, scales: Scales = FULL, inputs: BoundaryInputs | None = None):
        """Heat released in the gas per metre of each cell (W/m): the kiln's release profile
        at the heat release of ``inputs``, times the continuation's ``scales.release``."""
        u = inputs or self.inputs
        if u.release_cells is not None:
            return scales.release * u.release_cells
        q0 = self.kiln.firing.heat_release
        factor = scales.release * (u.heat_release / q0 if q0 > 0 else 0.0)
        return factor * self.grid.heat_release

    def gas_mean(self, tgn, tb, tw, g_mean, gas, exchange, geo, radiation_scale=1.0):
        """Cell-mean gas temperatures (K) from the face ones, and the exchange coefficients.

        The faces weighted by :func:`~rotarykiln.kiln.exchange.upwind_weight` of the cell's
        transfer units (conductance to wall and bed over the gas's heat capacity flow): the
        face average in an ordinary cell (up to 1 transfer unit), towards the outlet face in a
        cell of many transfer units, where the average would let the outlet overshoot the wall
        and bed it exchanges with and oscillate cell to cell. The coefficients are taken at the
        face average.
        """
        t_in, t_out = (tgn[..., 1:], tgn[..., :-1])
        if not self.kiln.gas.counter_current:
            t_in, t_out = t_out, t_in
        t_avg = 0.5 * (t_in + t_out)
        co = exchange.coefficients(gas, t_avg, tb, tw)
        t_max = np.maximum(np.maximum(t_in, t_out), np.maximum(tw, tb))
        conductance = gas_conductance(co, geo, t_max, radiation_scale)
        capacity = g_mean.sum(-1) * gas.cp(t_avg)
        ntu = conductance * self.dz / np.maximum(capacity, 1e-300)
        theta = upwind_weight(ntu)
        return np.where(theta == 0.5, t_avg, t_in + theta * (t_out - t_in)), co

    def _stirred_gain(self, t_gas):
        r"""Heat (W) each cell's gas gains by the axial mixing of a stirred recirculation zone.

        The gas unknowns (the temperature where each cell's gas leaves) of neighbouring cells
        whose nodes both lie in the zone exchange :math:`K (T_{j+1} - T_j)/\Delta z`; the
        exchange is internal, so it conserves energy (no flux through the zone's ends).
        """
        pair, k_dz = self.stirred
        flux = k_dz * pair * (t_gas[..., 1:] - t_gas[..., :-1])  # into j from j + 1
        gain = np.zeros_like(t_gas)
        gain[..., :-1] += flux
        gain[..., 1:] -= flux
        return gain

    def __call__(self, x):
        return self.evaluate(x)
