r"""Bulk solids: density, particle size, specific heat :math:`c_p(T)`, conductivity, emissivity.

**Specific heat.** The molar heat capacity is given in pieces (:class:`CpSegment`), each with
its own validity range :math:`[T_{low}, T_{high}]` and one of three forms:

- ``shomate`` (NIST-JANAF / NIST WebBook), :math:`t = T/1000`:
  :math:`c_p = A + Bt + Ct^2 + Dt^3 + E/t^2`, J/(mol K);
- ``nasa7`` (NASA Glenn 7-coefficient polynomials, McBride et al. 1993, as in Cantera):
  :math:`c_p/R = a_1 + a_2T + a_3T^2 + a_4T^3 + a_5T^4`;
- ``maier_kelley``: :math:`c_p = a + bT + c/T^2`, J/(mol K);

converted to J/(kg K) with the molar mass :math:`M`; or a constant :math:`c_p` in J/(kg K).
Consecutive pieces meet at a boundary; a boundary may be a phase transition
(:class:`PhaseTransition`) with a latent heat :math:`L` (J/mol), e.g. alpha -> beta quartz at
847 K. The phase enthalpies :math:`h_k(T)` are the exact antiderivatives of the pieces, with
constants chosen so that :math:`h_{k+1}(T_{tr}) - h_k(T_{tr}) = L` and :math:`h(298.15\,K) = 0`.

**The transition is spread over a small window** :math:`[T_{tr} - w/2, T_{tr} + w/2]`
(``width`` :math:`w`, 10 K by default) by a smooth phase fraction
:math:`s = 3x^2 - 2x^3`, :math:`x = (T - T_{tr} + w/2)/w` clipped to [0, 1]:

.. math:: h(T) = (1 - s)\,h_k(T) + s\,h_{k+1}(T), \qquad
          c_p(T) = \frac{dh}{dT} = (1 - s)\,c_{p,k} + s\,c_{p,k+1} + s'\,(h_{k+1} - h_k)

Why this and not a sharp step or a logistic: a sharp latent heat makes :math:`h(T)` jump and
the kiln residual discontinuous, so Newton can cycle between the phases of a cell near 847 K;
a logistic (tanh) step never reaches 0 or 1, so :math:`h(298.15\,K)` would not be exactly 0 and
the enthalpy outside the window would differ from the tabulated one. The cubic step has compact
support: outside the window :math:`h` equals the sharp-transition enthalpy exactly, inside it
:math:`h` is continuously differentiable and :math:`c_p` is continuous (the latent heat appears
as a bump of peak :math:`1.5L/w` in :meth:`Solid.cp`; ``Solid.cp(T, latent=False)`` leaves the
bump out: the phases' values blended by the phase fraction, :math:`(1 - s)\,c_{p,k} +
s\,c_{p,k+1}`, continuous too, so that no closure that uses it makes the kiln residual jump).
10 K is narrow against the bed heating in a kiln cell and comparable to the spread of the real
(lambda-type) quartz transition.
A boundary without a transition switches piece sharply (the pieces of a fit match there).

:meth:`Solid.enthalpy` is thus the exact integral of :meth:`Solid.cp`, which keeps kiln energy
balances consistent. Evaluation is vectorised (a loop over the 2-3 pieces only). Outside the
fitted range the pieces are extrapolated; the solvers call :meth:`Solid.check_range` once on the
converged state, which warns (:class:`~rotarykiln.errors.OutOfRangeWarning`).

References
----------
M.W. Chase Jr., NIST-JANAF Thermochemical Tables, 4th ed., J. Phys. Chem. Ref. Data Monograph 9
(1998); NIST Chemistry WebBook, SRD 69 (Shomate coefficients). B.J. McBride, S. Gordon,
M.A. Reno, NASA TM-4513 (1993) (NASA 7-coefficient polynomials). Sources of each value in
``solids.yaml``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import InputError, check_positive, check_range, warn_out_of_range
from rotarykiln.materials._library import library_entry, load_library

__all__ = ["CpSegment", "PhaseTransition", "Solid", "load_solid", "solid_names"]

T0 = 298.15
R_UNIVERSAL = 8.314462618  # J/(mol K)
DEFAULT_TRANSITION_WIDTH = 10.0  # K
_N_COEFFS = {"shomate": (5, 8), "nasa7": (5, 7), "maier_kelley": (3,)}


@dataclass(frozen=True)
class CpSegment:
    """One piece of a molar heat capacity, valid on [``t_low``, ``t_high``] (K).

    Attributes: ``form`` (``"shomate"``, ``"nasa7"`` or ``"maier_kelley"``, see the module
    docstring), ``coefficients`` (Shomate A-E in J/(mol K) with t = T/1000, F-H ignored; NASA
    a1-a5 of cp/R, a6-a7 ignored; Maier-Kelley a, b, c in J/(mol K), J/(mol K2), J K/mol),
    ``t_low``, ``t_high`` (K), ``phase`` (a label, e.g. ``"alpha quartz"``).
    """

    form: str
    coefficients: tuple[float, ...]
    t_low: float
    t_high: float
    phase: str = ""

    def __post_init__(self):
        if self.form not in _N_COEFFS:
            raise InputError("cp_segments.form", self.form, "one of " + ", ".join(_N_COEFFS))
        counts = _N_COEFFS[self.form]
        if len(self.coefficients) not in counts:
            raise InputError(
                f"cp_segments.{self.form}.coefficients",
                len(self.coefficients),
                " or ".join(str(c) for c in counts) + " values",
            )
        if not (0.0 <= self.t_low < self.t_high):
            raise InputError(
                "cp_segments.range", (self.t_low, self.t_high), "T_low >= 0 K and T_low < T_high"
            )

    def cp_molar(self, T):
        """Molar heat capacity of this piece, J/(mol K), at ``T`` (K, array)."""
        c = self.coefficients
        if self.form == "shomate":
            t = T / 1000.0
            return c[0] + t * (c[1] + t * (c[2] + t * c[3])) + c[4] / (t * t)
        if self.form == "nasa7":
            return R_UNIVERSAL * (c[0] + T * (c[1] + T * (c[2] + T * (c[3] + T * c[4]))))
        return c[0] + c[1] * T + c[2] / (T * T)

    def antiderivative(self, T):
        """An antiderivative of :meth:`cp_molar`, J/mol (arbitrary constant), at ``T`` (K)."""
        c = self.coefficients
        if self.form == "shomate":
            t = T / 1000.0
            poly = t * (c[0] + t * (c[1] / 2 + t * (c[2] / 3 + t * c[3] / 4)))
            return 1000.0 * (poly - c[4] / t)
        if self.form == "nasa7":
            poly = c[0] + T * (c[1] / 2 + T * (c[2] / 3 + T * (c[3] / 4 + T * c[4] / 5)))
            return R_UNIVERSAL * T * poly
        return T * (c[0] + 0.5 * c[1] * T) - c[2] / T


@dataclass(frozen=True)
class PhaseTransition:
    """A phase transition at a boundary between two :class:`CpSegment` pieces.

    Attributes: ``temperature`` (K, must equal the boundary), ``enthalpy`` (J/mol, latent heat
    taken up on heating), ``width`` (K, the window over which it is released, see the module
    docstring; 0 for a sharp step).
    """

    temperature: float
    enthalpy: float
    width: float = DEFAULT_TRANSITION_WIDTH


@dataclass(frozen=True)
class Solid:
    """A bulk solid (SI units).

    Attributes: ``name``; ``bulk_density`` (kg/m3); ``particle_density`` (kg/m3);
    ``particle_diameter`` (m); ``emissivity`` (-); ``cp_coeffs`` (a, b, c) of a Maier-Kelley
    form with no stated range, with ``molar_mass`` (kg/mol), or ``cp_const`` (J/(kg K));
    ``bed_conductivity`` (W/(m K), measured bulk value, or None to compute it from
    ``solid_conductivity`` with a bed conductivity model); ``solid_conductivity`` (W/(m K));
    ``angle_of_repose`` (deg); ``cp_segments`` (tuple of :class:`CpSegment`, contiguous, with
    ``molar_mass``; takes precedence over ``cp_coeffs`` and ``cp_const``); ``transitions``
    (tuple of :class:`PhaseTransition` at segment boundaries); ``cp_source`` (str, cited in
    range warnings).
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
    cp_segments: tuple[CpSegment, ...] | None = None
    transitions: tuple[PhaseTransition, ...] = ()
    cp_source: str = ""

    def __post_init__(self):
        check_positive(f"{self.name}.bulk_density", self.bulk_density, "kg/m3")
        check_positive(f"{self.name}.particle_density", self.particle_density, "kg/m3")
        check_positive(f"{self.name}.particle_diameter", self.particle_diameter, "m")
        check_range(f"{self.name}.emissivity", self.emissivity, 0.0, 1.0, closed_high=True)
        segs = self.cp_segments
        if segs is None and self.cp_coeffs is not None:
            segs = (CpSegment("maier_kelley", tuple(self.cp_coeffs), 0.0, np.inf),)
        if segs is None:
            if self.cp_const is None:
                raise InputError(
                    f"{self.name}.cp", None, "given (cp, cp_maier_kelley or cp_segments)"
                )
            check_positive(f"{self.name}.cp", self.cp_const, "J/(kg K)")
            object.__setattr__(self, "_pieces", None)
            return
        if len(segs) == 0:
            raise InputError(f"{self.name}.cp_segments", "[]", "at least one segment")
        check_positive(f"{self.name}.molar_mass", self.molar_mass, "kg/mol")
        object.__setattr__(self, "_pieces", self._build_pieces(tuple(segs)))

    def _build_pieces(self, segs):
        """Boundaries (T, L, w) and enthalpy constants of the pieces, h(T0) = 0."""
        for a, b in zip(segs[:-1], segs[1:], strict=True):
            if a.t_high != b.t_low:
                raise InputError(
                    f"{self.name}.cp_segments",
                    f"[{a.t_low:g}, {a.t_high:g}] then [{b.t_low:g}, {b.t_high:g}] K",
                    "contiguous (each range starts where the previous one ends)",
                )
        given = {float(tr.temperature): tr for tr in self.transitions}
        bounds = []
        for a in segs[:-1]:
            tr = given.pop(float(a.t_high), None)
            if tr is None:
                bounds.append((a.t_high, 0.0, 0.0))
                continue
            if not (np.isfinite(tr.enthalpy) and 0.0 <= tr.width):
                raise InputError(
                    f"{self.name}.transitions", f"L={tr.enthalpy}, width={tr.width}", "finite, >= 0"
                )
            bounds.append((a.t_high, float(tr.enthalpy), float(tr.width)))
        if given:
            raise InputError(
                f"{self.name}.transitions.temperature",
                ", ".join(f"{t:g} K" for t in given),
                "a boundary between two cp segments",
            )
        for k, seg in enumerate(segs):
            half_low = bounds[k - 1][2] / 2 if k > 0 else 0.0
            half_high = bounds[k][2] / 2 if k < len(bounds) else 0.0
            if half_low + half_high >= seg.t_high - seg.t_low:
                raise InputError(
                    f"{self.name}.transitions.width",
                    f"{2 * max(half_low, half_high):g} K",
                    f"narrower than the segment [{seg.t_low:g}, {seg.t_high:g}] K",
                )
        offsets = [0.0]
        for k, (tb, latent, _) in enumerate(bounds):
            h_below = float(segs[k].antiderivative(tb)) + offsets[k]
            offsets.append(h_below + latent - float(segs[k + 1].antiderivative(tb)))
        pieces = (segs, tuple(bounds), tuple(offsets))
        _, h_ref = self._molar(np.asarray(T0), pieces, latent=True)
        return (segs, tuple(bounds), tuple(o - float(h_ref) for o in offsets))

    @staticmethod
    def _molar(T, pieces, latent, with_cp=True):
        """Molar c_p (J/(mol K)) and h (J/mol) on an array ``T`` (K): one pass per piece.
        Without ``with_cp`` only h is computed (c_p returned as None); the c_p without the
        latent bump (``latent`` False) only c_p (h returned as None)."""
        segs, bounds, offsets = pieces
        cp = segs[0].cp_molar(T) if with_cp else None
        with_h = latent or not with_cp
        h = segs[0].antiderivative(T) + offsets[0] if with_h else None
        if not bounds or T.size == 0:
            return cp, h
        t_max = np.fmax.reduce(T, axis=None)  # ignores NaN: other elements stay right
        for k, (tb, _, w) in enumerate(bounds):
            if not t_max >= tb - 0.5 * w:
                break
            cp_b = segs[k + 1].cp_molar(T) if with_cp else None
            h_b = segs[k + 1].antiderivative(T) + offsets[k + 1] if with_h else None
            if w > 0.0:
                x = np.minimum(np.maximum((T - (tb - 0.5 * w)) / w, 0.0), 1.0)  # clipped
                s = x * x * (3.0 - 2.0 * x)
                if with_h:
                    dh = h_b - h
                if with_cp:
                    cp_mixed = cp + s * (cp_b - cp)  # the two phases' c_p by phase fraction
                    if latent:
                        cp = cp_mixed + (6.0 / w) * x * (1.0 - x) * dh
                    else:
                        cp = cp_mixed  # continuous: a jump here made the kiln residual jump
                if with_h:
                    h = h + s * dh
            else:
                above = T >= tb
                if with_cp:
                    cp = np.where(above, cp_b, cp)
                if with_h:
                    h = np.where(above, h_b, h)
        return cp, h

    @property
    def void_fraction(self) -> float:
        """Bed void fraction :math:`1 - \\rho_b/\\rho_p`, -."""
        return 1.0 - self.bulk_density / self.particle_density

    @property
    def temperature_range(self) -> tuple[float, float] | None:
        """Fitted range of :meth:`cp`, (K, K); None for a constant cp (no stated range)."""
        if self._pieces is None:
            return None
        segs = self._pieces[0]
        return (float(segs[0].t_low), float(segs[-1].t_high))

    def check_range(self, T) -> bool:
        """Warn once if any temperature lies outside the fitted range of :meth:`cp`.

        Called by the solvers on the converged bed temperatures (not inside Newton).

        Parameters
        ----------
        T : float or array, K
            Temperatures at which the solid's properties were used.

        Returns
        -------
        bool
            True when an :class:`~rotarykiln.errors.OutOfRangeWarning` was issued (it shows
            the span outside the range).

        Examples
        --------
        >>> import warnings
        >>> with warnings.catch_warnings(record=True) as w:
        ...     warnings.simplefilter("always")
        ...     load_solid("sand").check_range([300.0, 2100.0, 2200.0])
        True
        >>> print(str(w[0].message).split(" is ")[0])
        sand temperature [K] = 2100 to 2200

        References
        ----------
        The range of each fit as stated by its source (``solids.yaml``).
        """
        rng = self.temperature_range
        if rng is None or (rng[0] <= 0.0 and rng[1] == np.inf):
            return False
        source = f"the c_p fit of {self.name}" + (f" ({self.cp_source})" if self.cp_source else "")
        return warn_out_of_range(f"{self.name} temperature [K]", T, rng[0], rng[1], source)

    def phase_cp(self, T):
        """Specific heat without a transition's latent bump, J/(kg K): the stable phase's, and
        inside a transition window the phases' blended by the phase fraction (continuous). The
        heat capacity the covered-wall contact (penetration) models take.

        Examples
        --------
        >>> s = load_solid("sand")
        >>> round(float(s.phase_cp(847.0)) / float(s.cp(847.0)), 2)  # the latent bump is left out
        0.4
        """
        return self.cp(T, latent=False)

    def cp(self, T, *, latent=True, check=False):
        """Specific heat, J/(kg K), at ``T`` (K): the derivative of :meth:`enthalpy`.

        Parameters
        ----------
        T : float or array, K
            Temperature, any shape (e.g. ``(batch, n_cells)``).
        latent : bool
            True (default): the apparent specific heat dh/dT, which includes the latent heat
            of a phase transition spread over its window. False: the specific heat of the
            stable phase as tabulated (jumps at the transition temperature).
        check : bool
            Also call :meth:`check_range` (off in solver loops).

        Returns
        -------
        ndarray, J/(kg K)
            Same shape as ``T``.

        Examples
        --------
        >>> sand = load_solid("sand")
        >>> round(float(sand.cp(298.15)), 0)
        742.0
        >>> [round(float(v), 1) for v in sand.cp([800.0, 900.0, 1200.0]) * 0.060084]
        [73.7, 67.9, 71.0]

        References
        ----------
        Chase (1998), NIST-JANAF tables; McBride et al. (1993); see ``solids.yaml``.
        """
        T = np.asarray(T, dtype=float)
        if check:
            self.check_range(T)
        if self._pieces is None:
            return np.full_like(T, self.cp_const)
        cp, _ = self._molar(T, self._pieces, latent)
        return cp / self.molar_mass

    def enthalpy(self, T, *, check=False):
        """Sensible enthalpy relative to 298.15 K, J/kg (exact integral of :meth:`cp`).

        Includes the latent heat of the phase transitions below ``T``.

        Parameters
        ----------
        T : float or array, K
            Temperature, any shape.
        check : bool
            Also call :meth:`check_range` (off in solver loops).

        Returns
        -------
        ndarray, J/kg
            Same shape as ``T``; 0 at 298.15 K.

        Examples
        --------
        >>> s = load_solid("sand")
        >>> abs(float(s.enthalpy(400.0) - s.enthalpy(399.0) - s.cp(399.5))) < 1e-2
        True
        >>> float(s.enthalpy(298.15))
        0.0

        References
        ----------
        Chase (1998), NIST-JANAF tables; see ``solids.yaml``.
        """
        T = np.asarray(T, dtype=float)
        if check:
            self.check_range(T)
        if self._pieces is None:
            return self.cp_const * (T - T0)
        _, h = self._molar(T, self._pieces, True, with_cp=False)
        return h / self.molar_mass


