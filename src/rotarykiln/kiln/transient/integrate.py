r"""The transient kiln: the steady residual with hold-ups, integrated in time (method of lines).

Every cell of the steady model (:class:`~rotarykiln.kiln.residual.KilnResidual`, the same
cells, closures, burner, reactions and bed profile) becomes a set of ordinary differential
equations: what a balance does not pass on, it stores,

.. math:: \frac{dU_{j,r}}{dt} = -R_{j,r}(x)

with :math:`R` the steady residual of row r of cell j (net outflow: energy in W, species in
kg/s) and :math:`U` the hold-up of :mod:`rotarykiln.kiln.transient.holdup`: bed species
:math:`M_{ij} = \tau_j \dot m_{ij}`, bed energy :math:`\tau_j\sum_i \dot m_{ij} h_i(T_b)`,
gas likewise with its own (real, frozen) hold-up, and the wall nodes :math:`C_k T_k`. The
unknowns stay those of the steady model (temperatures at the cell outlets, species flows), so

.. math:: \frac{d\dot m_{ij}}{dt} = -\frac{R_{ij}}{\tau_j},\qquad
          \frac{dT_{b,j}}{dt} = \frac{-R^E_j - \tau_j\sum_i h_i\,d\dot m_{ij}/dt}
                                     {\tau_j\sum_i \dot m_{ij} c_{p,i}},\qquad
          \frac{dT_k}{dt} = \frac{R^{wall}_k}{C_k}.

Every bed and gas species is a state here (the steady model keeps the species no reaction
touches at their inlet flow), so a feed or fuel step travels with the solids and the gas.
The solids speed of the case is multiplied by the speed factor of the events
(:mod:`rotarykiln.kiln.transient.events`; 0 for a stopped drum): the transport terms of the bed rows, and
the bed's axial dispersion, are scaled by it. The exchange geometry (the fill profile of the
case) is held; the hold-up follows the flows. A solved Kramers bed depth is not supported.

A non-reacting tracer rides with the bed: its mass :math:`m_j` in each cell leaves at
:math:`s\,m_j/\tau_j` and disperses with the bed
(:func:`~rotarykiln.kiln.bed.dispersion.dispersion_sources`); a pulse in the feed gives the RTD of
the dynamic model.

The system is integrated by scipy's BDF (variable order, implicit, stiff) with a Jacobian by
forward differences (:meth:`TransientKiln.jacobian`): the columns that reach no common row
perturbed together (the couplings of each variable to the rows of its own and the neighbouring
cells probed on the block-tridiagonal band of the steady Newton, :meth:`TransientKiln.probe`),
all evaluated in one batched call of the right-hand side, as a sparse matrix; BDF reuses it
across steps as long as its Newton iteration converges. Quadrature states integrate the energy and
every species across the two ends (feed, discharge, gas inlet and outlet), the shell loss, the
heat released and the heat of reaction, so the energy and element balances over time are
checked against the inventories.

References
----------
W.E. Schiesser, The Numerical Method of Lines, Academic Press (1991); L.F. Shampine,
M.W. Reichelt, SIAM J. Sci. Comput. 18 (1997) 1-22 (the BDF/NDF codes scipy follows).
"""

from __future__ import annotations

import time as _time
from dataclasses import dataclass

import numpy as np
from scipy.integrate import BDF
from scipy.sparse import csc_matrix, lil_matrix

from rotarykiln.errors import ConvergenceError, InputError
from rotarykiln.kiln.accounting import global_balance
from rotarykiln.kiln.bed.dispersion import dispersion_sources
from rotarykiln.kiln.inputs.boundary import BoundaryInputs
from rotarykiln.kiln.residual import T_FLOOR, KilnResidual
from rotarykiln.kiln.results.transient import TransientSolution
from rotarykiln.kiln.steady.newton import band_entries, colour_batch
from rotarykiln.kiln.transient.events import (
    Schedule,
    Transient,
    check_output_size,
    output_times_bound,
)
from rotarykiln.kiln.transient.holdup import Holdup, WallProperties, refine_lining

__all__ = ["TransientKiln", "simulate"]

#: Temperature step of the numerical heat capacity dh/dT, K.
CP_STEP = 1e-3
#: Relative step of the finite-difference Jacobian (the steady Newton's), of max(|y|, floor).
JAC_STEP = 1e-7
#: Floors of the Jacobian steps: temperatures (K), species flows (over the inlet flows, the
#: steady solve's), tracer mass (kg; the tracer rows are linear in it).
JAC_FLOOR_T, JAC_FLOOR_SPECIES, JAC_FLOOR_TRACER = 1.0, 1e-6, 1.0
#: Most output states whose boundary flows are evaluated in one batched call.
COLLECT_BATCH = 64


@dataclass
class _Run:
    segment: int = 0
    calls: int = 0
    t_max: float = 0.0


