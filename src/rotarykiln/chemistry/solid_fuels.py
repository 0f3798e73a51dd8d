r"""Solid fuels: analyses and their bases, heating values, combustion with any oxidiser, kinetics.

- :class:`SolidFuel`: a fuel by its proximate analysis (moisture, volatiles, fixed carbon, ash)
  and ultimate analysis (C, H, O, N, S, Cl), each given on its own basis (as received ``ar``,
  air-dried ``ad``, dry ``d``, dry ash-free ``daf``), checked to sum to 1 on that basis, and
  reported on any basis (ASTM D3180). A measured HHV, or one from a correlation.
- Heating values: Dulong, Boie (1953), Channiwala & Parikh (2002), Parikh, Channiwala & Ghosal
  (2005, proximate); HHV -> LHV.
- Complete combustion with any oxidiser (air, O2-enriched air, pure O2, recirculated flue gas):
  the oxidiser demand and the flue gas, elements balanced to round-off
  (:func:`complete_combustion`).
- Devolatilisation: single first-order rate (Badzioch & Hawksley 1970) and the two competing
  rates of Kobayashi, Howard & Sarofim (1977) with Ubhayakar's (1976) constants.
- Char burn-out: the kinetic/diffusion series-resistance rate of Baum & Street (1971) / Field
  (1969) as implemented in OpenFOAM (``COxidationKineticDiffusionLimitedRate``), and the burn-out
  time of a char sphere.

Why here and not in :mod:`rotarykiln.materials`: a fuel is defined by what it releases and
consumes when it burns (volatiles, char, oxygen, flue gas), i.e. by its reactions and their
kinetics, which are chemistry; :mod:`rotarykiln.materials` holds properties of matter that does
not react (bulk solids, gases, refractories). The fuel *data* are YAML in ``data/fuels/``.

Mass fractions are fractions; temperatures K; heating values J/kg. Reference note: team source
folder reference/cement_lime.md section 5 (and flames.md section 1).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np
import yaml

from rotarykiln.chemistry.clinker import element_molar_mass
from rotarykiln.errors import InputError, check_positive, check_range, warn_out_of_range

__all__ = [
    "BASES",
    "H_FG_25C",
    "CombustionProducts",
    "SolidFuel",
    "astm_d3180_basis_factor",
    "badzioch_hawksley_devolatilisation_rate",
    "baum_street_char_burnout_time",
    "baum_street_char_oxidation_rate",
    "baum_street_diffusion_rate_coefficient",
    "baum_street_kinetic_rate_coefficient",
    "blend_fuels",
    "boie_hhv",
    "channiwala_parikh_hhv",
    "complete_combustion",
    "dulong_hhv",
    "kobayashi_devolatilisation_rates",
    "kobayashi_isothermal_yield",
    "load_kiln_fuel",
    "lhv_from_hhv",
    "oxidiser_composition",
    "oxidiser_oxygen_mass_fraction",
    "parikh_proximate_hhv",
    "stoichiometric_oxygen_demand",
]

#: Molar gas constant, J/(mol K).
R_GAS = 8.314462618
#: Analysis bases: as received, air-dried, dry, dry ash-free (ASTM D3180).
BASES = ("ar", "ad", "d", "daf")
#: Latent heat of water at 25 degC, J/kg (the LHV convention of the reference note, 5.2).
H_FG_25C = 2442.6e3

_DATA = Path(__file__).resolve().parent.parent / "data" / "fuels"
_ULTIMATE = ("C", "H", "O", "N", "S", "Cl")
_PROXIMATE = ("moisture", "volatiles", "fixed_carbon", "ash")
_GASES = {
    "O2": {"O": 2},
    "N2": {"N": 2},
    "Ar": {"Ar": 1},
    "CO2": {"C": 1, "O": 2},
    "H2O": {"H": 2, "O": 1},
    "SO2": {"S": 1, "O": 2},
    "HCl": {"H": 1, "Cl": 1},
}


def _mw(species: str) -> float:
    return sum(element_molar_mass(e) * n for e, n in _GASES[species].items())


@lru_cache(maxsize=2)
def _fuel_data() -> dict:
    with open(_DATA / "kiln_fuels.yaml", encoding="utf-8") as fh:
        return yaml.safe_load(fh)


def _frac(field_name, value):
    v = float(value)
    if not (math.isfinite(v) and 0.0 <= v <= 1.0):
        raise InputError(field_name, v, "a mass fraction in [0, 1] (not a percentage)")
    return v


# --------------------------------------------------------------------------------------------
# Bases
# --------------------------------------------------------------------------------------------


def astm_d3180_basis_factor(from_basis, to_basis, moisture_ar, ash_d, moisture_ad=None):
    r"""Factor converting a constituent's mass fraction (or a heating value) between bases.

    Through the dry basis: :math:`x_d = x_{ar}/(1 - W_{ar}) = x_{ad}/(1 - W_{ad})
    = x_{daf}(1 - A_d)`, so :math:`x_{to} = f\,x_{from}`. For constituents other than moisture
    and ash (C, H, volatiles, fixed carbon, HHV ...); ash converts the same way between ar, ad
    and d. H and O exclude the moisture's water.

    Parameters
    ----------
    from_basis, to_basis : str
        ``ar``, ``ad``, ``d`` or ``daf``.
    moisture_ar : float, -
        Total moisture as received, in [0, 1).
    ash_d : float, -
        Ash on the dry basis, in [0, 1).
    moisture_ad : float or None, -
        Moisture of the air-dried sample (needed for ``ad``).

    Returns
    -------
    float, -

    Examples
    --------
    >>> round(astm_d3180_basis_factor("ar", "d", 0.0165, 0.0925), 5)
    1.01678

    References
    ----------
    ASTM D3180, Standard practice for calculating coal and coke analyses from as-determined to
    different bases; ISO 1170; team source folder reference/cement_lime.md 5.1.
    """

    def to_dry(b):
        if b == "ar":
            return 1.0 / (1.0 - moisture_ar)
        if b == "ad":
            if moisture_ad is None:
                raise InputError("moisture_ad", "missing", "given for the air-dried basis")
            check_range("moisture_ad", moisture_ad, 0.0, 1.0, closed_low=True)
            return 1.0 / (1.0 - moisture_ad)
        if b == "d":
            return 1.0
        return 1.0 - ash_d

    for name, b in (("from_basis", from_basis), ("to_basis", to_basis)):
        if b not in BASES:
            raise InputError(name, b, "one of ar, ad, d, daf")
    check_range("moisture_ar", moisture_ar, 0.0, 1.0, closed_low=True)
    check_range("ash_d", ash_d, 0.0, 1.0, closed_low=True)
    return to_dry(from_basis) / to_dry(to_basis)


@dataclass(frozen=True)
class SolidFuel:
    """A solid fuel by its analyses, stored on the dry basis with the as-received moisture.

    Build with :meth:`from_analyses` (analyses on any basis, checked) or :func:`load_kiln_fuel`.

    Attributes
    ----------
    name : str
        Label.
    dry : mapping
        Dry-basis mass fractions ``C``, ``H``, ``O``, ``N``, ``S``, ``Cl``, ``ash`` (sum 1) and
        ``volatiles``, ``fixed_carbon`` (NaN when no proximate analysis), -.
    moisture_ar : float, -
        Total moisture as received.
    moisture_ad : float or None, -
        Moisture of the air-dried sample.
    hhv_d : float or None, J/kg
        Measured higher heating value, dry basis.

    Examples
    --------
    >>> f = load_kiln_fuel("pittsburgh_8")
    >>> round(f.ultimate("ar")["C"], 4)
    0.7425

    References
    ----------
    ASTM D3180; team source folder reference/cement_lime.md 5.1.
    """

    name: str
    dry: Mapping[str, float]
    moisture_ar: float
    moisture_ad: float | None = None
    hhv_d: float | None = None

    @classmethod
    def from_analyses(
        cls,
        *,
        ultimate: Mapping[str, float],
        ultimate_basis: str = "d",
        proximate: Mapping[str, float] | None = None,
        proximate_basis: str = "ar",
        moisture_ar: float | None = None,
        moisture_ad: float | None = None,
        hhv: float | None = None,
        hhv_basis: str = "ar",
        name: str = "fuel",
        sum_tolerance: float = 0.005,
    ) -> SolidFuel:
        """A fuel from its ultimate (and proximate) analysis on stated bases, checked.

        ``ultimate``: C, H, N, S, (Cl), (O: by difference when missing) and ash (except on the
        daf basis), mass fractions on ``ultimate_basis``; on ``ar``/``ad`` the moisture is not
        part of H and O, and the sum with the moisture is 1. ``proximate``: moisture (on ar/ad),
        volatiles, fixed carbon (by difference when missing) and ash (except daf) on
        ``proximate_basis``. The as-received moisture comes from an ar proximate analysis or
        ``moisture_ar``. Sums off 1 by more than ``sum_tolerance`` are refused naming the basis;
        so is an ash that differs between the two analyses (dry basis) by more than it.
        """
        for name_, b in (("ultimate_basis", ultimate_basis), ("proximate_basis", proximate_basis)):
            if b not in BASES:
                raise InputError(name_, b, "one of ar, ad, d, daf")
        if hhv_basis not in BASES:
            raise InputError("hhv_basis", hhv_basis, "one of ar, ad, d, daf")
        tol = sum_tolerance
        prox = dict(proximate or {})
        ult = dict(ultimate)
        for k in prox:
            if k not in _PROXIMATE:
                raise InputError("proximate", k, "keys among " + ", ".join(_PROXIMATE))
        for k in ult:
            if k not in (*_ULTIMATE, "ash"):
                raise InputError("ultimate", k, "keys among C, H, O, N, S, Cl, ash")
        for k, v in prox.items():
            _frac(f"proximate.{k}", v)
        for k, v in ult.items():
            _frac(f"ultimate.{k}", v)

        # moisture
        if proximate is not None and proximate_basis in ("ar", "ad"):
            if "moisture" not in prox:
                raise InputError(
                    "proximate.moisture", "missing", f"given on the {proximate_basis} basis"
                )
            if proximate_basis == "ar":
                if moisture_ar is not None and abs(moisture_ar - prox["moisture"]) > tol:
                    raise InputError(
                        "moisture_ar",
                        moisture_ar,
                        f"equal to proximate.moisture {prox['moisture']:g} (as-received basis)",
                    )
                moisture_ar = prox["moisture"]
            else:
                moisture_ad = prox["moisture"]
        elif "moisture" in prox:
            raise InputError(
                "proximate.moisture", prox["moisture"], f"absent on the {proximate_basis} basis"
            )
        if moisture_ar is None:
            needs_ar = (
                ultimate_basis == "ar"
                or (proximate is not None and proximate_basis == "ar")
                or (hhv is not None and hhv_basis == "ar")
            )
            if needs_ar:
                raise InputError("moisture_ar", "missing", "given (the as-received moisture)")
            moisture_ar = 0.0
        moisture_ar = _frac("moisture_ar", moisture_ar)
        if moisture_ar >= 1.0:
            raise InputError("moisture_ar", moisture_ar, "< 1")
        if moisture_ad is not None:
            moisture_ad = _frac("moisture_ad", moisture_ad)

        def water(b):
            return moisture_ar if b == "ar" else (moisture_ad if b == "ad" else 0.0)

        def dry_factor(b, ash_d):
            return astm_d3180_basis_factor(b, "d", moisture_ar, ash_d, moisture_ad)

        # proximate -> dry
        ash_d_prox = None
        vm_d = fc_d = float("nan")
        if proximate is not None:
            w = water(proximate_basis) if proximate_basis in ("ar", "ad") else 0.0
            if proximate_basis == "daf":
                if "ash" in prox:
                    raise InputError("proximate.ash", prox["ash"], "absent on the daf basis")
            elif "ash" not in prox:
                raise InputError(
                    "proximate.ash", "missing", f"given on the {proximate_basis} basis"
                )
            if "volatiles" not in prox:
                raise InputError("proximate.volatiles", "missing", "given")
            a = prox.get("ash", 0.0)
            what = {
                "ar": "as-received basis: moisture + volatiles + fixed_carbon + ash",
                "ad": "air-dried basis: moisture + volatiles + fixed_carbon + ash",
                "d": "dry basis: volatiles + fixed_carbon + ash",
                "daf": "dry ash-free basis: volatiles + fixed_carbon",
            }[proximate_basis]
            fc_by_difference = "fixed_carbon" not in prox
            if not fc_by_difference:
                total = w + prox["volatiles"] + prox["fixed_carbon"] + a
                if abs(total - 1.0) > tol:
                    raise InputError(f"proximate ({what})", f"sum {total:.6g}", f"1 +- {tol:g}")
                fc = prox["fixed_carbon"]
            else:
                fc = 1.0 - w - prox["volatiles"] - a
                if fc < 0.0:
                    raise InputError(
                        f"proximate ({what})",
                        f"sum without fixed carbon {1.0 - fc:.6g}",
                        "<= 1 (fixed carbon by difference)",
                    )
            if proximate_basis != "daf":
                f = 1.0 / (1.0 - w)
                ash_d_prox = a * f
                vm_d, fc_d = prox["volatiles"] * f, fc * f

        # ultimate -> dry
        if ultimate_basis == "daf":
            if "ash" in ult:
                raise InputError("ultimate.ash", ult["ash"], "absent on the daf basis")
            if ash_d_prox is None:
                raise InputError(
                    "proximate.ash", "missing", "given (a daf ultimate analysis needs the ash)"
                )
            ash_d = ash_d_prox
        else:
            if "ash" not in ult:
                raise InputError("ultimate.ash", "missing", f"given on the {ultimate_basis} basis")
            ash_d = None
        for k in ("C", "H", "N", "S"):
            if k not in ult:
                raise InputError(f"ultimate.{k}", "missing", "given")
        ult.setdefault("Cl", 0.0)
        w = water(ultimate_basis) if ultimate_basis in ("ar", "ad") else 0.0
        if ultimate_basis == "ad" and moisture_ad is None:
            raise InputError("moisture_ad", "missing", "given for an air-dried analysis")
        a = ult.get("ash", 0.0)
        what = {
            "ar": "as-received basis: C + H + O + N + S + Cl + ash + moisture",
            "ad": "air-dried basis: C + H + O + N + S + Cl + ash + moisture",
            "d": "dry basis: C + H + O + N + S + Cl + ash",
            "daf": "dry ash-free basis: C + H + O + N + S + Cl",
        }[ultimate_basis]
        known = sum(ult[k] for k in ("C", "H", "N", "S", "Cl")) + a + w
        if "O" in ult:
            total = known + ult["O"]
            if abs(total - 1.0) > tol:
                raise InputError(f"ultimate ({what})", f"sum {total:.6g}", f"1 +- {tol:g}")
        else:
            if known > 1.0:
                raise InputError(
                    f"ultimate ({what})", f"sum without O {known:.6g}", "<= 1 (O by difference)"
                )
            ult["O"] = 1.0 - known
        if ultimate_basis == "daf":
            f = 1.0 - ash_d
        else:
            f = 1.0 / (1.0 - w)
            ash_d = a * f
        dry = {k: ult[k] * f for k in _ULTIMATE}
        dry["ash"] = ash_d
        if ash_d_prox is not None and abs(ash_d_prox - ash_d) > tol:
            raise InputError(
                "proximate.ash",
                f"{ash_d_prox:.6g} (dry basis)",
                f"equal to the ultimate analysis' ash {ash_d:.6g} +- {tol:g} (dry basis)",
            )
        if proximate is not None and proximate_basis == "daf":
            vm_d = prox["volatiles"] * (1.0 - ash_d)
            fc_d = (1.0 - ash_d) - vm_d
        elif proximate is not None and fc_by_difference:
            fc_d = 1.0 - ash_d - vm_d  # by difference with the one ash kept (the ultimate's)
        dry["volatiles"], dry["fixed_carbon"] = vm_d, fc_d
        hhv_d = None
        if hhv is not None:
            check_positive("hhv", hhv, "J/kg")
            hhv_d = float(hhv) * dry_factor(hhv_basis, ash_d)
        return cls(name, dry, moisture_ar, moisture_ad, hhv_d)

    def _factor(self, basis: str) -> float:
        return astm_d3180_basis_factor(
            "d", basis, self.moisture_ar, self.dry["ash"], self.moisture_ad
        )

    def _water(self, basis: str) -> float:
        return {"ar": self.moisture_ar, "ad": self.moisture_ad or 0.0}.get(basis, 0.0)

    def ultimate(self, basis: str = "ar") -> dict[str, float]:
        """Ultimate analysis on ``basis`` (with ``moisture`` and ``ash`` where they belong)."""
        f = self._factor(basis)
        out = {k: self.dry[k] * f for k in _ULTIMATE}
        if basis != "daf":
            out["ash"] = self.dry["ash"] * f
        if basis in ("ar", "ad"):
            out["moisture"] = self._water(basis)
        return out

    def proximate(self, basis: str = "ar") -> dict[str, float]:
        """Proximate analysis on ``basis`` (NaN volatiles if none was given)."""
        f = self._factor(basis)
        out = {"volatiles": self.dry["volatiles"] * f, "fixed_carbon": self.dry["fixed_carbon"] * f}
        if basis != "daf":
            out["ash"] = self.dry["ash"] * f
        if basis in ("ar", "ad"):
            out["moisture"] = self._water(basis)
        return out

    def hhv(self, basis: str = "ar", correlation: str | None = None) -> float:
        """Higher heating value on ``basis``, J/kg: measured, or from ``correlation``.

        ``correlation``: None (the measured value; Channiwala-Parikh if none), or one of
        ``channiwala_parikh``, ``dulong``, ``boie``, ``parikh_proximate``.
        """
        d = self.dry
        if correlation is None:
            if self.hhv_d is not None:
                return self.hhv_d * self._factor(basis)
            correlation = "channiwala_parikh"
        if correlation == "channiwala_parikh":
            h = channiwala_parikh_hhv(d["C"], d["H"], d["O"], d["N"], d["S"], d["ash"])
        elif correlation == "dulong":
            h = dulong_hhv(d["C"], d["H"], d["O"], d["S"])
        elif correlation == "boie":
            h = boie_hhv(d["C"], d["H"], d["O"], d["N"], d["S"])
        elif correlation == "parikh_proximate":
            if math.isnan(d["volatiles"]):
                raise InputError("proximate", "missing", "given (parikh_proximate needs it)")
            h = parikh_proximate_hhv(d["fixed_carbon"], d["volatiles"], d["ash"])
        else:
            raise InputError(
                "correlation",
                correlation,
                "one of channiwala_parikh, dulong, boie, parikh_proximate",
            )
        return float(h) * self._factor(basis)

    def lhv(self, basis: str = "ar", correlation: str | None = None) -> float:
        """Lower heating value on ``basis``, J/kg (:func:`lhv_from_hhv` of :meth:`hhv`)."""
        u = self.ultimate(basis)
        return float(lhv_from_hhv(self.hhv(basis, correlation), u["H"], u.get("moisture", 0.0)))

    def as_fired(self) -> dict[str, float]:
        """As-received mass fractions C, H, O, N, S, Cl, ash, moisture (sum 1)."""
        return self.ultimate("ar")


def load_kiln_fuel(name: str) -> SolidFuel:
    """A fuel of ``data/fuels/kiln_fuels.yaml`` (the Argonne premium coals) as a SolidFuel."""
    coals = _fuel_data()["argonne_coals"]
    if name not in coals:
        raise InputError("fuel", name, "one of " + ", ".join(coals))
    c = coals[name]
    if c["ultimate_dry_percent"] is None:
        raise InputError(
            "fuel", name, "a fuel with an ultimate analysis in the source (this one has none)"
        )
    p = {k: v / 100.0 for k, v in c["proximate_ar_percent"].items()}
    u = {k: v / 100.0 for k, v in c["ultimate_dry_percent"].items()}
    return SolidFuel.from_analyses(
        ultimate=u,
        ultimate_basis="d",
        proximate=p,
        proximate_basis="ar",
        hhv=c["hhv_ar_btu_per_lb"] * 2326.0,
        hhv_basis="ar",
        name=c["label"],
    )


def blend_fuels(fuels: Sequence[SolidFuel], mass_flows: Sequence[float]) -> dict[str, float]:
    """As-fired mass fractions of several fuels fired together, mass-flow weighted.

    Parameters
    ----------
    fuels : sequence
        The fuels [SolidFuel objects].
    mass_flows : sequence of float, kg/s
        Their as-received mass flows, >= 0, not all 0.

    Returns
    -------
    dict of float, -
        C, H, O, N, S, Cl, ash, moisture of the blend (sum 1), for :func:`complete_combustion`.

    Examples
    --------
    >>> b = blend_fuels([load_kiln_fuel("pittsburgh_8"), load_kiln_fuel("beulah_zap")], [1, 1])
    >>> round(float(sum(b.values())), 12)
    1.0

    References
    ----------
    Mass balance.
    """
    m = np.asarray(mass_flows, dtype=float)
    if len(fuels) == 0 or m.shape != (len(fuels),):
        raise InputError("mass_flows", m, f"{len(fuels)} values, one per fuel")
    if not np.all(np.isfinite(m) & (m >= 0)) or m.sum() <= 0:
        raise InputError("mass_flows", m, ">= 0 kg/s each and not all 0")
    out: dict[str, float] = {}
    for f, w in zip(fuels, m / m.sum(), strict=True):
        for k, v in f.as_fired().items():
            out[k] = out.get(k, 0.0) + w * v
    return out


# --------------------------------------------------------------------------------------------
# Heating values
# --------------------------------------------------------------------------------------------


def _pct(*values):
    return [100.0 * np.asarray(v, dtype=float) for v in values]


def dulong_hhv(C, H, O, S):
    r"""Higher heating value by Dulong's formula, dry basis, J/kg.

    .. math:: HHV\,[\mathrm{MJ/kg}] = 0.3383\,C + 1.443\,(H - O/8) + 0.0942\,S \quad (\text{wt \%})

    Parameters
    ----------
    C, H, O, S : float or array, -
        Dry-basis mass fractions.

    Returns
    -------
    float or ndarray, J/kg

    Notes
    -----
    For low-oxygen coals (O < 10 %); underestimates biomass by about 10 %.

    Examples
    --------
    >>> round(dulong_hhv(0.7550, 0.0483, 0.0663, 0.0219) / 1e6, 2)
    31.52

    References
    ----------
    Dulong's formula as coded in PabloMBarral/apps ``core/combustion/heating_value.py``; team
    source folder reference/cement_lime.md 5.2.
    """
    c, h, o, s = _pct(C, H, O, S)
    out = 1e6 * (0.3383 * c + 1.443 * (h - o / 8.0) + 0.0942 * s)
    return out if np.ndim(out) else float(out)


def boie_hhv(C, H, O, N, S):
    r"""Higher heating value by Boie (1953), dry basis, J/kg.

    .. math:: HHV\,[\mathrm{MJ/kg}] = 0.3516\,C + 1.16225\,H - 0.1109\,O + 0.0628\,N
        + 0.10465\,S \quad (\text{wt \%})

    Parameters
    ----------
    C, H, O, N, S : float or array, -
        Dry-basis mass fractions.

    Returns
    -------
    float or ndarray, J/kg

    Examples
    --------
    >>> round(boie_hhv(0.7550, 0.0483, 0.0663, 0.0149, 0.0219) / 1e6, 2)
    31.75

    References
    ----------
    W. Boie, Energietechnik 3 (1953) 309, as coded in PabloMBarral/apps
    ``core/combustion/heating_value.py``; team source folder reference/cement_lime.md 5.2.
    """
    c, h, o, n, s = _pct(C, H, O, N, S)
    out = 1e6 * (0.3516 * c + 1.16225 * h - 0.1109 * o + 0.0628 * n + 0.10465 * s)
    return out if np.ndim(out) else float(out)


def channiwala_parikh_hhv(C, H, O, N, S, ash):
    r"""Higher heating value by Channiwala & Parikh (2002), dry basis, J/kg.

    .. math:: HHV\,[\mathrm{MJ/kg}] = 0.3491\,C + 1.1783\,H + 0.1005\,S - 0.1034\,O
        - 0.0151\,N - 0.0211\,A \quad (\text{wt \%})

    Parameters
    ----------
    C, H, O, N, S, ash : float or array, -
        Dry-basis mass fractions.

    Returns
    -------
    float or ndarray, J/kg

    Notes
    -----
    Fitted on 225 and validated on 50 fuels (coals, biomass, liquids, gases): C 0-92.25,
    H 0.43-25.15, O 0-50, N 0-5.6, S 0-94.08, ash 0-71.4 %, HHV 4.745-55.345 MJ/kg; average
    absolute error 1.45 %, bias 0.00 %. A warning is issued outside the ranges.

    Examples
    --------
    >>> round(channiwala_parikh_hhv(0.7550, 0.0483, 0.0663, 0.0149, 0.0219, 0.0925) / 1e6, 2)
    31.37

    References
    ----------
    S.A. Channiwala, P.P. Parikh, A unified correlation for estimating HHV of solid, liquid and
    gaseous fuels, Fuel 81 (2002) 1051-1063, doi:10.1016/S0016-2361(01)00131-4; team source
    folder reference/cement_lime.md 5.2.
    """
    c, h, o, n, s, a = _pct(C, H, O, N, S, ash)
    src = "Channiwala & Parikh (2002)"
    for what, v, lo, hi in (
        ("C [%]", c, 0.0, 92.25),
        ("H [%]", h, 0.43, 25.15),
        ("O [%]", o, 0.0, 50.0),
        ("N [%]", n, 0.0, 5.6),
        ("S [%]", s, 0.0, 94.08),
        ("ash [%]", a, 0.0, 71.4),
    ):
        warn_out_of_range(what, v, lo, hi, src)
    out = 1e6 * (0.3491 * c + 1.1783 * h + 0.1005 * s - 0.1034 * o - 0.0151 * n - 0.0211 * a)
    return out if np.ndim(out) else float(out)


def parikh_proximate_hhv(fixed_carbon, volatiles, ash):
    r"""Higher heating value from the proximate analysis (Parikh, Channiwala & Ghosal 2005), J/kg.

    .. math:: HHV\,[\mathrm{MJ/kg}] = 0.3536\,FC + 0.1559\,VM - 0.0078\,A \quad (\text{wt \%, dry})

    Parameters
    ----------
    fixed_carbon, volatiles, ash : float or array, -
        Dry-basis mass fractions.

    Returns
    -------
    float or ndarray, J/kg

    Notes
    -----
    Average absolute error 3.74 %; underestimates the Argonne bituminous coals by 14-23 %.

    Examples
    --------
    >>> round(parikh_proximate_hhv(0.529, 0.378, 0.0925) / 1e6, 2)
    24.53

    References
    ----------
    J. Parikh, S.A. Channiwala, G.K. Ghosal, A correlation for calculating HHV from proximate
    analysis of solid fuels, Fuel 84 (2005) 487-494; team source folder
    reference/cement_lime.md 5.2.
    """
    fc, vm, a = _pct(fixed_carbon, volatiles, ash)
    out = 1e6 * (0.3536 * fc + 0.1559 * vm - 0.0078 * a)
    return out if np.ndim(out) else float(out)


def lhv_from_hhv(hhv, H, moisture=0.0):
    r"""Lower heating value from the higher, on the same basis, J/kg.

    .. math:: LHV = HHV - h_{fg}\left(\frac{M_{H_2O}}{2 M_H} H + W\right),
        \qquad h_{fg}(25\,^\circ C) = 2442.6\ \mathrm{kJ/kg}

    Parameters
    ----------
    hhv : float or array, J/kg
        Higher heating value on the basis of ``H`` and ``moisture``.
    H : float or array, -
        Hydrogen mass fraction (excluding the moisture's).
    moisture : float or array, -
        Moisture mass fraction (0 on the dry basis).

    Returns
    -------
    float or ndarray, J/kg

    Examples
    --------
    >>> round(lhv_from_hhv(31.18e6, 0.0475, 0.0165) / 1e6, 2)
    30.1

    References
    ----------
    PabloMBarral/apps ``core/combustion/heating_value.py``; team source folder
    reference/cement_lime.md 5.2 and flames.md 1.
    """
    ratio = _mw("H2O") / (2.0 * element_molar_mass("H"))
    out = np.asarray(hhv, dtype=float) - H_FG_25C * (
        ratio * np.asarray(H, dtype=float) + np.asarray(moisture, dtype=float)
    )
    return out if out.ndim else float(out)


# --------------------------------------------------------------------------------------------
# Oxidisers and complete combustion
# --------------------------------------------------------------------------------------------


def oxidiser_composition(oxidiser="air", o2_mole_fraction=None):
    r"""Mole fractions of an oxidiser: air, pure O2, O2-enriched air, or given.

    ``oxidiser``: ``"air"`` (dry air, ``data/fuels/kiln_fuels.yaml``), ``"oxygen"``,
    ``"enriched_air"`` (air plus pure O2 to the mole fraction ``o2_mole_fraction``) or a mapping
    of mole fractions over O2, N2, Ar, CO2, H2O (e.g. recirculated flue gas mixed with O2),
    summing to 1 +- 1e-6, with O2 > 0.

    Parameters
    ----------
    oxidiser : str or mapping
        As above.
    o2_mole_fraction : float or None, -
        For ``enriched_air``: the O2 mole fraction, in [0.20946, 1].

    Returns
    -------
    dict of float, -
        Mole fractions.

    Examples
    --------
    >>> round(oxidiser_composition("enriched_air", 0.30)["N2"], 4)
    0.6914

    References
    ----------
    Dry air: CRC Handbook of Chemistry and Physics; team source folder
    reference/cement_lime.md 5.7.
    """
    data = _fuel_data()["oxidisers"]
    if isinstance(oxidiser, str):
        if oxidiser == "enriched_air":
            air = data["air"]
            if o2_mole_fraction is None:
                raise InputError("o2_mole_fraction", "missing", "given for enriched_air")
            check_range(
                "o2_mole_fraction",
                o2_mole_fraction,
                air["O2"],
                1.0,
                closed_low=True,
                closed_high=True,
            )
            f = (o2_mole_fraction - air["O2"]) / (1.0 - air["O2"])  # mol O2 added per mol mix
            comp = {k: (1.0 - f) * v for k, v in air.items()}
            comp["O2"] += f
            return comp
        if oxidiser not in data:
            raise InputError("oxidiser", oxidiser, "one of air, oxygen, enriched_air or a mapping")
        return dict(data[oxidiser])
    comp = {}
    for k, v in dict(oxidiser).items():
        if k not in ("O2", "N2", "Ar", "CO2", "H2O"):
            raise InputError("oxidiser", k, "species among O2, N2, Ar, CO2, H2O")
        comp[k] = _frac(f"oxidiser.{k}", v)
    total = sum(comp.values())
    if abs(total - 1.0) > 1e-6:
        raise InputError("oxidiser (mole fractions)", f"sum {total:.8g}", "1 +- 1e-06")
    if comp.get("O2", 0.0) <= 0.0:
        raise InputError(
            "oxidiser.O2", comp.get("O2", 0.0), "> 0 (a fuel needs an oxidiser with oxygen)"
        )
    return comp


def oxidiser_oxygen_mass_fraction(composition):
    r"""O2 mass fraction of an oxidiser given by mole fractions.

    .. math:: Y_{O_2} = \frac{x_{O_2} M_{O_2}}{\sum_i x_i M_i}

    Parameters
    ----------
    composition : mapping
        Mole fractions over O2, N2, Ar, CO2, H2O, -.

    Returns
    -------
    float, -

    Examples
    --------
    >>> round(oxidiser_oxygen_mass_fraction({"O2": 0.21, "N2": 0.79}), 4)
    0.2329

    References
    ----------
    Team source folder reference/cement_lime.md 5.7.
    """
    comp = oxidiser_composition(composition)
    m = sum(x * _mw(k) for k, x in comp.items())
    return comp["O2"] * _mw("O2") / m


def stoichiometric_oxygen_demand(C, H, O, S, Cl=0.0):
    r"""Oxygen needed to burn a fuel completely, kg O2 per kg fuel.

    .. math:: m_{O_2} = M_{O_2}\left(\frac{C}{M_C} + \frac{S}{M_S}
        + \frac{H/M_H - Cl/M_{Cl}}{4}\right) - O
        \approx 2.664\,C + 7.937\,H + 0.998\,S - O

    (C -> CO2, S -> SO2, H -> H2O after HCl takes the chlorine's hydrogen.)

    Parameters
    ----------
    C, H, O, S, Cl : float or array, -
        Mass fractions (same basis; the result is per kg of fuel on that basis).

    Returns
    -------
    float or ndarray, kg/kg

    Examples
    --------
    >>> round(stoichiometric_oxygen_demand(1.0, 0.0, 0.0, 0.0), 3)
    2.664

    References
    ----------
    Stoichiometry; team source folder reference/cement_lime.md 5.7 and flames.md 1.
    """
    mo2 = _mw("O2")
    n = (
        np.asarray(C, dtype=float) / element_molar_mass("C")
        + np.asarray(S, dtype=float) / element_molar_mass("S")
        + (
            np.asarray(H, dtype=float) / element_molar_mass("H")
            - np.asarray(Cl) / element_molar_mass("Cl")
        )
        / 4.0
    )
    out = mo2 * n - np.asarray(O, dtype=float)
    return out if out.ndim else float(out)


@dataclass(frozen=True)
class CombustionProducts:
    """Complete combustion of one kg of fuel (as fired) with an oxidiser.

    Attributes
    ----------
    excess_ratio : float, -
        Oxidiser supplied / stoichiometric (lambda).
    oxidiser_moles : float, mol/kg fuel
        Oxidiser supplied.
    oxidiser_mass : float, kg/kg fuel
        Oxidiser supplied.
    stoichiometric_oxidiser_mass : float, kg/kg fuel
        Oxidiser at lambda = 1.
    flue_gas_moles : dict
        mol/kg fuel of CO2, H2O, SO2, HCl, N2, O2, Ar.
    flue_gas_mass : float, kg/kg fuel
        Mass of the flue gas.
    ash : float, kg/kg fuel
        Ash (to the bed or the dust).
    elements_in, elements_out : dict
        mol/kg fuel of each element entering (fuel + oxidiser) and leaving (gas).
    """

    excess_ratio: float
    oxidiser_moles: float
    oxidiser_mass: float
    stoichiometric_oxidiser_mass: float
    flue_gas_moles: dict
    flue_gas_mass: float
    ash: float
    elements_in: dict = field(default_factory=dict)
    elements_out: dict = field(default_factory=dict)

    def mole_fractions(self, dry: bool = False) -> dict[str, float]:
        """Flue-gas mole fractions, wet or dry (water removed)."""
        n = {k: v for k, v in self.flue_gas_moles.items() if not (dry and k == "H2O")}
        total = sum(n.values())
        return {k: v / total for k, v in n.items()}

    def element_balance_error(self) -> float:
        """Largest |in - out| / in over the elements (0 for an exact balance)."""
        return max(
            abs(self.elements_in[e] - self.elements_out.get(e, 0.0)) / self.elements_in[e]
            for e in self.elements_in
            if self.elements_in[e] > 0
        )


def complete_combustion(fuel, oxidiser="air", excess_ratio=1.0):
    r"""Oxidiser demand and flue gas of a fuel burnt completely with any oxidiser.

    Per kg of fuel as fired (mass fractions C, H, O, N, S, Cl, moisture, ash):
    C -> CO2, S -> SO2, Cl -> HCl, the rest of H -> H2O, N -> N2, moisture -> H2O, ash stays
    solid; oxygen demand :math:`n_{O_2} = n_C + n_S + (n_H - n_{Cl})/4 - n_O/2`; oxidiser
    :math:`\lambda n_{O_2}/x_{O_2}` mol, whose N2, Ar, CO2, H2O pass through and whose excess O2
    remains. Elements balance to round-off (:meth:`CombustionProducts.element_balance_error`).

    Parameters
    ----------
    fuel : SolidFuel or mapping
        A fuel, or its as-fired mass fractions (sum 1 +- 1e-6), -.
    oxidiser : str or mapping
        See :func:`oxidiser_composition` (``"air"``, ``"oxygen"``, mole fractions).
    excess_ratio : float, -
        :math:`\lambda` >= 1 (complete combustion).

    Returns
    -------
    CombustionProducts, per kg of fuel
        Oxidiser, flue gas (mol/kg, kg/kg), ash (kg/kg) and the element flows.

    Examples
    --------
    >>> p = complete_combustion({"C": 1.0})
    >>> round(p.oxidiser_mass, 3), round(p.mole_fractions()["CO2"], 4)
    (11.513, 0.2098)

    References
    ----------
    Stoichiometry; team source folder reference/cement_lime.md 5.7 and flames.md 1.
    """
    if isinstance(fuel, SolidFuel):
        x = fuel.as_fired()
    else:
        x = {}
        for k, v in dict(fuel).items():
            if k not in (*_ULTIMATE, "ash", "moisture"):
                raise InputError("fuel", k, "keys among C, H, O, N, S, Cl, ash, moisture")
            x[k] = _frac(f"fuel.{k}", v)
        total = sum(x.values())
        if abs(total - 1.0) > 1e-6:
            raise InputError(
                "fuel (as-fired basis, with moisture and ash)", f"sum {total:.8g}", "1 +- 1e-06"
            )
    lam = float(excess_ratio)
    if not (math.isfinite(lam) and lam >= 1.0):
        raise InputError(
            "excess_ratio",
            lam,
            ">= 1 (complete combustion; a fuel needs at least its stoichiometric air)",
        )
    comp = oxidiser_composition(oxidiser)
    el = {e: x.get(e, 0.0) / element_molar_mass(e) for e in _ULTIMATE}
    n_w = x.get("moisture", 0.0) / _mw("H2O")
    if el["H"] < el["Cl"]:
        raise InputError("fuel.Cl", x.get("Cl", 0.0), "with enough hydrogen to form HCl")
    demand = el["C"] + el["S"] + (el["H"] - el["Cl"]) / 4.0 - el["O"] / 2.0
    if demand <= 0.0:
        raise InputError("fuel", f"oxygen demand {demand:.4g} mol/kg", "> 0 (a combustible fuel)")
    n_ox = lam * demand / comp["O2"]
    m_ox_mol = sum(v * _mw(k) for k, v in comp.items())
    gas = {
        "CO2": el["C"] + n_ox * comp.get("CO2", 0.0),
        "H2O": (el["H"] - el["Cl"]) / 2.0 + n_w + n_ox * comp.get("H2O", 0.0),
        "SO2": el["S"],
        "HCl": el["Cl"],
        "N2": el["N"] / 2.0 + n_ox * comp.get("N2", 0.0),
        "O2": (lam - 1.0) * demand,
        "Ar": n_ox * comp.get("Ar", 0.0),
    }
    e_in = {
        "C": el["C"],
        "H": el["H"] + 2.0 * n_w,
        "O": el["O"] + n_w,
        "N": el["N"],
        "S": el["S"],
        "Cl": el["Cl"],
        "Ar": 0.0,
    }
    for sp, xk in comp.items():
        for e, k in _GASES[sp].items():
            e_in[e] += n_ox * xk * k
    e_out = {e: 0.0 for e in e_in}
    for sp, n in gas.items():
        for e, k in _GASES[sp].items():
            e_out[e] += n * k
    return CombustionProducts(
        excess_ratio=lam,
        oxidiser_moles=n_ox,
        oxidiser_mass=n_ox * m_ox_mol,
        stoichiometric_oxidiser_mass=demand / comp["O2"] * m_ox_mol,
        flue_gas_moles=gas,
        flue_gas_mass=sum(n * _mw(sp) for sp, n in gas.items()),
        ash=x.get("ash", 0.0),
        elements_in=e_in,
        elements_out=e_out,
    )


# --------------------------------------------------------------------------------------------
# Devolatilisation
# --------------------------------------------------------------------------------------------


def badzioch_hawksley_devolatilisation_rate(T, V, V_star, A, E):
    r"""Single first-order devolatilisation rate (Badzioch & Hawksley 1970), 1/s.

    .. math:: \frac{dV}{dt} = A\,e^{-E/(R T)}\,(V^* - V)

    Parameters
    ----------
    T : float or array, K
        Particle temperature.
    V : float or array, -
        Volatiles released so far, per kg of daf coal.
    V_star : float, -
        Ultimate volatile yield, per kg of daf coal.
    A : float, 1/s
        Pre-exponential factor (PKP's calibration bounds 1e4-1e9).
    E : float, J/mol
        Activation energy (PKP's bounds 50-200 kJ/mol).

    Returns
    -------
    float or ndarray, 1/s

    Examples
    --------
    >>> round(badzioch_hawksley_devolatilisation_rate(1500.0, 0.0, 0.5, 1e5, 1e5), 1)
    16.5

    References
    ----------
    S. Badzioch, P.G.W. Hawksley, Kinetics of thermal decomposition of pulverized coal
    particles, Ind. Eng. Chem. Process Des. Dev. 9 (1970) 521-530; mighelone/pkpcoal README
    (bounds); team source folder reference/cement_lime.md 5.3.
    """
    check_positive("T", T, "K")
    check_positive("A", A, "1/s")
    check_positive("E", E, "J/mol")
    out = (
        A
        * np.exp(-E / (R_GAS * np.asarray(T, dtype=float)))
        * (np.asarray(V_star, dtype=float) - np.asarray(V, dtype=float))
    )
    return out if np.ndim(out) else float(out)


def kobayashi_devolatilisation_rates(T, A1=2.0e5, E1=1.046e5, A2=1.3e7, E2=1.674e5):
    r"""Rate constants of the two competing devolatilisation reactions (Kobayashi et al. 1977), 1/s.

    .. math:: k_i = A_i\,e^{-E_i/(R T)},\qquad \frac{dm_c}{dt} = -(k_1 + k_2)\,m_c,\qquad
        \frac{dV}{dt} = (\alpha_1 k_1 + \alpha_2 k_2)\,m_c

    Defaults: Ubhayakar et al. (1976), :math:`A_1 = 2\times10^5` 1/s, :math:`E_1 = 104.6`
    kJ/mol, :math:`A_2 = 1.3\times10^7` 1/s, :math:`E_2 = 167.4` kJ/mol. The two rates cross at
    1809 K: high heating rates give high yields.

    Parameters
    ----------
    T : float or array, K
        Particle temperature.
    A1, A2 : float, 1/s
        Pre-exponential factors.
    E1, E2 : float, J/mol
        Activation energies.

    Returns
    -------
    tuple of (float or ndarray), 1/s
        :math:`(k_1, k_2)`.

    Examples
    --------
    >>> [round(k, 1) for k in kobayashi_devolatilisation_rates(1500.0)]
    [45.6, 19.3]

    References
    ----------
    H. Kobayashi, J.B. Howard, A.F. Sarofim, 16th Symp. (Int.) Combust. (1977) 411-425;
    S.K. Ubhayakar, D.B. Stickler, C.W. von Rosenberg, R.E. Gannon, 16th Symp. (Int.) Combust.
    (1977) 427-436; constants as in mighelone/pkpcoal ``Pyrolysis.py`` and Uintah
    ``KobayashiSarofimDevol.cc``; team source folder reference/cement_lime.md 5.3.
    """
    T = np.asarray(T, dtype=float)
    check_positive("T", T, "K")
    k1 = A1 * np.exp(-E1 / (R_GAS * T))
    k2 = A2 * np.exp(-E2 / (R_GAS * T))
    if T.ndim:
        return k1, k2
    return float(k1), float(k2)


def kobayashi_isothermal_yield(
    T, t, alpha1, alpha2=1.0, A1=2.0e5, E1=1.046e5, A2=1.3e7, E2=1.674e5
):
    r"""Volatile yield of the Kobayashi model at constant temperature, per kg of daf coal.

    .. math:: V(t) = \frac{\alpha_1 k_1 + \alpha_2 k_2}{k_1 + k_2}
        \left(1 - e^{-(k_1 + k_2) t}\right)

    (the exact solution with :math:`m_c(0) = 1`).

    Parameters
    ----------
    T : float, K
        Particle temperature.
    t : float or array, s
        Time, >= 0.
    alpha1 : float, -
        Yield of reaction 1 (the proximate VM_daf in PKP's guess).
    alpha2 : float, -
        Yield of reaction 2 (0.8-1.0 [recalled]).
    A1, A2 : float, 1/s
        Pre-exponential factors.
    E1, E2 : float, J/mol
        Activation energies.

    Returns
    -------
    float or ndarray, -

    Examples
    --------
    >>> round(kobayashi_isothermal_yield(1500.0, 1.0, 0.4, 0.9), 4)
    0.5486

    References
    ----------
    Kobayashi, Howard & Sarofim (1977); team source folder reference/cement_lime.md 5.3.
    """
    check_range("alpha1", alpha1, 0.0, 1.0, closed_low=True, closed_high=True)
    check_range("alpha2", alpha2, 0.0, 1.0, closed_low=True, closed_high=True)
    t = np.asarray(t, dtype=float)
    if not np.all(np.isfinite(t) & (t >= 0)):
        raise InputError("t", t, ">= 0 s")
    k1, k2 = kobayashi_devolatilisation_rates(T, A1, E1, A2, E2)
    out = (alpha1 * k1 + alpha2 * k2) / (k1 + k2) * (1.0 - np.exp(-(k1 + k2) * t))
    return out if out.ndim else float(out)


# --------------------------------------------------------------------------------------------
# Char burn-out
# --------------------------------------------------------------------------------------------

#: OpenFOAM coalChemistryFoam tutorial constants (Baum & Street / Field defaults):
#: C1 kg/(m s Pa K^0.75), C2 kg/(m2 s Pa), E J/mol.
_BS_C1, _BS_C2, _BS_E = 5.0e-12, 0.002, 7.9e4


def baum_street_diffusion_rate_coefficient(d_p, T_p, T_c, C1=_BS_C1):
    r"""Oxygen diffusion rate coefficient to a char particle (Baum & Street 1971), kg/(m2 s Pa).

    .. math:: D_0 = \frac{C_1}{d_p}\left(\frac{T_p + T_c}{2}\right)^{0.75}

    Parameters
    ----------
    d_p : float or array, m
        Particle diameter.
    T_p, T_c : float or array, K
        Particle and carrier-gas temperatures.
    C1 : float, kg/(m s Pa K^0.75)
        Mass diffusion constant (OpenFOAM tutorial 5e-12).

    Returns
    -------
    float or ndarray, kg/(m2 s Pa)

    Examples
    --------
    >>> f"{baum_street_diffusion_rate_coefficient(50e-6, 1500.0, 1500.0):.3g}"
    '2.41e-05'

    References
    ----------
    M.M. Baum, P.J. Street, Combust. Sci. Technol. 3 (1971) 231-243; OpenFOAM-dev
    ``COxidationKineticDiffusionLimitedRate.C`` and tutorial ``simplifiedSiwek``; team source
    folder reference/cement_lime.md 5.4.
    """
    check_positive("d_p", d_p, "m")
    check_positive("T_p", T_p, "K")
    check_positive("T_c", T_c, "K")
    out = C1 / np.asarray(d_p, dtype=float) * (0.5 * (np.asarray(T_p) + np.asarray(T_c))) ** 0.75
    return out if np.ndim(out) else float(out)


def baum_street_kinetic_rate_coefficient(T, C2=_BS_C2, E=_BS_E):
    r"""Kinetic rate coefficient of char oxidation (Baum & Street / Field), kg/(m2 s Pa).

    .. math:: R_k = C_2\,e^{-E/(R T)}

    Parameters
    ----------
    T : float or array, K
        Temperature (OpenFOAM uses the carrier-gas temperature, most textbooks the particle's).
    C2 : float, kg/(m2 s Pa)
        Pre-exponential factor (OpenFOAM tutorial 0.002).
    E : float, J/mol
        Activation energy (OpenFOAM tutorial 7.9e7 J/kmol = 79 kJ/mol).

    Returns
    -------
    float or ndarray, kg/(m2 s Pa)

    Examples
    --------
    >>> f"{baum_street_kinetic_rate_coefficient(1500.0):.3g}"
    '3.55e-06'

    References
    ----------
    Baum & Street (1971); I.W. Smith / M.A. Field defaults as in OpenFOAM-dev tutorial
    ``simplifiedSiwek/constant/coalCloud1Properties``; team source folder
    reference/cement_lime.md 5.4.
    """
    T = np.asarray(T, dtype=float)
    check_positive("T", T, "K")
    out = C2 * np.exp(-E / (R_GAS * T))
    return out if out.ndim else float(out)


def baum_street_char_oxidation_rate(
    d_p, T_p, T_c, p_o2, C1=_BS_C1, C2=_BS_C2, E=_BS_E, kinetic_temperature="carrier"
):
    r"""Char burning rate of one particle, kinetic and diffusion resistances in series, kg/s.

    .. math:: \dot m_C = \pi d_p^2\, p_{O_2}\, \frac{D_0 R_k}{D_0 + R_k}

    with :math:`D_0` (:func:`baum_street_diffusion_rate_coefficient`) and :math:`R_k`
    (:func:`baum_street_kinetic_rate_coefficient`), product CO2 (:math:`S_b = 1`). A 50 um char
    is kinetically limited below about 1500 K and mixed above.

    Parameters
    ----------
    d_p : float or array, m
        Particle diameter.
    T_p, T_c : float or array, K
        Particle and carrier-gas temperatures.
    p_o2 : float or array, Pa
        Oxygen partial pressure far from the particle, >= 0.
    C1 : float, kg/(m s Pa K^0.75)
        Diffusion constant.
    C2 : float, kg/(m2 s Pa)
        Kinetic pre-exponential factor.
    E : float, J/mol
        Activation energy.
    kinetic_temperature : str
        ``"carrier"`` (as OpenFOAM's code) or ``"particle"`` (as most textbooks).

    Returns
    -------
    float or ndarray, kg/s
        Carbon consumed per particle.

    Examples
    --------
    >>> f"{baum_street_char_oxidation_rate(50e-6, 1500.0, 1500.0, 0.05 * 101325.0):.3g}"
    '1.23e-10'

    References
    ----------
    Baum & Street (1971); OpenFOAM-dev ``COxidationKineticDiffusionLimitedRate.C``; team source
    folder reference/cement_lime.md 5.4.
    """
    if kinetic_temperature not in ("carrier", "particle"):
        raise InputError("kinetic_temperature", kinetic_temperature, "one of carrier, particle")
    p = np.asarray(p_o2, dtype=float)
    if not np.all(np.isfinite(p) & (p >= 0)):
        raise InputError("p_o2", p, ">= 0 Pa")
    D0 = baum_street_diffusion_rate_coefficient(d_p, T_p, T_c, C1)
    Rk = baum_street_kinetic_rate_coefficient(
        T_c if kinetic_temperature == "carrier" else T_p, C2, E
    )
    out = math.pi * np.asarray(d_p, dtype=float) ** 2 * p * D0 * Rk / (D0 + Rk)
    return out if np.ndim(out) else float(out)


def baum_street_char_burnout_time(d0, rho_char, T, p_o2, C1=_BS_C1, C2=_BS_C2, E=_BS_E):
    r"""Burn-out time of a char sphere of constant density at constant T and p_O2, s.

    With :func:`baum_street_char_oxidation_rate` (:math:`T_p = T_c = T`) and
    :math:`m = \rho \pi d^3/6`, :math:`\dot d = -2 p_{O_2}/(\rho (1/R_k + d/(C_1 T^{0.75})))`, so

    .. math:: t_b = \frac{\rho\, d_0}{2\, p_{O_2} R_k} + \frac{\rho\, d_0^2}{4\, p_{O_2} C_1 T^{0.75}}
        = t_{kinetic} + t_{diffusion}

    Parameters
    ----------
    d0 : float or array, m
        Initial char diameter.
    rho_char : float, kg/m3
        Char (apparent) density, constant (shrinking sphere).
    T : float, K
        Particle and gas temperature.
    p_o2 : float, Pa
        Oxygen partial pressure, > 0.
    C1 : float, kg/(m s Pa K^0.75)
        Diffusion constant.
    C2 : float, kg/(m2 s Pa)
        Kinetic pre-exponential factor.
    E : float, J/mol
        Activation energy.

    Returns
    -------
    float or ndarray, s

    Examples
    --------
    >>> round(baum_street_char_burnout_time(50e-6, 1000.0, 1500.0, 0.05 * 101325.0), 3)
    1.493

    References
    ----------
    Rate of Baum & Street (1971) as in OpenFOAM-dev; integration DERIVED here; team source
    folder reference/cement_lime.md 5.4.
    """
    check_positive("d0", d0, "m")
    check_positive("rho_char", rho_char, "kg/m3")
    check_positive("p_o2", p_o2, "Pa")
    Rk = baum_street_kinetic_rate_coefficient(T, C2, E)
    d0 = np.asarray(d0, dtype=float)
    out = rho_char * d0 / (2.0 * p_o2 * Rk) + rho_char * d0**2 / (
        4.0 * p_o2 * C1 * np.asarray(T, dtype=float) ** 0.75
    )
    return out if np.ndim(out) else float(out)
