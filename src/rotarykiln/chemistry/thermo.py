r"""Temperature-dependent heat capacity of a species: NASA 7-coefficient, Shomate, polynomial.

A user species (:func:`rotarykiln.chemistry.species.load_species`) may give its specific heat as
a function of temperature instead of a constant mean. Three forms are accepted, each with the
temperature range over which it was fitted (``T_range``, K); the form is checked at load to give
a positive :math:`c_p` over that whole range.

- NASA 7-coefficient polynomials (McBride, Gordon & Reno 1993), molar and dimensionless,
  one or two ranges split at ``T_mid``:

  .. math:: \frac{c_p}{R} = a_1 + a_2 T + a_3 T^2 + a_4 T^3 + a_5 T^4

- Shomate (NIST Chemistry WebBook), with :math:`t = T/1000`:

  .. math:: c_p = A + B t + C t^2 + D t^3 + E/t^2

  in J/(mol K) (``basis: molar``, NIST's form) or J/(kg K) (``basis: mass``, handy for
  lumped species fitted per kg, such as wood, char and tar);

- a power polynomial in T per kg, :math:`c_p = \sum_k c_k T^k` J/(kg K) (``polynomial``), the
  form of most biomass property correlations.

Outside ``T_range`` every form is continued at its end value of :math:`c_p` (constant), so an
extrapolation can never turn :math:`c_p` negative; the enthalpy stays continuous.

All functions return specific (per kg) values: :math:`c_p` in J/(kg K) and the sensible enthalpy
:math:`h(T) - h(298.15\,K)` in J/kg, the form the kiln balances carry.

References
----------
B.J. McBride, S. Gordon, M.A. Reno, NASA TM-4513 (1993) (7-coefficient polynomials);
M.W. Chase, NIST-JANAF Thermochemical Tables, 4th ed. (1998), and the NIST Chemistry WebBook
(Shomate equation).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from rotarykiln.errors import InputError

__all__ = ["SpeciesThermo", "thermo_from_dict", "R_GAS", "T_REF"]

R_GAS = 8.314462618  # J/(mol K)
T_REF = 298.15  # K
#: Samples per range on which a c_p form is checked positive at load.
_CHECK_POINTS = 401


@dataclass(frozen=True)
class SpeciesThermo:
    r"""Specific heat of one species as a function of T, per kg.

    ``kind`` (``nasa7``, ``shomate``, ``polynomial``); ``ranges``: tuple of
    ``(T_low, T_high, coefficients)`` in K, contiguous and increasing; ``molar_mass`` (kg/mol,
    to turn molar forms into per-kg values; 1 for per-kg forms); ``scale``: factor from the
    form's value to J/(kg K).

    Examples
    --------
    N2 from the GRI-Mech 3.0 NASA polynomials (300-1000-5000 K):

    >>> th = thermo_from_dict("N2", {"nasa7": {"T_range": [300, 1000, 5000], "coefficients": [
    ...     [3.298677, 1.4082404e-3, -3.963222e-6, 5.641515e-9, -2.444854e-12],
    ...     [2.92664, 1.4879768e-3, -5.68476e-7, 1.0097038e-10, -6.753351e-15]]}}, 0.0280134)
    >>> round(float(th.cp(300.0)), 1), round(float(th.enthalpy(1000.0)) / 1e3, 1)
    (1037.9, 766.4)
    """

    kind: str
    ranges: tuple
    molar_mass: float
    scale: float

    @property
    def T_low(self) -> float:
        return self.ranges[0][0]

    @property
    def T_high(self) -> float:
        return self.ranges[-1][1]

    # --- one range ---------------------------------------------------------------------
    def _cp_raw(self, c, T):
        if self.kind == "nasa7":
            return c[0] + T * (c[1] + T * (c[2] + T * (c[3] + T * c[4])))
        if self.kind == "shomate":
            t = T / 1000.0
            return c[0] + t * (c[1] + t * (c[2] + t * c[3])) + c[4] / (t * t)
        out = np.zeros_like(T)
        for a in reversed(c):
            out = out * T + a
        return out

    def _h_raw(self, c, T):
        """Antiderivative of the raw c_p (in the form's units times K)."""
        if self.kind == "nasa7":
            return T * (c[0] + T * (c[1] / 2 + T * (c[2] / 3 + T * (c[3] / 4 + T * c[4] / 5))))
        if self.kind == "shomate":
            t = T / 1000.0
            return 1000.0 * (
                c[0] * t + c[1] * t**2 / 2 + c[2] * t**3 / 3 + c[3] * t**4 / 4 - c[4] / t
            )
        out = np.zeros_like(T)
        for k in range(len(c) - 1, -1, -1):
            out = out * T + c[k] / (k + 1)
        return out * T

    # --- public ------------------------------------------------------------------------
    def cp(self, T):
        """Specific heat at T (K), J/(kg K); constant beyond the fitted range."""
        T = np.asarray(T, dtype=float)
        Tc = np.clip(T, self.T_low, self.T_high)
        out = np.zeros_like(Tc)
        for i, (lo, hi, c) in enumerate(self.ranges):
            inside = (Tc >= lo) & ((Tc < hi) | (i == len(self.ranges) - 1))
            out = np.where(inside, self._cp_raw(c, Tc), out)
        out = out * self.scale
        return out if out.ndim else float(out)

    def _H(self, T):
        """Absolute enthalpy integral from T_low (J/kg), continuous, linear beyond range."""
        T = np.asarray(T, dtype=float)
        Tc = np.clip(T, self.T_low, self.T_high)
        base, cp_lo, cp_hi, offsets = self._constants
        if len(self.ranges) == 1:
            out = self._h_raw(self.ranges[0][2], Tc) * self.scale - offsets[0]
        else:
            out = np.zeros_like(Tc)
            for i, (lo, hi, c) in enumerate(self.ranges):
                last = i == len(self.ranges) - 1
                inside = (Tc >= lo) & ((Tc < hi) | last)
                out = np.where(inside, self._h_raw(c, Tc) * self.scale - offsets[i], out)
        if T.size and (T.min() < self.T_low or T.max() > self.T_high):
            out = out + cp_lo * np.minimum(T - self.T_low, 0.0)
            out = out + cp_hi * np.maximum(T - self.T_high, 0.0)
        return out

    @property
    def _constants(self):
        """(unused, c_p at T_low, c_p at T_high, per-range offsets making _H continuous)."""
        cached = self.__dict__.get("_const")
        if cached is not None:
            return cached
        offsets, base = [], 0.0
        for lo, hi, c in self.ranges:
            lo_h = float(self._h_raw(c, np.float64(lo))) * self.scale
            offsets.append(lo_h - base)
            base += float(self._h_raw(c, np.float64(hi)) - self._h_raw(c, np.float64(lo))) * (
                self.scale
            )
        cp_lo = float(self._cp_raw(self.ranges[0][2], np.float64(self.T_low))) * self.scale
        cp_hi = float(self._cp_raw(self.ranges[-1][2], np.float64(self.T_high))) * self.scale
        out = (base, cp_lo, cp_hi, tuple(offsets))
        object.__setattr__(self, "_const", out)
        return out

    def enthalpy(self, T):
        """Sensible enthalpy h(T) - h(298.15 K), J/kg."""
        h_ref = self.__dict__.get("_href")
        if h_ref is None:
            h_ref = float(self._H(np.float64(T_REF)))
            object.__setattr__(self, "_href", h_ref)
        out = self._H(T) - h_ref
        return out if np.ndim(out) else float(out)

    def mean_cp(self, T1: float = T_REF, T2: float = 1000.0) -> float:
        """Mean specific heat between T1 and T2 (K), J/(kg K)."""
        return float((self._H(np.float64(T2)) - self._H(np.float64(T1))) / (T2 - T1))

    def check_range(self, T, name: str = "species") -> None:
        """Warn (:class:`~rotarykiln.errors.OutOfRangeWarning`) if T leaves the fitted range."""
        from rotarykiln.errors import warn_out_of_range

        warn_out_of_range(f"{name} temperature [K]", T, self.T_low, self.T_high, f"{name} c_p fit")


def _numbers(field: str, value, n: int | None = None) -> list[float]:
    if not isinstance(value, list | tuple) or not value:
        raise InputError(field, value, f"a list of {n or 'some'} numbers")
    out = []
    for v in value:
        if isinstance(v, bool) or not isinstance(v, int | float) or not np.isfinite(v):
            raise InputError(field, value, f"a list of {n or 'some'} finite numbers")
        out.append(float(v))
    if n is not None and len(out) != n:
        raise InputError(field, f"{len(out)} numbers", f"{n} numbers")
    return out


def _t_range(field: str, value, parts: int | None = None) -> list[float]:
    t = _numbers(field, value)
    if len(t) < 2 or (parts is not None and len(t) != parts + 1):
        want = "[T_low, T_high]" if parts in (None, 1) else "[T_low, T_mid, T_high]"
        raise InputError(field, value, f"{want} in K")
    if t[0] <= 0 or any(b <= a for a, b in zip(t, t[1:], strict=False)):
        raise InputError(field, value, "increasing temperatures > 0 K")
    return t


FORMS = ("nasa7", "shomate", "polynomial")


def thermo_from_dict(name: str, spec: Mapping, molar_mass: float) -> SpeciesThermo:
    """Build and check a :class:`SpeciesThermo` from a species' YAML ``cp`` mapping.

    ``spec`` holds exactly one of:

    - ``nasa7: {T_range: [T_low, T_mid, T_high], coefficients: [[a1..a5], [a1..a5]]}`` (or
      one range: ``T_range: [T_low, T_high]``, ``coefficients: [a1..a5]``; a6, a7 may follow,
      they are not used: the formation enthalpy is the species' ``h_f``);
    - ``shomate: {T_range: [T_low, T_high], coefficients: [A, B, C, D, E], basis: molar|mass}``
      (or NIST's several ranges: ``T_range: [T_low, T_mid, T_high]``, ``coefficients:
      [[A..E], [A..E]]``);
    - ``polynomial: {T_range: [T_low, T_high], coefficients: [c0, c1, ...]}`` (J/(kg K), T in K).

    Refused with a one-line :class:`InputError` naming the field: an unknown form, a wrong
    number of coefficients, a range that is not increasing, and a c_p that is not positive
    everywhere in the stated range.

    Parameters
    ----------
    name : str
        Species name (in messages).
    spec : mapping
        The ``cp`` mapping of the species (T in K; c_p per mol or per kg as the form says).
    molar_mass : float, kg/mol
        Turns molar forms into per-kg values.

    Returns
    -------
    SpeciesThermo, J/(kg K)
        c_p(T) in J/(kg K) and the sensible enthalpy in J/kg.

    Examples
    --------
    >>> th = thermo_from_dict("char", {"polynomial": {"T_range": [298, 1200],
    ...     "coefficients": [420.0, 2.09, -6.85e-4]}}, 0.012)
    >>> round(float(th.cp(700.0)))
    1547
    >>> thermo_from_dict("x", {"polynomial": {"T_range": [298, 1200],
    ...     "coefficients": [420.0, 2.09, -6.85e-3]}}, 0.012)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: species.x.cp.polynomial: c_p -6936 J/(kg K) at 1200 K is not positive over T_range [298, 1200] K

    References
    ----------
    B.J. McBride, S. Gordon, M.A. Reno, NASA TM-4513 (1993); NIST Chemistry WebBook (Shomate).
    """
    f = f"species.{name}.cp"
    if not isinstance(spec, Mapping):
        raise InputError(
            f, spec, "a number (J/(kg K)) or a mapping with one of " + ", ".join(FORMS)
        )
    forms = [k for k in spec if k in FORMS]
    extra = [k for k in spec if k not in FORMS]
    if extra:
        raise InputError(f"{f}.{extra[0]}", "given", "one of " + ", ".join(FORMS))
    if len(forms) != 1:
        raise InputError(f, ", ".join(forms) or "empty", "exactly one of " + ", ".join(FORMS))
    kind = forms[0]
    body = spec[kind]
    fk = f"{f}.{kind}"
    if not isinstance(body, Mapping):
        raise InputError(fk, body, "a mapping with T_range and coefficients")
    allowed = {"T_range", "coefficients"} | ({"basis"} if kind == "shomate" else set())
    for key in body:
        if key not in allowed:
            raise InputError(f"{fk}.{key}", "given", "one of " + ", ".join(sorted(allowed)))
    for key in ("T_range", "coefficients"):
        if key not in body:
            raise InputError(f"{fk}.{key}", "missing", "given")
    coefs = body["coefficients"]
    if kind == "nasa7":
        two = isinstance(coefs, list | tuple) and coefs and isinstance(coefs[0], list | tuple)
        sets = list(coefs) if two else [coefs]
        t = _t_range(f"{fk}.T_range", body["T_range"], len(sets))
        cs = []
        for i, c in enumerate(sets):
            vals = _numbers(f"{fk}.coefficients[{i}]" if two else f"{fk}.coefficients", c)
            if len(vals) not in (5, 7):
                raise InputError(f"{fk}.coefficients", f"{len(vals)} numbers", "5 or 7 per range")
            cs.append(tuple(vals[:5]))
        ranges = tuple((t[i], t[i + 1], cs[i]) for i in range(len(cs)))
        scale = R_GAS / molar_mass
    elif kind == "shomate":
        two = isinstance(coefs, list | tuple) and coefs and isinstance(coefs[0], list | tuple)
        sets = list(coefs) if two else [coefs]
        t = _t_range(f"{fk}.T_range", body["T_range"], len(sets))
        cs = [
            tuple(_numbers(f"{fk}.coefficients[{i}]" if two else f"{fk}.coefficients", c, 5))
            for i, c in enumerate(sets)
        ]
        basis = body.get("basis", "molar")
        if basis not in ("molar", "mass"):
            raise InputError(f"{fk}.basis", basis, "molar (J/(mol K), NIST) or mass (J/(kg K))")
        ranges = tuple((t[i], t[i + 1], cs[i]) for i in range(len(cs)))
        scale = 1.0 / molar_mass if basis == "molar" else 1.0
    else:
        t = _t_range(f"{fk}.T_range", body["T_range"], 1)
        vals = _numbers(f"{fk}.coefficients", coefs)
        if len(vals) > 6:
            raise InputError(f"{fk}.coefficients", f"{len(vals)} numbers", "1 to 6 numbers")
        ranges = ((t[0], t[1], tuple(vals)),)
        scale = 1.0
    th = SpeciesThermo(kind, ranges, molar_mass, scale)
    for lo, hi, c in ranges:
        T = np.linspace(lo, hi, _CHECK_POINTS)
        cp = th._cp_raw(c, T) * scale
        if not np.all(np.isfinite(cp)) or np.any(cp <= 0):
            i = int(np.argmin(np.where(np.isfinite(cp), cp, -np.inf)))
            raise InputError(
                fk,
                f"c_p {cp[i]:.4g} J/(kg K) at {T[i]:.6g} K",
                f"positive over T_range [{', '.join(f'{v:.6g}' for v in (lo, hi))}] K",
            )
    return th
