r"""Bulk solids: density, particle size, specific heat :math:`c_p(T)`, conductivity, emissivity.

The specific heat is either constant or of the Maier-Kelley form (per mole, converted with the
molar mass :math:`M`):

.. math:: c_p(T) = \frac{a + bT + c/T^2}{M}, \qquad
          h(T) = \frac{a(T - T_0) + \tfrac{b}{2}(T^2 - T_0^2) - c(1/T - 1/T_0)}{M}

with :math:`h(T_0 = 298.15\,K) = 0`; :meth:`Solid.enthalpy` is the exact integral of
:meth:`Solid.cp`, which keeps kiln energy balances consistent.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import check_positive, check_range
from rotarykiln.materials._library import library_entry, load_library

__all__ = ["Solid", "load_solid", "solid_names"]

T0 = 298.15


@dataclass(frozen=True)
class Solid:
    """A bulk solid (SI units).

    Attributes: ``name``; ``bulk_density`` (kg/m3); ``particle_density`` (kg/m3);
    ``particle_diameter`` (m); ``emissivity`` (-); ``cp_coeffs`` (a, b, c) of the Maier-Kelley
    form with ``molar_mass`` (kg/mol), or ``cp_const`` (J/(kg K)); ``bed_conductivity``
    (W/(m K), measured bulk value, or None to compute it from ``solid_conductivity`` with a bed
    conductivity model); ``solid_conductivity`` (W/(m K)); ``angle_of_repose`` (deg).
    """

    name: str
    bulk_density: float
    particle_density: float
    particle_diameter: float
    emissivity: float
    cp_coeffs: tuple[float, float, float] | None = None
    molar_mass: float | None = None
    cp_const: float | None = None
    bed_conductivity: float | None = None
    solid_conductivity: float = 1.0
    angle_of_repose: float = 35.0

    def __post_init__(self):
        check_positive(f"{self.name}.bulk_density", self.bulk_density, "kg/m3")
        check_positive(f"{self.name}.particle_density", self.particle_density, "kg/m3")
        check_positive(f"{self.name}.particle_diameter", self.particle_diameter, "m")
        check_range(f"{self.name}.emissivity", self.emissivity, 0.0, 1.0, closed_high=True)
        if self.cp_coeffs is None and self.cp_const is None:
            from rotarykiln.errors import InputError

            raise InputError(f"{self.name}.cp", None, "given (cp or cp_maier_kelley)")

    @property
    def void_fraction(self) -> float:
        """Bed void fraction :math:`1 - \\rho_b/\\rho_p`, -."""
        return 1.0 - self.bulk_density / self.particle_density

    def cp(self, T):
        """Specific heat, J/(kg K), at ``T`` (K).

        Examples
        --------
        >>> round(float(load_solid("sand").cp(298.15)), 0)
        740.0
        """
        T = np.asarray(T, dtype=float)
        if self.cp_coeffs is None:
            return np.full_like(T, self.cp_const)
        a, b, c = self.cp_coeffs
        return (a + b * T + c / T**2) / self.molar_mass

    def enthalpy(self, T):
        """Sensible enthalpy relative to 298.15 K, J/kg (exact integral of :meth:`cp`).

        Examples
        --------
        >>> s = load_solid("sand")
        >>> abs(float(s.enthalpy(400.0) - s.enthalpy(399.0) - s.cp(399.5))) < 1e-2
        True
        """
        T = np.asarray(T, dtype=float)
        if self.cp_coeffs is None:
            return self.cp_const * (T - T0)
        a, b, c = self.cp_coeffs
        return (a * (T - T0) + 0.5 * b * (T**2 - T0**2) - c * (1.0 / T - 1.0 / T0)) / (
            self.molar_mass
        )


def solid_names() -> list[str]:
    """Names of the solids in the library ``solids.yaml``."""
    return sorted(load_library("solids.yaml"))


def load_solid(name: str, **overrides) -> Solid:
    """A solid from the library, with optional overrides of any attribute.

    Examples
    --------
    >>> load_solid("limestone").bulk_density
    1680.0
    """
    e = library_entry("solids.yaml", name, "material.solid")
    kw = dict(
        name=name,
        bulk_density=e["bulk_density"],
        particle_density=e["particle_density"],
        particle_diameter=e["particle_diameter"],
        emissivity=e["emissivity"],
        bed_conductivity=e.get("bed_conductivity"),
        solid_conductivity=e.get("solid_conductivity", 1.0),
        angle_of_repose=e.get("angle_of_repose", 35.0),
    )
    if "cp_maier_kelley" in e:
        kw["cp_coeffs"] = tuple(float(v) for v in e["cp_maier_kelley"])
        kw["molar_mass"] = e["molar_mass"]
    else:
        kw["cp_const"] = float(e["cp"])
    kw.update(overrides)
    return Solid(**kw)
