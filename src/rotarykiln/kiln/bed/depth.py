r"""The bed depth of the reacting kiln solved inside its Newton system (Kramers-Croockewit).

With ``z`` measured from the feed end, the Kramers-Croockewit / Saeman equation
(:mod:`rotarykiln.transport.kramers`) reads

.. math:: \frac{dh}{dz} = C - K(q)\left[\frac{h}{R}\left(2 - \frac{h}{R}\right)\right]^{-3/2},
          \qquad K = \frac{3 q \tan\alpha}{4\pi n R^3},\quad C = \frac{\tan\psi}{\cos\alpha}

with :math:`q(z) = \sum_i Q_i(z)/\rho_b` the local volumetric solids flow: as the bed loses
mass (drying, calcination, pyrolysis) the flow and with it the depth fall. The depth at every
face except the discharge (where it is the dam height) is an unknown of the kiln's Newton
system; the residual of cell j is the trapezoidal (box) form

.. math:: h_{j+1} - h_j - \Delta z\,\Big[C - K(\bar q_j)\,P(\bar h_j)^{-3/2}\Big] = 0

with cell means :math:`\bar h_j, \bar q_j` of the two faces (second order, local: the system
stays block-tridiagonal). The cross-section of each cell (fill, chord, wall arcs, areas,
hydraulic diameter, beam length) follows the cell-mean depth, and so do the exchange areas and
the bed hold-up :math:`\rho A_{bed}` that the rate laws see.

The volumetric flow :math:`q` of the bed is a field of the law (``volume_law``, the case's
``transport.volume``), not a subclass:

- ``"bulk"`` (default): :math:`q = \sum_i Q_i/\rho_b`, the bulk density constant along the kiln
  (a bed that loses mass compacts and keeps its density: stated assumption);
- ``"fresh_feed"``: the particles keep the fresh feed's volume as they lose mass (the
  rotaryPyrolysis script's wood chips), or lose the fraction :math:`s` of it (``shrinkage``) at
  full conversion of the fed species,

  .. math:: q = \dot V_0\,[1 - s\,X],\qquad X = 1 - \sum_{i\,\in\,feed} Q_i / \dot m_0

  with :math:`\dot V_0` the fresh feed's volumetric flow (m3/s) and :math:`\dot m_0` its mass
  flow; the bed's bulk density :math:`\rho = \sum_i Q_i / q` then falls with the mass that
  leaves, and the hold-up of each species per metre is :math:`m'_i = Q_i A_{bed}/q`.

References
----------
H. Kramers, P. Croockewit, Chem. Eng. Sci. 1 (1952) 259; W.C. Saeman, Chem. Eng. Prog. 47
(1951) 508; Scott (1986) eq. 2.10; M. Pichler et al., J. Anal. Appl. Pyrolysis 158 (2021)
105171 (the constant-volume bed of its rotaryPyrolysis script).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import InputError, check_positive
from rotarykiln.geometry import CrossSection
from rotarykiln.kiln.grid import section_fields

__all__ = ["VOLUME_LAWS", "KramersBed"]

#: The volume laws of a bed (:attr:`KramersBed.volume_law`, the case's ``transport.volume``).
VOLUME_LAWS = ("bulk", "fresh_feed")


@dataclass(frozen=True)
class KramersBed:
    """Kramers bed-depth law of a kiln, for its Newton system (SI units).

    ``radius`` (m), ``omega`` (rad/s), ``slope`` (rad), ``repose`` (rad, dynamic angle of
    repose), ``density`` (kg/m3, the bed's bulk density at the feed: the kiln's
    ``bed.bulk_density``), ``dam_height`` (m, > 0 at the discharge).

    The bed's volume law (module docstring): ``volume_law`` ``"bulk"`` (the flow over
    ``density``) or ``"fresh_feed"`` (``volume_flow0``, the fresh feed's volumetric flow in
    m3/s, all along; ``shrinkage`` s in [0, 1), the fraction of it lost at full conversion of
    the fed species ``feed``: pairs (bed species, kg/s), needed with a shrinkage).

    Examples
    --------
    >>> bed = KramersBed(0.2, 0.157, 0.0175, 0.61, 1500.0, 0.03)
    >>> h = np.array([0.04, 0.05]); q = np.array([1e-5, 1e-5])
    >>> bed.residual(h, q, 0.1).shape
    (1,)
    >>> round(float(bed.volume_flow(("CaCO3",), np.array([[0.015]]))[0]), 12)
    1e-05

    Wood chips that keep the fresh feed's 3e-5 m3/s, or lose 30 % of it when charred:

    >>> chips = KramersBed(0.2, 0.2094, 0.0524, 0.6458, 279.5, 0.025,
    ...                    volume_law="fresh_feed", volume_flow0=3e-5, feed=(("wood", 0.008),))
    >>> float(chips.volume_flow(("wood", "char"), np.array([[0.001, 0.002]]))[0])
    3e-05
    >>> import dataclasses
    >>> charred = dataclasses.replace(chips, shrinkage=0.3)
    >>> round(float(charred.volume_flow(("wood", "char"), np.array([[0.0, 0.002]]))[0]), 12)
    2.1e-05
    >>> round(float(charred.bed_density(("wood", "char"), np.array([[0.0, 0.002]]))[0]), 2)
    95.24
    """

    radius: float
    omega: float
    slope: float
    repose: float
    density: float
    dam_height: float
    volume_law: str = "bulk"
    volume_flow0: float = 0.0
    feed: tuple = ()
    shrinkage: float = 0.0

    def __post_init__(self):
        check_positive("kiln.drum.radius", self.radius, "m")
        check_positive("operation.speed", self.omega, "rad/s")
        check_positive("material.bulk_density", self.density, "kg/m3")
        self._check_volume_law()
        if not 0.0 < self.dam_height < self.radius:
            raise InputError(
                "transport.dam_height",
                self.dam_height,
                f"in (0, {self.radius:.4g}) m (the bed depth inside the reacting solve starts "
                "at a discharge dam)",
            )
        if not 0.0 < self.slope < self.repose < np.pi / 2:
            raise InputError("kiln.slope", self.slope, "in (0, the angle of repose)")

    def _check_volume_law(self):
        if self.volume_law not in VOLUME_LAWS:
            raise InputError("transport.volume", self.volume_law, " or ".join(VOLUME_LAWS))
        if not 0.0 <= self.shrinkage < 1.0:
            raise InputError("transport.shrinkage", self.shrinkage, "in [0, 1)")
        if self.volume_law == "bulk":
            if self.shrinkage != 0.0:
                raise InputError(
                    "transport.shrinkage",
                    self.shrinkage,
                    "0 with transport.volume: bulk (a shrinkage is a share of the fresh feed's "
                    "volume: transport.volume: fresh_feed)",
                )
            return
        check_positive("transport.volume (the fresh feed's volume flow)", self.volume_flow0, "m3/s")
        flows = [q for _, q in self.feed]
        if self.shrinkage > 0.0 and (
            not flows or not all(np.isfinite(q) and q >= 0.0 for q in flows) or sum(flows) <= 0
        ):
            raise InputError(
                "operation.feed",
                self.feed,
                "the fed species and their flows (kg/s, > 0 in all) with a transport.shrinkage",
            )

    def volume_flow(self, names, qb):
        """Volumetric flow of the bed (m3/s) from its species flows ``qb`` (kg/s, the bed
        species ``names`` on the last axis), by the volume law (module docstring)."""
        if self.volume_law == "bulk":
            return qb.sum(-1) / self.density
        qb = np.asarray(qb, dtype=float)
        if self.shrinkage == 0.0:
            return np.full(qb.shape[:-1], self.volume_flow0)
        fed = dict(self.feed)
        total = sum(fed.values())
        mask = np.array([n in fed for n in names], dtype=float)
        conversion = 1.0 - (np.maximum(qb, 0.0) * mask).sum(-1) / total
        return self.volume_flow0 * (1.0 - self.shrinkage * np.clip(conversion, 0.0, 1.0))

    def bed_density(self, names, qb):
        """Bulk density of the bed (kg/m3) at the species flows ``qb`` (kg/s): ``density``
        with the bulk law, else the mass flow over the volume flow."""
        if self.volume_law == "bulk":
            return self.density
        q = np.maximum(qb, 0.0)
        return q.sum(-1) / np.maximum(self.volume_flow(names, q), 1e-300)

    def slope_of_depth(self, h, q):
        """dh/dz (-) at depth ``h`` (m) and volumetric flow ``q`` (m3/s), z from the feed."""
        R = self.radius
        k = 1.5 * q * np.tan(self.repose) / (self.omega * R**3)
        c = np.tan(self.slope) / np.cos(self.repose)
        u = np.clip(h / R, 1e-6, 1.999)
        return c - k * (u * (2.0 - u)) ** -1.5

    def residual(self, h_faces, q_faces, dz):
        """Residuals (m) of the cells between ``h_faces`` (..., n+1) with flows ``q_faces``."""
        hm = 0.5 * (h_faces[..., 1:] + h_faces[..., :-1])
        qm = 0.5 * (q_faces[..., 1:] + q_faces[..., :-1])
        return h_faces[..., 1:] - h_faces[..., :-1] - dz * self.slope_of_depth(hm, qm)

    def geometry(self, grid, h_cells):
        """``grid`` with the cross-section of each cell at the cell-mean depth ``h_cells``."""
        R = self.radius
        cs = CrossSection.from_depth(np.clip(h_cells, 1e-6 * R, 1.999 * R), R)
        return dataclasses.replace(grid, fill=cs.fill, **section_fields(cs, R))

    def initial_depth(self, length, z_nodes, mass_flow):
        """Depth (m) at the faces for a constant ``mass_flow`` (kg/s): the transport model's
        Kramers profile, the Newton solve's starting point."""
        from rotarykiln.transport.kramers import kramers_profile

        p = kramers_profile(
            mass_flow,
            length=length,
            radius=self.radius,
            speed=self.omega,
            slope=self.slope,
            repose=self.repose,
            density=self.density,
            dam_height=self.dam_height,
            n_points=max(401, len(z_nodes)),
        )
        return np.interp(z_nodes, np.asarray(p.z), np.asarray(p.depth))