def solid_names() -> list[str]:
    """Names of the solids in the library ``solids.yaml``."""
    return sorted(load_library("solids.yaml"))


def _segments_from_yaml(name: str, items) -> tuple[CpSegment, ...]:
    segs = []
    for i, item in enumerate(items):
        try:
            t_low, t_high = (float(v) for v in item["range"])
            segs.append(
                CpSegment(
                    form=str(item["form"]),
                    coefficients=tuple(float(v) for v in item["coefficients"]),
                    t_low=t_low,
                    t_high=t_high,
                    phase=str(item.get("phase", "")),
                )
            )
        except (KeyError, TypeError, ValueError) as exc:
            raise InputError(
                f"{name}.cp_segments[{i}]", item, "a mapping with form, range and coefficients"
            ) from exc
    return tuple(segs)


def load_solid(name: str, **overrides) -> Solid:
    """A solid from the library, with optional overrides of any attribute.

    Overriding ``cp_const``, ``cp_coeffs`` or ``cp_segments`` replaces the library's c_p.

    Examples
    --------
    >>> load_solid("limestone").bulk_density
    1680.0
    >>> load_solid("sand", cp_const=800.0).cp(1200.0)
    array(800.)
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
        cp_source=str(e.get("cp_source", "")),
    )
    if {"cp_const", "cp_coeffs", "cp_segments"} & overrides.keys():
        kw["molar_mass"] = e.get("molar_mass")
    elif "cp_segments" in e:
        kw["cp_segments"] = _segments_from_yaml(name, e["cp_segments"])
        kw["transitions"] = tuple(
            PhaseTransition(
                float(t["temperature"]),
                float(t["enthalpy"]),
                float(t.get("width", DEFAULT_TRANSITION_WIDTH)),
            )
            for t in e.get("transitions", ())
        )
        kw["molar_mass"] = e["molar_mass"]
    elif "cp_maier_kelley" in e:
        coeffs = tuple(float(v) for v in e["cp_maier_kelley"])
        if "cp_range" in e:
            t_low, t_high = (float(v) for v in e["cp_range"])
            kw["cp_segments"] = (CpSegment("maier_kelley", coeffs, t_low, t_high),)
        else:
            kw["cp_coeffs"] = coeffs
        kw["molar_mass"] = e["molar_mass"]
    else:
        kw["cp_const"] = float(e["cp"])
    kw.update(overrides)
    return Solid(**kw)
