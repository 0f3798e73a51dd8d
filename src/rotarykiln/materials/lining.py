r"""Lining and shell materials with temperature-dependent conductivity, and lining layers.

Conductivity is a quadratic :math:`k(T) = k_0 + k_1 T + k_2 T^2`. Steady radial conduction
through a cylindrical layer with :math:`k(T)` is solved exactly by the Kirchhoff transform:
with :math:`K(T) = \int k\,dT`,

.. math:: q' = \frac{2\pi\,[K(T_i) - K(T_o)]}{\ln(r_o/r_i)} \quad [W/m].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import InputError, check_positive, check_range
from rotarykiln.materials._library import library_entry, load_library

__all__ = ["LiningMaterial", "Layer", "load_lining_material", "lining_material_names"]


@dataclass(frozen=True)
class LiningMaterial:
    """A lining (refractory, insulation, steel) material.

    Attributes: ``name``; ``k_coeffs`` (k0 W/(m K), k1 W/(m K2), k2 W/(m K3)); ``emissivity``
    (-, of its surface); ``t_max`` (K, service limit).
    """

    name: str
    k_coeffs: tuple[float, float, float]
    emissivity: float = 0.85
    t_max: float = 1700.0

    def __post_init__(self):
        check_range(f"{self.name}.emissivity", self.emissivity, 0.0, 1.0, closed_high=True)
        k = self.conductivity(np.array([300.0, self.t_max]))
        check_positive(f"{self.name}.k", k, "W/(m K)")

    def conductivity(self, T):
        """k(T), W/(m K).

        Examples
        --------
        >>> round(float(load_lining_material("carbon_steel").conductivity(300.0)), 1)
        52.5
        """
        k0, k1, k2 = self.k_coeffs
        T = np.asarray(T, dtype=float)
        return k0 + k1 * T + k2 * T**2

    def conductivity_integral(self, T):
        """Kirchhoff potential :math:`K(T) = \\int_0^T k\\,dT`, W/m."""
        k0, k1, k2 = self.k_coeffs
        T = np.asarray(T, dtype=float)
        return T * (k0 + T * (k1 / 2.0 + T * k2 / 3.0))


@dataclass(frozen=True)
class Layer:
    """One lining layer: a material and a thickness (m), optionally absent on axial stretches
    or with a thickness that varies along the kiln.

    ``absent`` is a tuple of ``(z_start, z_end)`` ranges (m from the solids inlet) where the
    layer is missing (e.g. an uninsulated stretch of shell). ``profile``: ``(z, thickness)``,
    two tuples of positions (m, increasing) and thicknesses (m, >= 0), linear between them and
    constant beyond (e.g. a coating built up in the burning zone); ``thickness`` is then the
    largest of them. Where a profile gives 0 the layer is absent.
    """

    material: LiningMaterial
    thickness: float
    absent: tuple[tuple[float, float], ...] = ()
    profile: tuple[tuple[float, ...], tuple[float, ...]] | None = None

    def __post_init__(self):
        name = f"lining.{self.material.name}"
        check_positive(f"{name}.thickness", self.thickness, "m")
        if self.profile is not None:
            z, t = (np.asarray(a, dtype=float) for a in self.profile)
            if z.ndim != 1 or z.shape != t.shape or z.size < 1:
                raise InputError(f"{name}.profile", self.profile, "positions and thicknesses")
            if not (np.all(np.isfinite(z)) and np.all(np.diff(z) > 0)):
                raise InputError(f"{name}.profile", z.tolist(), "increasing positions (m)")
            if not (np.all(np.isfinite(t)) and np.all(t >= 0) and t.max() > 0):
                raise InputError(f"{name}.profile", t.tolist(), "thicknesses >= 0 m, not all 0")
        for a, b in self.absent:
            if not b > a:
                raise InputError(
                    f"lining.{self.material.name}.absent", (a, b), "a range (start < end)"
                )

    def present(self, z):
        """Boolean mask: is the layer present at positions ``z`` (m)?"""
        z = np.asarray(z, dtype=float)
        mask = np.ones(z.shape, dtype=bool)
        for a, b in self.absent:
            mask &= ~((z >= a) & (z <= b))
        if self.profile is not None:
            mask &= self.thickness_at(z) > 0
        return mask

    def thickness_at(self, z):
        """Thickness (m) at positions ``z`` (m): the constant one, or the profile's.

        Examples
        --------
        >>> coating = Layer(LiningMaterial("coating", (1.0, 0.0, 0.0), 0.9, 1800.0), 0.2,
        ...                 profile=((20.0, 30.0, 40.0), (0.0, 0.2, 0.0)))
        >>> coating.thickness_at([10.0, 25.0, 30.0]).tolist()
        [0.0, 0.1, 0.2]
        """
        z = np.asarray(z, dtype=float)
        if self.profile is None:
            return np.full(z.shape, self.thickness)
        zp, tp = (np.asarray(a, dtype=float) for a in self.profile)
        return np.interp(z, zp, tp)

    def divided(self, m: int) -> Layer:
        """One of ``m`` equal sub-layers of the layer (its profile divided too)."""
        profile = None
        if self.profile is not None:
            profile = (self.profile[0], tuple(float(t) / m for t in self.profile[1]))
        return Layer(self.material, self.thickness / m, self.absent, profile)


def lining_material_names() -> list[str]:
    """Names of the lining materials in ``refractories.yaml``."""
    return sorted(load_library("refractories.yaml"))


def load_lining_material(name: str) -> LiningMaterial:
    """A lining material from the library.

    Examples
    --------
    >>> load_lining_material("fireclay_brick").emissivity
    0.85
    """
    e = library_entry("refractories.yaml", name, "lining.material")
    return LiningMaterial(
        name=name,
        k_coeffs=tuple(float(v) for v in e["k"]),
        emissivity=float(e.get("emissivity", 0.85)),
        t_max=float(e.get("t_max", 1700.0)),
    )
