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
the bed hold-up :math:`\rho_b A_{bed}` that the rate laws see. The bulk density is constant
along the kiln (a bed that shrinks as it reacts keeps its density: stated assumption).

References
----------
H. Kramers, P. Croockewit, Chem. Eng. Sci. 1 (1952) 259; W.C. Saeman, Chem. Eng. Prog. 47
(1951) 508; Scott (1986) eq. 2.10.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import InputError, check_positive
from rotarykiln.geometry import CrossSection
from rotarykiln.kiln.grid import section_fields

__all__ = ["KramersBed"]


@dataclass(frozen=True)
class KramersBed:
    """Kramers bed-depth law of a kiln, for its Newton system (SI units).

    ``radius`` (m), ``omega`` (rad/s), ``slope`` (rad), ``repose`` (rad, dynamic angle of
    repose), ``density`` (kg/m3, bulk), ``dam_height`` (m, > 0 at the discharge).

    Examples
    --------
    >>> bed = KramersBed(0.2, 0.157, 0.0175, 0.61, 1500.0, 0.03)
    >>> h = np.array([0.04, 0.05]); q = np.array([1e-5, 1e-5])
    >>> bed.residual(h, q, 0.1).shape
    (1,)
    """

    radius: float
    omega: float
    slope: float
    repose: float
    density: float
    dam_height: float

    def __post_init__(self):
        check_positive("kiln.drum.radius", self.radius, "m")
        check_positive("operation.speed", self.omega, "rad/s")
        check_positive("material.bulk_density", self.density, "kg/m3")
        if not 0.0 < self.dam_height < self.radius:
            raise InputError(
                "transport.dam_height",
                self.dam_height,
                f"in (0, {self.radius:.4g}) m (the bed depth inside the reacting solve starts "
                "at a discharge dam)",
            )
        if not 0.0 < self.slope < self.repose < np.pi / 2:
            raise InputError("kiln.slope", self.slope, "in (0, the angle of repose)")

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