class TransientKiln:
    """The method-of-lines system of a :class:`~rotarykiln.kiln.inputs.kiln.Kiln` on ``n`` cells.

    ``wall`` (:class:`~rotarykiln.kiln.transient.holdup.WallProperties`): heat capacity of the wall.
    The lining is cut into sub-layers (:func:`~rotarykiln.kiln.transient.holdup.refine_lining`).
    """

    def __init__(self, kiln, n_cells: int, wall: WallProperties):
        if kiln.bed.depth is not None:
            raise InputError(
                "transport",
                "a solved bed depth",
                "a fixed fill or residence time for the transient model (it holds the bed "
                "profile of the case)",
            )
        if any(z.shell_temperature is not None for z in kiln.wall.heaters):
            raise InputError(
                "wall.heaters",
                "a shell_temperature set-point",
                "a power for the transient model (a set-point needs a controller)",
            )
        self.kiln_case = kiln
        parent = None
        if kiln.wall.layers:
            layers, parent = refine_lining(kiln.wall.layers, wall.max_node_spacing)
            kiln = kiln.replace(wall__layers=layers)
        self.kiln = kiln
        self.layer_parent = parent
        self.wall_props = wall
        # the steady residual with every bed and gas species an unknown (linear flows): its
        # steady solutions are the steady model's (a species no reaction touches keeps its
        # flow); the species rows in kg/s over the inlet flows (q_ref 1)
        self.res = res = KilnResidual(kiln, n_cells, q_ref=1.0, every_species=True)
        self.n, self.nv = res.n, res.nv
        self.m = res.nv + 1  # + tracer mass per cell
        i0 = res.i_species
        self.sb = slice(i0, i0 + res.nb)  # bed species of a cell's unknowns
        self.sg = slice(i0 + res.nb, i0 + res.nb + res.ng)  # gas species
        self.n_acc = 1 + res.nb + res.ng  # energy, bed species, gas species across boundaries
        self.size = self.n * self.m + self.n_acc
        self.holdup: Holdup | None = None
        self.jac_floor = np.concatenate(
            [
                np.full(res.i_species, JAC_FLOOR_T),
                np.full(res.nv - res.i_species, JAC_FLOOR_SPECIES),
                [JAC_FLOOR_TRACER],
            ]
        )
        self._floor_flat = np.tile(self.jac_floor, self.n)
        self._bed_mass = res.kiln.bed.bulk_density * res.grid.bed_area * np.ones(self.n)
        #: the block of each row of a cell: 0 the fluid rows (bed and gas energy, species),
        #: then each wall node's row, then the tracer's (:meth:`probe`)
        self.row_block = np.zeros(self.m, dtype=np.intp)
        self.row_block[2 : res.i_species] = np.arange(1, res.i_species - 1)
        self.row_block[res.nv] = res.i_species - 1
        #: which rows of the neighbouring cells each variable's column reaches (offsets -1, 0,
        #: +1; :meth:`probe`), and which cells
        self.couplings: np.ndarray | None = None
        self.reach: np.ndarray | None = None
        self._jac_structure = None

    # --- states --------------------------------------------------------------------------
    def steady_state(self, kiln=None, **kw):
        """The unknowns (n, nv) of the steady solution of ``kiln`` (default: the case's),
        and the :class:`~rotarykiln.kiln.results.solution.KilnSolution`."""
        from rotarykiln.kiln.steady.solve import solve_kiln

        k = self.kiln if kiln is None else kiln
        sol = solve_kiln(k, self.n, **kw)
        return self.unknowns_of(sol), sol

    def unknowns_of(self, sol) -> np.ndarray:
        """The transient unknowns (n, nv) of a steady solution on the same cells."""
        res = self.res
        x = np.empty((self.n, self.nv))
        x[:, 0] = sol.t_bed_nodes[1:]
        x[:, 1] = sol.t_gas_nodes[res.gas_out]
        x[:, 2 : res.i_species] = sol.fluxes["x"][:, 2 : res.i_species]
        for i, s in enumerate(res.bed_names):
            x[:, self.sb.start + i] = sol.bed_flows[s][1:] / res.bed_scale
        for i, s in enumerate(res.gas_names):
            x[:, self.sg.start + i] = sol.gas_flows[s][res.gas_out] / res.gas_scale
        return x

    def cold_state(self, u: BoundaryInputs) -> np.ndarray:
        """A cold kiln: everything at ambient, filled with its hold-up of feed, gas flowing."""
        res = self.res
        x = np.empty((self.n, self.nv))
        x[:, : res.i_species] = self.kiln.wall.ambient_temperature
        x[:, self.sb] = u.feed / res.bed_scale
        x[:, self.sg] = u.gas / res.gas_scale
        return x

    def pack(self, x, tracer=None) -> np.ndarray:
        y = np.zeros(self.size)
        blk = y[: self.n * self.m].reshape(self.n, self.m)
        blk[:, : self.nv] = x
        if tracer is not None:
            blk[:, self.nv] = tracer
        return y

    def unpack(self, y):
        blk = y[: self.n * self.m].reshape(self.n, self.m)
        return blk[:, : self.nv], blk[:, self.nv], y[self.n * self.m :]

    # --- inventories and boundary flows ----------------------------------------------------
    def inventory(self, x):
        """Energy (J, sensible above 298.15 K), bed and gas species (kg) held by the kiln."""
        res, h = self.res, self.holdup
        qb = x[:, self.sb] * res.bed_scale
        qg = x[:, self.sg] * res.gas_scale
        hb = res.bed_enthalpy(x[:, 0])
        hg = res.mixture.species_enthalpy(x[:, 1])
        mb = h.tau_bed[:, None] * qb
        mg = h.tau_gas[:, None] * qg
        energy = (mb * hb).sum() + (mg * hg).sum() + (h.wall * x[:, 2 : res.i_species]).sum()
        return float(energy), mb.sum(0), mg.sum(0)

    # --- the right-hand side ---------------------------------------------------------------
    def rhs(
        self, t, y, schedule: Schedule, run: _Run, fluxes: bool = False, quadrature: bool = True
    ):
        """dy/dt at ``t``; ``y`` of shape (size,) or (size, k) (a batch of k states, for the
        finite-difference Jacobian: the residual is evaluated once for all of them). Without
        ``quadrature`` the rates of the quadrature states are left 0 (the Jacobian's batch:
        its quadrature rows are empty). With ``fluxes``, also the flows across the boundary
        (:meth:`boundary`): of the state, or arrays over the batch."""
        res, hold = self.res, self.holdup
        run.calls += 1
        run.t_max = max(run.t_max, t)
        single = y.ndim == 1
        Yb = (y[:, None] if single else y).T  # (k, size)
        kb = Yb.shape[0]
        blk_in = Yb[:, : self.n * self.m].reshape(kb, self.n, self.m)
        x, tracer = blk_in[..., : self.nv], blk_in[..., self.nv]
        u = schedule.inputs(t, run.segment)
        # the residual, with the species enthalpies at the faces and the heat capacities dh/dT
        # at the cells' outlets (central differences of CP_STEP) from its own enthalpy calls
        R, fl, prod, _, (tb_n, tg_n, qb, qg), (hb_nodes, c_b, hg_nodes, c_g) = res.evaluate(
            x, full=True, inputs=u, heat_capacity_step=CP_STEP
        )
        s = u.speed_factor
        dz = res.dz
        n = self.n
        disp_e = disp_s = None
        D = res.kiln.bed.dispersion
        holdup_m = self._bed_mass
        if s != 1.0:
            # actual transport = s x the transport of the flows held (the feed unscaled)
            R = R.copy()
            if D > 0:
                disp_e, disp_s = dispersion_sources(D, holdup_m, qb, hb_nodes, dz, res.disperses)
            Hb = (qb * hb_nodes).sum(-1)
            inner = np.ones(n)
            inner[0] = 0.0
            R[..., 0] += (s - 1.0) * (Hb[..., 1:] - inner * Hb[..., :-1])
            dq = qb[..., 1:, :] - inner[:, None] * qb[..., :-1, :]
            R[..., self.sb] += (s - 1.0) * dq / res.bed_scale
            if D > 0:
                R[..., 0] += (1.0 - s) * disp_e
                R[..., self.sb] += (1.0 - s) * disp_s / res.bed_scale
        dY = np.empty_like(Yb)
        blk = dY[:, : self.n * self.m].reshape(kb, self.n, self.m)
        # species: d(tau Q)/dt = -R (scaled units)
        db = -R[..., self.sb] / hold.tau_bed[:, None]
        dg = -R[..., self.sg] / hold.tau_gas[:, None]
        blk[..., self.sb] = db
        blk[..., self.sg] = dg
        # bed energy at the outlet face of each cell
        q_b = qb[..., 1:, :]
        h_b = hb_nodes[..., 1:, :]
        cap_b = hold.tau_bed * np.maximum((q_b * c_b).sum(-1), 1e-12 * res.bed_scale)
        blk[..., 0] = (-R[..., 0] - hold.tau_bed * (h_b * db).sum(-1) * res.bed_scale) / cap_b
        # gas energy at the gas outlet face of each cell
        q_g = qg[..., res.gas_out, :]
        h_g = hg_nodes[..., res.gas_out, :]
        cap_g = hold.tau_gas * np.maximum((q_g * c_g).sum(-1), 1e-12 * res.gas_scale)
        blk[..., 1] = (-R[..., 1] - hold.tau_gas * (h_g * dg).sum(-1) * res.gas_scale) / cap_g
        # wall nodes: the rows are what each node receives
        blk[..., 2 : res.i_species] = R[..., 2 : res.i_species] / hold.wall
        # tracer: leaves each cell at s m / tau, disperses with the bed (none fed and none
        # held, as in a run without a pulse: nothing moves, exactly)
        if u.tracer == 0.0 and not tracer.any():
            d_tr = 0.0
        else:
            t_out = s * tracer / hold.tau_bed
            feed_tr = np.full((kb, 1), u.tracer)
            t_in = np.concatenate([feed_tr, t_out[:, :-1]], -1)
            d_tr = t_in - t_out
            if D > 0 and s > 0:
                bulk = s * qb.sum(-1)
                bulk[:, 0] = u.feed.sum()
                tq = np.stack([bulk, np.concatenate([feed_tr, t_out], -1)], -1)
                _, sp = dispersion_sources(
                    s * D, holdup_m, tq, np.zeros_like(tq), dz, np.array([False, True])
                )
                d_tr = d_tr + sp[..., 1]
        blk[..., self.nv] = d_tr
        # quadrature: energy and species across the ends, losses, sources
        if not (quadrature or fluxes):
            dY[:, self.n * self.m :] = 0.0
            return dY[0] if single else dY.T
        flux = self.boundary(
            u, fl, prod, tb_n, tg_n, qb, qg, hb_nodes, hg_nodes, accumulation_only=not fluxes
        )
        dY[:, self.n * self.m :] = flux["acc"]
        if not fluxes:
            return dY[0] if single else dY.T
        if not single:
            return dY.T, flux
        one = {k: v[0] for k, v in flux.items() if k not in ("bed_outlet", "gas_outlet")}
        for k in ("bed_outlet", "gas_outlet"):
            one[k] = {name: float(v[0]) for name, v in flux[k].items()}
        return dY[0], one

    def boundary(
        self,
        u,
        fl,
        prod,
        tb_n,
        tg_n,
        qb,
        qg,
        hb_nodes=None,
        hg_nodes=None,
        accumulation_only=False,
    ):
        """Flows across the kiln's boundary (W and kg/s), arrays over the batch: the energy
        terms of :func:`~rotarykiln.kiln.accounting.global_balance`, the species across the
        ends, and the outlets, the outlet flow of each species too (with
        ``accumulation_only``, only ``acc``: the right-hand side of the quadrature states, as
        the integrator needs it)."""
        res = self.res
        s = u.speed_factor
        gi, go = (-1, 0) if res.kiln.gas.counter_current else (0, -1)
        if hb_nodes is None or hg_nodes is None:  # the enthalpies at the floored faces
            tb_n, tg_n = np.maximum(tb_n, T_FLOOR), np.maximum(tg_n, T_FLOOR)
        bal = global_balance(
            res,
            fl,
            prod,
            tb_n,
            tg_n,
            qb,
            qg,
            u,
            bed_enthalpy=hb_nodes,
            gas_enthalpy=hg_nodes,
            reaction_from_sources=True,
        )
        kb = qb.shape[0]
        net_b = u.feed - s * qb[:, -1]
        net_g = qg[:, gi] - qg[:, go]
        acc = np.concatenate([bal["net"][:, None], net_b, net_g], -1)
        if accumulation_only:
            return {"acc": acc}
        out = {
            "energy_in_W": bal["energy_in"],
            "energy_out_W": bal["energy_out"],
            "shell_loss_W": bal["shell_loss"],
            "heat_release_W": bal["release"],
            "electric_heating_W": bal["heating"],
            "reaction_heat_W": bal["reaction_heat"],
            "bed_outlet_temperature_K": tb_n[:, -1],
            "gas_outlet_temperature_K": tg_n[:, go],
            "solids_outlet_flow_kg_s": s * qb[:, -1].sum(-1),
            "gas_outlet_flow_kg_s": qg[:, go].sum(-1),
            "feed_kg_s": np.full(kb, u.feed.sum()),
            "gas_inlet_temperature_K": np.full(kb, u.gas_temperature),
            "speed_factor": np.full(kb, s),
        }
        out = {"acc": acc} | {k: np.asarray(v, dtype=float) for k, v in out.items()}
        out["bed_outlet"] = {n: s * qb[:, -1, i] for i, n in enumerate(res.bed_names)}
        out["gas_outlet"] = {n: qg[:, go, i] for i, n in enumerate(res.gas_names)}
        return out

    def jacobian(self, t, y, schedule: Schedule, run: _Run, f=None):
        """d(dy/dt)/dy at ``t``, ``y`` (CSC) by forward differences, the columns perturbed
        together in few colours, all evaluated with the unperturbed state in one batched call
        of :meth:`rhs` (without its quadrature states); ``f``: the right-hand side at ``y``
        when the caller has it (the batch then leaves the unperturbed state out: a state's
        right-hand side is the same to the last bit alone or in a batch).

        A column (variable v of cell j) reaches the rows of the cells ``j + o`` of
        :attr:`couplings` (:meth:`probe`: the wall nodes their own cell, the nodes inside the
        lining only the wall rows, the gas and bed variables the fluid rows of the next cell
        along their flow, the bed both neighbours with dispersion); columns that reach no
        common row share a colour (:meth:`_structure`; Barr's lined kiln: 18 colours instead
        of the ``3 m`` = 45 of the block-tridiagonal band of the steady Newton,
        :func:`~rotarykiln.kiln.steady.newton.colour_batch`). Every entry is the difference
        quotient of its own column, with the step ``JAC_STEP`` x max(|y|, floor) of the band
        Jacobian: the same entries, to the last bit; the entries that are 0 are not stored.
        The quadrature rows and columns are left empty, as in :meth:`sparsity`.
        """
        n, m = self.n, self.m
        nm = n * m
        if self.couplings is None:
            self.probe(t, y, schedule, run)
        flat_colour, k, src, step, indices, indptr = self._structure()
        yb = y[:nm]
        h = JAC_STEP * np.maximum(np.abs(yb), self._floor_flat)
        h = (yb + h) - yb  # the step actually taken
        base = f is None  # the unperturbed state evaluated too (last)
        Y = np.empty((k + base, self.size))
        Y[:] = y
        Y[flat_colour, np.arange(nm)] = yb + h
        F = self.rhs(t, Y.T, schedule, run, quadrature=False).T  # (k [+ 1], size)
        dR = F[:k, :nm] - (F[k, :nm] if base else f[:nm])  # [colour, row]
        data = dR.ravel()[src] / h[step]
        J = csc_matrix((data, indices, indptr), shape=(self.size, self.size))
        J.eliminate_zeros()  # BDF's I - c J and its LU then skip them
        return J

    def probe(self, t, y, schedule: Schedule, run: _Run, spread_only=False) -> np.ndarray:
        """Which rows of the neighbouring cells each variable of a cell reaches: (m, 3, m) bool
        over the offsets -1, 0, +1 of the row's cell from the column's and the rows of that
        cell, kept in :attr:`couplings` (the union over the calls; a variable's own row
        always), by blocks of rows (:attr:`row_block`): the fluid rows of a cell (bed and gas
        energy, species) are reached together, a wall node's row and the tracer's alone.
        :attr:`reach`: the cells reached, (m, 3).

        The block-tridiagonal band Jacobian (``3 m`` colours,
        :func:`~rotarykiln.kiln.steady.newton.colour_batch`) by forward differences at ``y``
        and at a state spread about it (temperatures 1 to 50 K higher, the flows scaled by
        0.9 to 1.1 and kept off 0, a seeded generator): a variable reaches a block of rows
        when any entry of its column there differs from 0 at either state. The second state
        keeps the couplings that vanish at ``y`` itself (the enthalpy a flow carries is 0 at
        298.15 K: a cold kiln). A fluid row takes its block with it: the reactions, the
        exchange and the transport couple a cell's fluid rows in ways a state may hide; a wall
        node's row is its conduction (and the inner wall's exchange), the tracer's its
        transport. :func:`simulate` probes at each solids speed a segment of the schedule
        starts or ends with (the inputs of the segment); ``spread_only``: the spread state
        only (the couplings at ``y`` are already known). The probe costs one batched call of
        2 (``3 m + 1``) states: a few Jacobians.
        """
        n, m = self.n, self.m
        nm = n * m
        i0 = self.res.i_species
        blk = y[:nm].reshape(n, m)
        rng = np.random.default_rng(0)
        spread = blk.copy()
        spread[:, :i0] += rng.uniform(1.0, 50.0, (n, i0))
        spread[:, i0:] = np.abs(spread[:, i0:]) * rng.uniform(0.9, 1.1, (n, m - i0))
        spread[:, i0:] += rng.uniform(0.01, 0.05, (n, m - i0))
        src, rows, cols, _ = band_entries(n, m)
        off = rows // m - cols // m + 1
        var = cols % m
        block = self.row_block[rows % m]
        n_blocks = int(self.row_block.max()) + 1
        hits = np.zeros((m, 3, n_blocks), dtype=bool)
        hits[np.arange(m), 1, self.row_block] = True  # a variable's own row
        nc = 3 * m
        states = (spread,) if spread_only else (blk, spread)
        Y = np.empty((len(states), nc + 1, self.size))
        for state, part in zip(states, Y, strict=True):
            h = JAC_STEP * np.maximum(np.abs(state), self.jac_floor)
            h = (state + h) - state
            part[:nc, :nm] = colour_batch(state, h).reshape(nc, nm)
            part[nc, :nm] = state.ravel()
            part[:, nm:] = y[nm:]
        with np.errstate(all="ignore"):  # a NaN of the spread state only adds couplings
            F = self.rhs(t, Y.reshape(-1, self.size).T, schedule, run, quadrature=False)
        F = F.T.reshape(Y.shape)
        for part in F[..., :nm]:
            dR = part[:nc] - part[nc]
            hit = dR.ravel()[src] != 0.0
            hits[var[hit], off[hit], block[hit]] = True
        couplings = hits[..., self.row_block]  # every row of a block reached
        if self.couplings is not None:
            couplings |= self.couplings
        if self.couplings is None or not np.array_equal(couplings, self.couplings):
            self.couplings = couplings
            self.reach = couplings.any(-1)
            self._jac_structure = None
        return couplings

    def _structure(self):
        """The colouring of the Jacobian's columns for :attr:`couplings` and its CSC layout,
        computed once per couplings.

        Column (cell j, variable v) reaches the rows ``couplings[v, o + 1]`` of cell ``j + o``.
        Columns that reach no common row share a colour: taken in turn (the variables reaching
        the most rows first, then by cell), each column takes the first colour none of whose
        columns reaches one of its rows (greedy colouring of the columns' intersection graph;
        A.R. Curtis, M.J.D. Powell, J.K. Reid, IMA J. Appl. Math. 13 (1974) 117-119). A wall
        node, which reaches the wall rows of its own cell only, shares the colours of the fluid
        variables (Barr's lined kiln: 18 colours, 27 for whole cells, 45 for the band).
        Returns the colour of each flattened column, the number of colours, and for every
        stored entry (by column, rows sorted) its place in the differences ``dR[colour,
        row]`` and its column, with the CSC ``indices`` and ``indptr`` of the whole
        (quadrature-padded) matrix.
        """
        if self._jac_structure is None:
            n, m = self.n, self.m
            nm = n * m
            cells = np.arange(n)
            rows, cols = [], []
            for o in (-1, 0, 1):
                v, r = np.nonzero(self.couplings[:, o + 1, :])
                j = cells[(cells + o >= 0) & (cells + o < n)]
                rows.append(((j + o)[:, None] * m + r).ravel())
                cols.append((j[:, None] * m + v).ravel())
            rows, cols = np.concatenate(rows), np.concatenate(cols)
            order = np.lexsort((rows, cols))
            rows, cols = rows[order], cols[order]
            indptr = np.searchsorted(cols, np.arange(self.size + 1))
            # greedy colouring: used[c, row] when a column of colour c reaches the row
            reached = self.couplings.sum((1, 2))
            turn = sorted(range(nm), key=lambda c: (-reached[c % m], c % m, c // m))
            used = np.zeros((0, nm), dtype=bool)
            flat_colour = np.empty(nm, dtype=np.intp)
            for c in turn:
                hit = rows[indptr[c] : indptr[c + 1]]
                free = np.flatnonzero(~used[:, hit].any(1))
                if free.size:
                    k = free[0]
                else:
                    k = used.shape[0]
                    used = np.vstack([used, np.zeros((1, nm), dtype=bool)])
                used[k, hit] = True
                flat_colour[c] = k
            src = flat_colour[cols] * nm + rows
            self._jac_structure = (flat_colour, used.shape[0], src, cols, rows, indptr)
        return self._jac_structure

    def sparsity(self):
        """Block-tridiagonal pattern of the Jacobian (quadrature rows left empty: they
        feed back into nothing, and their Newton update is exact without them)."""
        n, m = self.n, self.m
        S = lil_matrix((self.size, self.size), dtype=np.int8)
        for j in range(n):
            lo, hi = max(j - 1, 0) * m, min(j + 2, n) * m
            S[j * m : (j + 1) * m, lo:hi] = 1
        return S.tocsr()


def simulate(
    kiln,
    n_cells: int,
    transient: Transient,
    until: float,
    *,
    rtol: float = 1e-6,
    newton_tol: float | None = None,
    progress: bool | None = False,
    steady=None,
    times=None,
) -> TransientSolution:
    """Integrate the transient kiln from t = 0 to ``until`` (s) under ``transient``'s events.

    Parameters
    ----------
    kiln : Kiln
        The kiln of the case (:func:`~rotarykiln.kiln.from_case.kiln_from_case`).
    n_cells : int
        Cells along the kiln (the steady model's grid).
    transient : Transient
        Start (steady or cold), events, tracer pulse, wall heat capacities, output interval
        (:class:`~rotarykiln.kiln.transient.events.Transient`).
    until : float, s
        End of the run.
    rtol : float
        Relative tolerance of the BDF integrator (absolute tolerances: 1e-4 K on
        temperatures, ``rtol`` x 1e-2 of the inlet flows on species).
    newton_tol : float, optional
        Tolerance of the BDF Newton iteration (scaled; scipy's default sqrt(rtol)): lower
        it to close the energy balance tighter.
    progress : bool or None
        A tqdm progress bar over simulated time, on stderr (None: when
        ``$ROTARYKILN_PROGRESS`` asks or stderr is a terminal;
        :func:`rotarykiln.progress.progress_enabled`).
    steady : KilnSolution, optional
        The steady solution of the case (on the same cells and refined lining) to start from.
    times : array, optional
        Output times (s); default every ``output_every`` or ``until`` / 200.

    Returns
    -------
    :class:`~rotarykiln.kiln.results.transient.TransientSolution`

    Raises
    ------
    ConvergenceError
        The integrator fails (step size collapse); the message gives the time reached.

    Examples
    --------
    >>> import warnings
    >>> from rotarykiln.api import load_case
    >>> from rotarykiln.kiln.from_case import kiln_from_case
    >>> from rotarykiln.transient_file import parse_transient
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     kiln, _ = kiln_from_case(load_case("tscheng_A16"))
    ...     tr = parse_transient({"output_every": "10 min", "events": [
    ...         {"at": "0 s", "variable": "gas_inlet_temperature", "to": "600 K"}]},
    ...         kiln, 3600.0)
    ...     sol = simulate(kiln, 10, tr, 3600.0)
    >>> s = sol.summary()
    >>> bool(s["gas_outlet_temperature_end_K"] > s["gas_outlet_temperature_start_K"] + 10)
    True

    References
    ----------
    W.E. Schiesser, The Numerical Method of Lines, Academic Press (1991); L.F. Shampine,
    M.W. Reichelt, SIAM J. Sci. Comput. 18 (1997) 1-22 (scipy's BDF).
    """
    if not until > 0:
        raise InputError("--until", until, "> 0 s")
    # the profiles kept (cells x output times, the events' times included) are bounded before
    # anything is allocated (kiln.events.MAX_OUTPUT_TIMES, MAX_OUTPUT_VALUES)
    if times is None:
        check_output_size(n_cells, output_times_bound(transient, until))
    else:
        check_output_size(n_cells, int(np.size(times)) + 2 * len(transient.events) + 4, "times")
    tk = TransientKiln(kiln, n_cells, transient.wall)
    res = tk.res
    sched = Schedule(kiln, res.bed_names, res.gas_names, transient.events, until, transient.tracer)
    u0 = sched.inputs(0.0, 0)
    if transient.start == "steady":
        if steady is None:
            x0, steady = tk.steady_state()
        else:
            x0 = tk.unknowns_of(steady)
    else:
        x0 = tk.cold_state(u0)
    tg_cells = _gas_cell_temperature(res, x0, u0)
    tk.holdup = Holdup.of(res, transient.wall, tg_cells, tk.layer_parent)
    y = tk.pack(x0)
    if times is None:
        every = transient.output_every or until / 200.0
        times = np.arange(0.0, until + 0.5 * every, every)
        times = np.unique(np.clip(times, 0.0, until))
    times = np.asarray(times, dtype=float)
    cuts = sorted({a for a, _ in sched.segments()} | {until})
    times = np.unique(np.concatenate([times, cuts]))
    atol = np.empty(tk.size)
    blk = atol[: tk.n * tk.m].reshape(tk.n, tk.m)
    blk[:, : res.i_species] = 1e-4
    blk[:, res.i_species : tk.nv] = rtol * 1e-2
    tr_scale = 1.0
    if transient.tracer is not None:
        t0, dt, mass = transient.tracer
        tr_scale = mass if mass is not None else 0.01 * sched.base["feed"] * dt
    blk[:, tk.nv] = rtol * 1e-3 * tr_scale
    # the quadratures: 1 J of energy; of each species, what its phase carries through the kiln
    # in rtol seconds (the element closure is judged over the throughput)
    flows = np.concatenate([np.full(res.nb, res.bed_scale), np.full(res.ng, res.gas_scale)])
    atol[tk.n * tk.m :] = np.concatenate([[1.0], rtol * flows])
    run = _Run()
    from rotarykiln.progress import progress_bar, progress_enabled

    bar = None
    if progress_enabled(progress):
        bar = progress_bar(float(until), desc="transient", unit="s", enabled=True)
    states, stamp = [], []
    started = _time.perf_counter()
    probed = set()
    try:
        for i, (a, b) in enumerate(sched.segments()):
            run.segment = i
            for tp in (a, b):
                # the couplings of the Jacobian's columns change with the solids speed only (the
                # bed's transport and dispersion scale with it; a stopped drum carries nothing):
                # probed at each speed the segments start or end with (a ramp's ends)
                speed = sched.inputs(tp, i).speed_factor
                if speed not in probed:
                    tk.probe(tp, y, sched, run, spread_only=bool(probed))
                    probed.add(speed)
            te = times[(times >= a) & (times <= b)]
            ts, ys = _integrate(
                tk.rhs, tk.jacobian, a, b, y, te, rtol, atol, (sched, run), newton_tol, bar
            )
            for tt, yy in zip(ts, ys, strict=True):
                if stamp and tt <= stamp[-1][0]:
                    continue  # a segment's first time is the previous one's last (left limit kept)
                stamp.append((float(tt), i))
                states.append(yy)
            y = ys[-1].copy()
            if bar is not None:
                bar.update(b - bar.n)
    finally:
        if bar is not None:
            bar.close()
    wall_time = _time.perf_counter() - started
    return _collect(tk, sched, stamp, states, steady, wall_time, run.calls, transient)


def _integrate(fun, jac, a, b, y0, t_eval, rtol, atol, args, newton_tol, bar):
    """BDF from ``a`` to ``b`` (s): the states at ``t_eval`` (``b`` included).

    scipy's :class:`~scipy.integrate.BDF` stepped by hand (as ``solve_ivp`` does) to set a
    tighter Newton tolerance: a linear invariant (the energy and elements held plus those that
    crossed the boundary) is kept by the BDF formula only as well as its Newton iteration
    converges. The last right-hand sides are kept: when the Newton iteration fails with an old
    Jacobian, BDF evaluates a new one and starts again from the same predicted state, whose
    right-hand side it already has (and the Jacobian's differences take it as their base).
    """
    recent = []  # the last right-hand sides evaluated, (t, y, f)

    def known(t, y):
        for t_k, y_k, f_k in recent:
            if t_k == t and np.array_equal(y_k, y):
                return f_k
        return None

    def rhs(t, y):
        f = known(t, y)
        if f is not None:
            return f.copy()
        f = fun(t, y, *args)
        recent.insert(0, (t, y.copy(), f.copy()))
        del recent[4:]  # a Newton iteration of scipy's BDF makes at most 4
        return f

    def jacobian(t, y):
        # BDF asks for it at the predicted state whose Newton iteration failed (or at the
        # start): its right-hand side is known
        return jac(t, y, *args, f=known(t, y))

    solver = BDF(rhs, a, y0, b, rtol=rtol, atol=atol, jac=jacobian)
    if newton_tol is not None:
        solver.newton_tol = newton_tol
    t_eval = np.asarray(t_eval, dtype=float)
    ts, ys = [a], [np.array(y0, dtype=float)]
    t_eval = t_eval[t_eval > a]
    while solver.status == "running":
        t_old = solver.t
        message = solver.step()
        if solver.status == "failed":
            raise ConvergenceError(
                f"the transient integration failed at t = {solver.t:.6g} s: {message}",
                step=float(solver.step_size or 0.0),
            )
        hit = t_eval[(t_eval > t_old) & (t_eval <= solver.t)]
        if hit.size:
            dense = solver.dense_output()
            for t in hit:
                ts.append(float(t))
                ys.append(solver.y.copy() if t == solver.t else dense(t))
        if bar is not None:
            bar.update(solver.t - bar.n)
    if ts[-1] < b:
        ts.append(b)
        ys.append(solver.y.copy())
    return ts, ys


def _gas_cell_temperature(res, x, u):
    """Cell-mean gas temperature (K) of the unknowns ``x`` with the inlet temperature of ``u``."""
    if res.kiln.gas.counter_current:
        faces = np.concatenate([x[:, 1], [u.gas_temperature]])
    else:
        faces = np.concatenate([[u.gas_temperature], x[:, 1]])
    return np.maximum(0.5 * (faces[1:] + faces[:-1]), T_FLOOR)


def _collect(tk, sched, stamp, states, steady, wall_time, calls, transient):
    res = tk.res
    t = np.array([s[0] for s in stamp])
    Y = np.array(states)
    n = len(t)
    x_all = np.empty((n, tk.n, tk.nv))
    tracer = np.empty((n, tk.n))
    acc = np.empty((n, tk.n_acc))
    outlet = []
    inv_e = np.empty(n)
    inv_b = np.empty((n, res.nb))
    inv_g = np.empty((n, res.ng))
    tb_faces = np.empty((n, tk.n + 1))
    tg_faces = np.empty((n, tk.n + 1))
    run = _Run()
    flux = {}
    for k in range(n):
        x, tr, a = tk.unpack(Y[k])
        x_all[k], tracer[k], acc[k] = x, tr, a
        run.segment = stamp[k][1]
        u = sched.inputs(t[k], stamp[k][1])
        if k not in flux:
            # the boundary flows of the next output states of the same inputs, in one call
            same = [k]
            while (
                len(same) < COLLECT_BATCH
                and same[-1] + 1 < n
                and stamp[same[-1] + 1][1] == stamp[k][1]
                and sched.inputs(t[same[-1] + 1], stamp[k][1]) is u
            ):
                same.append(same[-1] + 1)
            _, f = tk.rhs(t[k], Y[same].T, sched, run, fluxes=True)
            for e, i in enumerate(same):
                flux[i] = {
                    key: ({s: v[e] for s, v in val.items()} if isinstance(val, dict) else val[e])
                    for key, val in f.items()
                    if key != "acc"
                }
        tb_n, tg_n, _, _ = res.faces(x)
        tb_faces[k], tg_faces[k] = tb_n, tg_n
        out = flux.pop(k)
        out["bed_outlet"] = {s: float(v) for s, v in out["bed_outlet"].items()}
        out["gas_outlet"] = {s: float(v) for s, v in out["gas_outlet"].items()}
        out["tracer_outlet_kg_s"] = float(u.speed_factor * tr[-1] / tk.holdup.tau_bed[-1])
        outlet.append(out)
        inv_e[k], inv_b[k], inv_g[k] = tk.inventory(x)
    return TransientSolution(
        name=res.kiln.name,
        t=t,
        z_nodes=res.z_nodes,
        z=res.z,
        x=x_all,
        t_bed_nodes=tb_faces,
        t_gas_nodes=tg_faces,
        tracer=tracer,
        accumulated=acc,
        inventory_energy=inv_e,
        inventory_bed=inv_b,
        inventory_gas=inv_g,
        outlet=outlet,
        bed_names=res.bed_names,
        gas_names=res.gas_names,
        wall_labels=tuple(res.wall.labels()),
        i_species=res.i_species,
        bed_scale=res.bed_scale,
        gas_scale=res.gas_scale,
        gas_out=res.gas_out,
        species=res.species,
        steady=steady,
        holdup=tk.holdup,
        tracer_mass=_tracer_mass(transient, sched),
        wall_time=wall_time,
        rhs_calls=calls,
        counter_current=res.kiln.gas.counter_current,
    )


def _tracer_mass(transient, sched):
    if transient.tracer is None:
        return 0.0
    t0, dt, mass = transient.tracer
    return mass if mass is not None else 0.01 * sched.base["feed"] * dt
