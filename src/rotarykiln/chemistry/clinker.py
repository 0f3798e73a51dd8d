r"""Cement clinker chemistry: raw meal, moduli, Bogue and Taylor phases, Lea-Parker liquid, heats.

- :class:`RawMeal`: a raw meal (or a clinker) by its oxides CaO, SiO2, Al2O3, Fe2O3, MgO, SO3,
  K2O, Na2O, the unanalysed rest and the loss on ignition, as mass fractions on a stated basis
  (as received, or ignited = LOI-free), checked to sum to 1.
- The moduli: lime saturation factor (British-standard, 1.18 and Lea-Parker forms), silica and
  alumina ratios, and the refusal of an oxide composition outside any cement or lime practice
  (:func:`check_oxide_practice`, ranges and sources in ``data/clinker/models.yaml``).
- The potential phase composition of Bogue (1929), both equation sets (A/F >= 0.64 and < 0.64),
  with coefficients computed from the oxide molar masses, and Taylor's (1989) modified Bogue with
  the average phase compositions SimCem uses.
- The Lea & Parker (1934) liquid fraction at 1338, 1400 and 1450 degC.
- The clinker-phase thermodynamic functions of the SimCem database (``data/clinker/
  thermodynamic_data.yaml``): :math:`c_p, H, S, G` of a phase, reaction enthalpies and Gibbs
  energies, the theoretical heat of clinker formation.
- The stoichiometry of the five clinker-forming reactions and their mass-action rate form
  (Mastorakos et al. 1999), whose constants must be supplied.

Mass fractions are fractions (0.65, not 65 %); temperatures K; enthalpies J/mol or J/kg.
Reference note: team source folder reference/cement_lime.md sections 0-3.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np
import yaml

from rotarykiln.errors import InputError, check_positive, warn_out_of_range

__all__ = [
    "CLINKER_PHASES",
    "ClinkerReport",
    "OXIDES",
    "R_GAS",
    "RawMeal",
    "alumina_ratio",
    "bed_oxide_flows",
    "bogue_coefficients",
    "bogue_phase_composition",
    "carbonate_co2_per_clinker",
    "check_oxide_practice",
    "clinker_reaction_stoichiometry",
    "clinker_report",
    "element_molar_mass",
    "lea_parker_liquid_curve",
    "lea_parker_liquid_fraction",
    "lea_parker_lsf_coefficients",
    "lea_parker_melt_fraction",
    "lime_saturation_factor",
    "mastorakos_clinker_rates",
    "mastorakos_recalled_parameters",
    "molar_mass",
    "silica_ratio",
    "simcem_phase_cp",
    "simcem_phase_enthalpy",
    "simcem_phase_entropy",
    "simcem_phase_gibbs",
    "simcem_reaction_enthalpy",
    "simcem_reaction_gibbs",
    "taylor_phase_composition",
    "taylor_phase_table",
    "theoretical_heat_of_clinker_formation",
]

#: Molar gas constant, J/(mol K).
R_GAS = 8.314462618

#: The oxides of a raw meal analysis, in the order used throughout.
OXIDES = ("CaO", "SiO2", "Al2O3", "Fe2O3", "MgO", "SO3", "K2O", "Na2O")

_DATA = Path(__file__).resolve().parent.parent / "data" / "clinker"
_T25 = 298.15


@lru_cache(maxsize=4)
def _load(name: str) -> dict:
    with open(_DATA / name, encoding="utf-8") as fh:
        return yaml.safe_load(fh)


def _oxide_data() -> dict:
    return _load("oxides.yaml")


def _models() -> dict:
    return _load("models.yaml")


def _thermo() -> dict:
    return _load("thermodynamic_data.yaml")


def element_molar_mass(element: str) -> float:
    """Atomic weight of ``element`` (IUPAC 2021, ``data/clinker/oxides.yaml``), kg/mol."""
    weights = _oxide_data()["atomic_weights"]
    if element not in weights:
        raise InputError("element", element, "one of " + ", ".join(weights))
    return weights[element] / 1000.0


def molar_mass(formula):
    """Molar mass of an oxide or of an oxide combination, kg/mol.

    Parameters
    ----------
    formula : str or mapping
        An oxide name of ``data/clinker/oxides.yaml`` (``"CaO"``), a phase of the thermodynamic
        database (``"C3S"``, ``"CaCO3"``) or a mapping oxide -> moles (``{"CaO": 3, "SiO2": 1}``).

    Returns
    -------
    float, kg/mol

    Examples
    --------
    >>> round(molar_mass("Al2O3") * 1000, 3)
    101.96
    >>> round(molar_mass("C3S") * 1000, 3)
    228.314

    References
    ----------
    IUPAC CIAAW standard atomic weights 2021 (``data/clinker/oxides.yaml``).
    """
    data = _oxide_data()
    weights, oxides = data["atomic_weights"], data["oxides"]
    if isinstance(formula, str):
        if formula in oxides:
            return sum(weights[el] * n for el, n in oxides[formula]["elements"].items()) / 1000.0
        phases = _thermo()["phases"]
        if formula in phases:
            return molar_mass(phases[formula]["oxides"])
        raise InputError(
            "formula", formula, "an oxide or phase: " + ", ".join(list(oxides) + list(phases))
        )
    return float(sum(molar_mass(ox) * n for ox, n in formula.items()))


# --------------------------------------------------------------------------------------------
# Raw meal
# --------------------------------------------------------------------------------------------

_BASES = ("as_received", "ignited")


@dataclass(frozen=True)
class RawMeal:
    """A raw meal or a clinker by its oxides and loss on ignition, mass fractions on a basis.

    ``basis="as_received"``: the eight oxides, ``other`` (the unanalysed rest: TiO2, P2O5, Mn2O3
    ...) and ``loi`` sum to 1. ``basis="ignited"`` (LOI-free, the clinker basis): the eight oxides
    and ``other`` sum to 1 and ``loi`` is the ignition loss of the as-received meal. Refused (one
    line naming the basis) when the sum is off 1 by more than ``sum_tolerance`` (default 0.005:
    ten entries rounded to 0.1 % add up to at most +-0.5 %).

    Attributes
    ----------
    CaO, SiO2, Al2O3, Fe2O3, MgO, SO3, K2O, Na2O : float, -
        Oxide mass fractions on ``basis``, in [0, 1].
    other : float, -
        Unanalysed rest on ``basis``.
    loi : float, -
        Loss on ignition, fraction of the as-received mass, in [0, 1).
    basis : str
        ``"as_received"`` or ``"ignited"``.
    sum_tolerance : float, -
        Accepted absolute deviation of the sum from 1.

    Examples
    --------
    >>> meal = RawMeal(CaO=0.65, SiO2=0.22, Al2O3=0.055, Fe2O3=0.033, MgO=0.017, other=0.025,
    ...                loi=0.346, basis="ignited")
    >>> round(meal.clinker_factor, 3)
    1.529
    >>> round(meal.moduli()["SM"], 3)
    2.5

    References
    ----------
    Loss on ignition and raw-meal-to-clinker factor: team source folder reference/cement_lime.md
    section 1.1.
    """

    CaO: float
    SiO2: float
    Al2O3: float
    Fe2O3: float
    MgO: float = 0.0
    SO3: float = 0.0
    K2O: float = 0.0
    Na2O: float = 0.0
    other: float = 0.0
    loi: float = 0.0
    basis: str = "as_received"
    sum_tolerance: float = 0.005

    def __post_init__(self):
        if self.basis not in _BASES:
            raise InputError("raw_meal.basis", self.basis, "one of as_received, ignited")
        for name in (*OXIDES, "other"):
            _check_fraction(f"raw_meal.{name}", getattr(self, name))
        v = float(self.loi)
        if not (math.isfinite(v) and 0.0 <= v < 1.0):
            raise InputError("raw_meal.loi", v, "in [0, 1) (a fraction of the as-received mass)")
        if not (math.isfinite(self.sum_tolerance) and 0.0 <= self.sum_tolerance < 0.1):
            raise InputError("raw_meal.sum_tolerance", self.sum_tolerance, "in [0, 0.1)")
        total = sum(getattr(self, n) for n in (*OXIDES, "other"))
        if self.basis == "as_received":
            total += self.loi
            what = "raw_meal (as-received basis: oxides + other + loi)"
        else:
            what = "raw_meal (ignited, LOI-free basis: oxides + other)"
        if abs(total - 1.0) > self.sum_tolerance:
            raise InputError(
                what,
                f"sum {total:.6g}",
                f"1 +- {self.sum_tolerance:g} (give the unanalysed rest as `other`)",
            )

    @property
    def ignited(self) -> dict[str, float]:
        """Oxides and ``other`` on the ignited (LOI-free, clinker) basis, mass fractions."""
        f = 1.0 / (1.0 - self.loi) if self.basis == "as_received" else 1.0
        return {n: getattr(self, n) * f for n in (*OXIDES, "other")}

    @property
    def as_received(self) -> dict[str, float]:
        """Oxides, ``other`` and ``loi`` on the as-received basis, mass fractions."""
        f = (1.0 - self.loi) if self.basis == "ignited" else 1.0
        out = {n: getattr(self, n) * f for n in (*OXIDES, "other")}
        out["loi"] = self.loi
        return out

    @property
    def clinker_factor(self) -> float:
        """Raw meal per clinker with ash-free fuel, 1/(1 - LOI), kg/kg."""
        return 1.0 / (1.0 - self.loi)

    def moduli(self, lsf_definition: str = "british_standard") -> dict[str, float]:
        """LSF, SM and AM of the ignited composition (see :func:`lime_saturation_factor`)."""
        x = self.ignited
        return {
            "LSF": float(
                lime_saturation_factor(
                    x["CaO"], x["SiO2"], x["Al2O3"], x["Fe2O3"], definition=lsf_definition
                )
            ),
            "SM": float(silica_ratio(x["SiO2"], x["Al2O3"], x["Fe2O3"])),
            "AM": float(alumina_ratio(x["Al2O3"], x["Fe2O3"])),
        }

    def bogue(self, free_lime: float = 0.0) -> dict[str, float]:
        """Bogue potential phases of the ignited composition (see :func:`bogue_phase_composition`)."""
        x = self.ignited
        return bogue_phase_composition(
            x["CaO"], x["SiO2"], x["Al2O3"], x["Fe2O3"], SO3=x["SO3"], free_lime=free_lime
        )

    def check_practice(self, practice: str = "cement") -> None:
        """Refuse the meal if its moduli are outside ``practice`` (:func:`check_oxide_practice`)."""
        x = self.ignited
        check_oxide_practice(
            x["CaO"], x["SiO2"], x["Al2O3"], x["Fe2O3"], x["MgO"], practice=practice
        )


def _check_fraction(field, value):
    v = float(value)
    if not (math.isfinite(v) and 0.0 <= v <= 1.0):
        raise InputError(field, v, "a mass fraction in [0, 1] (not a percentage)")


# --------------------------------------------------------------------------------------------
# Moduli
# --------------------------------------------------------------------------------------------

_LSF_FIXED = {"british_standard": (2.8, 1.2, 0.65), "alternative_1.18": (2.8, 1.18, 0.65)}


def lea_parker_lsf_coefficients(alumina_ratio_value):
    r"""Coefficients of the Lea-Parker lime saturation limit, from Bogue's C2S = 0.

    .. math:: LSF = \frac{C}{c_S S + c_A A + c_F F}, \qquad
        (c_S, c_A, c_F) = -\frac{(B_{C_2S,S}, B_{C_2S,A}, B_{C_2S,F})}{B_{C_2S,C}}

    with :math:`B` the Bogue coefficients (:func:`bogue_coefficients`) of the set that applies:
    2.800/1.650/0.351 for A/F >= 0.64, 2.800/1.100/0.702 below.

    Parameters
    ----------
    alumina_ratio_value : float
        A/F mass ratio, dimensionless, > 0.

    Returns
    -------
    tuple of float, -
        :math:`(c_S, c_A, c_F)`.

    Examples
    --------
    >>> [round(c, 3) for c in lea_parker_lsf_coefficients(1.6)]
    [2.8, 1.65, 0.351]
    >>> [round(c, 3) for c in lea_parker_lsf_coefficients(0.5)]
    [2.8, 1.1, 0.702]

    References
    ----------
    F.M. Lea, T.W. Parker, Phil. Trans. R. Soc. A 234 (1935) 1-41 (as reproduced in Lea's
    Chemistry of Cement and Concrete); derivation from the Bogue equations, cemnet forum thread
    108168; team source folder reference/cement_lime.md section 1.1.
    """
    check_positive("alumina_ratio", alumina_ratio_value)
    B = bogue_coefficients(low_alumina=alumina_ratio_value < _c4af_ratio())
    row = B[1]
    return tuple(float(-row[j] / row[0]) for j in (1, 2, 3))


def lime_saturation_factor(CaO, SiO2, Al2O3, Fe2O3, SO3=0.0, definition="british_standard"):
    r"""Lime saturation factor of a clinker or an ignited raw meal.

    .. math:: LSF = \frac{C - 0.7\,\bar{S}}{2.8\,S + c_A A + c_F F}

    ``definition``: ``"british_standard"`` (c_A = 1.2, c_F = 0.65), ``"alternative_1.18"``
    (1.18, 0.65) or ``"lea_parker"`` (1.65, 0.35 for A/F >= 0.64; 1.1, 0.7 below; computed by
    :func:`lea_parker_lsf_coefficients`). The SO3 correction 0.7005 = M(CaO)/M(SO3) applies to
    cements (give SO3 = 0 for a raw meal).

    Parameters
    ----------
    CaO, SiO2, Al2O3, Fe2O3 : float or array, -
        Mass fractions (any common basis).
    SO3 : float or array, -
        SO3 mass fraction.
    definition : str
        One of ``british_standard``, ``alternative_1.18``, ``lea_parker``.

    Returns
    -------
    float or ndarray, -

    Notes
    -----
    Typical kiln feeds have LSF 0.92-0.98; above 1 free lime is inevitable.

    Examples
    --------
    >>> round(lime_saturation_factor(0.65, 0.22, 0.055, 0.033), 4)
    0.924
    >>> round(lime_saturation_factor(0.65, 0.22, 0.055, 0.033, definition="lea_parker"), 4)
    0.9049

    References
    ----------
    understanding-cement.com/parameters.html (BS form and SO3 correction); vdchari.com and
    cemnet forum 108168 (the 1.18 form); Lea & Parker (1935); team source folder
    reference/cement_lime.md section 1.1.
    """
    C, S, A, F = (np.asarray(v, dtype=float) for v in (CaO, SiO2, Al2O3, Fe2O3))
    sbar = np.asarray(SO3, dtype=float)
    if definition in _LSF_FIXED:
        cS, cA, cF = _LSF_FIXED[definition]
        den = cS * S + cA * A + cF * F
    elif definition == "lea_parker":
        with np.errstate(divide="ignore", invalid="ignore"):
            am = A / F
        hi = lea_parker_lsf_coefficients(1.0)
        lo = lea_parker_lsf_coefficients(0.5)
        high = am >= _c4af_ratio()
        den = np.where(high, hi[0] * S + hi[1] * A + hi[2] * F, lo[0] * S + lo[1] * A + lo[2] * F)
    else:
        raise InputError(
            "definition", definition, "one of british_standard, alternative_1.18, lea_parker"
        )
    with np.errstate(divide="ignore", invalid="ignore"):
        out = (C - _so3_lime() * sbar) / den
    return out if out.ndim else float(out)


def silica_ratio(SiO2, Al2O3, Fe2O3):
    r"""Silica modulus (ratio) :math:`SM = S/(A + F)`.

    Parameters
    ----------
    SiO2, Al2O3, Fe2O3 : float or array, -
        Mass fractions.

    Returns
    -------
    float or ndarray, -
        Typical 2.3-2.7; a high SM means less melt.

    Examples
    --------
    >>> round(silica_ratio(0.22, 0.055, 0.033), 3)
    2.5

    References
    ----------
    understanding-cement.com; cementops.io (team source folder reference/cement_lime.md 1.1).
    """
    S, A, F = (np.asarray(v, dtype=float) for v in (SiO2, Al2O3, Fe2O3))
    with np.errstate(divide="ignore", invalid="ignore"):
        out = S / (A + F)
    return out if out.ndim else float(out)


def alumina_ratio(Al2O3, Fe2O3):
    r"""Alumina modulus (ratio) :math:`AM = A/F`.

    Parameters
    ----------
    Al2O3, Fe2O3 : float or array, -
        Mass fractions.

    Returns
    -------
    float or ndarray, -
        Typical 1.3-1.8; 0.64 is the A/F of C4AF (Bogue's switch of equation set).

    Examples
    --------
    >>> round(alumina_ratio(0.055, 0.033), 3)
    1.667

    References
    ----------
    cementops.io; germancement.ge (team source folder reference/cement_lime.md 1.1).
    """
    A, F = np.asarray(Al2O3, dtype=float), np.asarray(Fe2O3, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = A / F
    return out if out.ndim else float(out)


def check_oxide_practice(CaO, SiO2, Al2O3, Fe2O3, MgO=0.0, practice="cement", field="raw_meal"):
    """Refuse an ignited oxide composition whose moduli are outside cement or lime practice.

    ``practice="cement"``: LSF (British-standard form) in [0.66, 1.10], SM in [1, 8], AM in
    [0.2, 50] (refused outside), with an :class:`~rotarykiln.errors.OutOfRangeWarning` outside the
    typical LSF 0.92-0.98, SM 2.3-2.7, AM 1.3-1.8. ``practice="lime"``: LSF >= 1.10 and
    CaO + MgO >= 0.60. ``practice="any"``: accepted if either is. Each bound, and where it comes
    from, is in ``data/clinker/models.yaml`` (``practice``).

    Raises
    ------
    InputError
        One line: ``raw_meal.LSF: 1.52 is not in [0.66, 1.1] (cement practice: ...)``.

    Examples
    --------
    >>> check_oxide_practice(0.65, 0.22, 0.055, 0.033)
    >>> check_oxide_practice(0.65, 0.05, 0.055, 0.033)
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: raw_meal.LSF: 2.8578 is not in [0.66, 1.1] (cement practice; \
the bounds and their sources are in data/clinker/models.yaml)
    """
    if practice not in ("cement", "lime", "any"):
        raise InputError(f"{field}.practice", practice, "one of cement, lime, any")
    if practice == "any":
        try:
            check_oxide_practice(CaO, SiO2, Al2O3, Fe2O3, MgO, "cement", field)
        except InputError as cement_error:
            try:
                check_oxide_practice(CaO, SiO2, Al2O3, Fe2O3, MgO, "lime", field)
            except InputError:
                raise cement_error from None
        return
    values = {
        "LSF": float(lime_saturation_factor(CaO, SiO2, Al2O3, Fe2O3)),
        "SM": float(silica_ratio(SiO2, Al2O3, Fe2O3)),
        "AM": float(alumina_ratio(Al2O3, Fe2O3)),
        "CaO_plus_MgO": float(CaO) + float(MgO),
    }
    spec = _models()["practice"][practice]
    for name, rng in spec["envelope"].items():
        lo, hi = (float(v) for v in rng["range"])
        v = values[name]
        if not (math.isfinite(v) and lo <= v <= hi) and not (v == math.inf and hi == math.inf):
            raise InputError(
                f"{field}.{name}",
                f"{v:.5g}",
                f"in [{lo:g}, {hi:g}] ({practice} practice; the bounds and their sources are in "
                "data/clinker/models.yaml)",
            )
    for name, rng in spec.get("typical", {}).items():
        lo, hi = rng["range"]
        warn_out_of_range(f"{field}.{name}", values[name], lo, hi, rng["source"])


# --------------------------------------------------------------------------------------------
# Bogue and Taylor
# --------------------------------------------------------------------------------------------

_BOGUE_OXIDES = ("CaO", "SiO2", "Al2O3", "Fe2O3")
_BOGUE_PHASES = ("C3S", "C2S_beta", "C3A", "C4AF")
_BOGUE_PHASES_LOW = ("C3S", "C2S_beta", "C4AF", "C2F")


def _mass_matrix(phases) -> np.ndarray:
    """Mass fraction of each Bogue oxide (columns) in each phase (rows)."""
    th = _thermo()["phases"]
    M = np.zeros((len(phases), 4))
    for i, ph in enumerate(phases):
        ox = th[ph]["oxides"]
        mph = molar_mass(ox)
        for j, o in enumerate(_BOGUE_OXIDES):
            M[i, j] = ox.get(o, 0.0) * molar_mass(o) / mph
    return M


def _c4af_ratio() -> float:
    return molar_mass("Al2O3") / molar_mass("Fe2O3")


def _so3_lime() -> float:
    return molar_mass("CaO") / molar_mass("SO3")


def bogue_coefficients(low_alumina=False):
    r"""Bogue's coefficients: phase mass = B @ (C, S, A, F), from the oxide molar masses.

    The pure phases' oxide mass fractions form a 4x4 matrix :math:`M` (rows C3S, C2S, C3A, C4AF;
    columns CaO, SiO2, Al2O3, Fe2O3); :math:`B = (M^T)^{-1}`. With ``low_alumina`` (A/F < 0.64)
    the phases are C3S, C2S, C4AF, C2F (no C3A).

    Parameters
    ----------
    low_alumina : bool
        Use the A/F < 0.64 set.

    Returns
    -------
    ndarray (4, 4), -
        Rows: phases; columns: CaO, SiO2, Al2O3, Fe2O3.

    Examples
    --------
    >>> np.round(bogue_coefficients()[0], 4).tolist()
    [4.0714, -7.6, -6.7177, -1.4298]

    References
    ----------
    R.H. Bogue, Ind. Eng. Chem. Anal. Ed. 1 (1929) 192; H.F.W. Taylor, Cement Chemistry, 2nd ed.
    (1997) section 4.4; team source folder reference/cement_lime.md section 1.2.
    """
    phases = _BOGUE_PHASES_LOW if low_alumina else _BOGUE_PHASES
    return np.linalg.inv(_mass_matrix(phases).T)


def bogue_phase_composition(CaO, SiO2, Al2O3, Fe2O3, SO3=0.0, free_lime=0.0):
    r"""Bogue's potential phase composition of a clinker, mass fractions.

    .. math::
        C_3S &= 4.0714\,C' - 7.6000\,S - 6.7178\,A - 1.4298\,F \\
        C_2S &= 2.8667\,S - 0.7544\,C_3S \\
        C_3A &= 2.6500\,A - 1.6920\,F, \qquad C_4AF = 3.0432\,F

    for A/F >= 0.64, with :math:`C' = C - 0.7005\,\bar{S} - C_{free}`. For A/F < 0.64 all A goes
    to C4AF and the excess F to C2F (C3A = 0). The coefficients are computed from the molar
    masses (:func:`bogue_coefficients`). The result is linear: the phases sum to
    C' + S + A + F for any input, and a phase is negative when the input is outside its
    assumptions (C2S < 0: LSF above the Lea-Parker limit, give the free lime).

    Parameters
    ----------
    CaO, SiO2, Al2O3, Fe2O3 : float, -
        Clinker oxide mass fractions.
    SO3 : float, -
        SO3 mass fraction (its lime equivalent is subtracted: calcium sulphate).
    free_lime : float, -
        Free CaO mass fraction, subtracted from CaO and returned as ``CaO_free``.

    Returns
    -------
    dict of float, -
        ``C3S``, ``C2S``, ``C3A``, ``C4AF``, ``C2F``, ``CaO_free``.

    Examples
    --------
    >>> p = bogue_phase_composition(0.65, 0.22, 0.055, 0.033)
    >>> {k: round(v * 100, 2) for k, v in p.items()}
    {'C3S': 55.78, 'C2S': 20.99, 'C3A': 8.99, 'C4AF': 10.04, 'C2F': 0.0, 'CaO_free': 0.0}

    References
    ----------
    R.H. Bogue, Calculation of the compounds in Portland cement, Ind. Eng. Chem. Anal. Ed. 1
    (1929) 192-197; H.F.W. Taylor, Cement Chemistry, 2nd ed. (1997) section 4.4; team source
    folder reference/cement_lime.md section 1.2.
    """
    for name, v in (
        ("CaO", CaO),
        ("SiO2", SiO2),
        ("Al2O3", Al2O3),
        ("Fe2O3", Fe2O3),
        ("SO3", SO3),
        ("free_lime", free_lime),
    ):
        _check_fraction(name, v)
    if Fe2O3 <= 0.0:
        raise InputError("Fe2O3", Fe2O3, "> 0 (Bogue's phases need iron: C4AF)")
    C = CaO - _so3_lime() * SO3 - free_lime
    b = np.array([C, SiO2, Al2O3, Fe2O3])
    low = Al2O3 / Fe2O3 < _c4af_ratio()
    p = bogue_coefficients(low) @ b
    if low:
        out = {"C3S": p[0], "C2S": p[1], "C3A": 0.0, "C4AF": p[2], "C2F": p[3]}
    else:
        out = {"C3S": p[0], "C2S": p[1], "C3A": p[2], "C4AF": p[3], "C2F": 0.0}
    out = {k: float(v) for k, v in out.items()}
    out["CaO_free"] = float(free_lime)
    return out


def taylor_phase_table():
    """Mass compositions of Taylor's alite, belite, aluminate and ferrite (SimCem's rows).

    Returns
    -------
    dict
        ``oxides`` (tuple of names) and, per phase, an array of oxide mass fractions, -.

    Examples
    --------
    >>> t = taylor_phase_table()
    >>> round(float(t["alite"][0]) * 100, 1), round(float(t["alite"][1]) * 100, 1)
    (71.6, 25.2)

    References
    ----------
    H.F.W. Taylor, Adv. Cem. Res. 2 (1989) 73-77, as the molar rows of SimCem's
    ``taylor_calculation`` (``data/clinker/models.yaml``).
    """
    t = _models()["taylor_phase_compositions"]
    oxides = tuple(t["oxides"])
    M = np.array([molar_mass(o) for o in oxides])
    out: dict = {"oxides": oxides}
    for ph in ("alite", "belite", "aluminate", "ferrite"):
        m = np.asarray(t[ph], dtype=float) * M
        out[ph] = m / m.sum()
    return out


def taylor_phase_composition(oxides):
    r"""Taylor's modified Bogue: phase masses from the average compositions of the real phases.

    Least squares over the oxides of :func:`taylor_phase_table`:

    .. math:: \min_w \Big\| \sum_p w_p\,\mathbf{c}_p - \mathbf{b} \Big\|_2

    with :math:`\mathbf{c}_p` the oxide mass fractions of alite, belite, aluminate and ferrite
    (Taylor 1989, as SimCem's rows) and :math:`\mathbf{b}` the clinker's oxide mass fractions.
    This is SimCem's pseudo-inverse approach, written in mass (SimCem's weighting of the least
    squares was not determined); Taylor's own procedure allocates the sulphates first and solves
    four equations, so expect differences of a few %. With only the four Bogue oxides and pure
    phases it reduces to Bogue.

    Parameters
    ----------
    oxides : mapping
        Oxide name -> mass fraction, - (CaO, SiO2, Al2O3, Fe2O3, MgO, SO3, Na2O, P2O5, K2O,
        TiO2, Mn2O3; missing ones are 0, others refused).

    Returns
    -------
    dict of float, -
        ``alite``, ``belite``, ``aluminate``, ``ferrite``.

    Examples
    --------
    >>> w = taylor_phase_composition({"CaO": 0.65, "SiO2": 0.22, "Al2O3": 0.055,
    ...                               "Fe2O3": 0.033, "MgO": 0.017})
    >>> round(w["alite"], 2), round(w["belite"], 2)
    (0.63, 0.17)

    References
    ----------
    H.F.W. Taylor, Modification of the Bogue calculation, Adv. Cem. Res. 2 (1989) 73-77;
    SimCem ``pysrc/simcem/clinker.py`` (``taylor_calculation``); team source folder
    reference/cement_lime.md section 1.3.
    """
    table = taylor_phase_table()
    names = table["oxides"]
    unknown = set(oxides) - set(names)
    if unknown:
        raise InputError("oxides", sorted(unknown)[0], "one of " + ", ".join(names))
    for k, v in oxides.items():
        _check_fraction(f"oxides.{k}", v)
    b = np.array([float(oxides.get(n, 0.0)) for n in names])
    A = np.column_stack([table[p] for p in ("alite", "belite", "aluminate", "ferrite")])
    w, *_ = np.linalg.lstsq(A, b, rcond=None)
    return {
        p: float(x) for p, x in zip(("alite", "belite", "aluminate", "ferrite"), w, strict=True)
    }


# --------------------------------------------------------------------------------------------
# Lea-Parker liquid
# --------------------------------------------------------------------------------------------


def lea_parker_liquid_fraction(Al2O3, Fe2O3, MgO=0.0, K2O=0.0, Na2O=0.0, T=1723.15, mgo_max=None):
    r"""Liquid (melt) fraction of a clinker at 1338, 1400 or 1450 degC (Lea & Parker 1934).

    .. math::
        L_{1450} &= 3.0\,A + 2.25\,F + M + K + N \\
        L_{1400} &= 2.95\,A + 2.2\,F + M + K + N \\
        L_{1338} &= 6.1\,F + M + K + N \quad (A/F \ge 1.38), \qquad
        8.2\,A - 5.22\,F + M + K + N \quad (A/F < 1.38)

    Parameters
    ----------
    Al2O3, Fe2O3, MgO, K2O, Na2O : float or array, -
        Clinker mass fractions.
    T : float, K
        1611.15 (1338 degC), 1673.15 (1400 degC) or 1723.15 (1450 degC), +-0.5 K.
    mgo_max : float or None, -
        Cap on the MgO counted (Lea-Parker count MgO up to about 0.02 [recalled]); None: all.

    Returns
    -------
    float or ndarray, -
        Liquid mass fraction of the clinker.

    Notes
    -----
    The 1450 degC coefficients were read (cemnet forum 107775, which adds SO3 when the alkalis
    are sulphated); those at 1400 and 1338 degC are recalled and unverified (reference note
    section 2, [MEMORY]). Valid for clinkers in the C3S-C2S-C3A-C4AF field.

    Examples
    --------
    >>> round(lea_parker_liquid_fraction(0.055, 0.033, 0.017) * 100, 2)
    25.63

    References
    ----------
    F.M. Lea, T.W. Parker, Investigations on a portion of the quaternary system
    CaO-Al2O3-SiO2-Fe2O3, Phil. Trans. R. Soc. A 234 (1934/35) 1-41 [journal details recalled];
    cemnet forum thread 107775; team source folder reference/cement_lime.md section 2.
    """
    A, F, M, K, N = (np.asarray(v, dtype=float) for v in (Al2O3, Fe2O3, MgO, K2O, Na2O))
    for name, v in (("Al2O3", A), ("Fe2O3", F), ("MgO", M), ("K2O", K), ("Na2O", N)):
        if not np.all(np.isfinite(v) & (v >= 0.0) & (v <= 1.0)):
            raise InputError(name, v, "a mass fraction in [0, 1]")
    if mgo_max is not None:
        M = np.minimum(M, mgo_max)
    co = _models()["lea_parker_liquid"]
    for key, c in co.items():  # noqa: B007 (key is used after the loop)
        if abs(float(T) - c["T_K"]) <= 0.5:
            break
    else:
        raise InputError(
            "T", f"{float(T):g} K", "one of 1611.15, 1673.15, 1723.15 K (1338, 1400, 1450 degC)"
        )
    rest = M + K + N
    if key == "1338":
        with np.errstate(divide="ignore", invalid="ignore"):
            high = A / F >= c["AM_split"]
        hi, lo = c["high_AM"], c["low_AM"]
        L = np.where(high, hi["a_A"] * A + hi["a_F"] * F, lo["a_A"] * A + lo["a_F"] * F) + rest
    else:
        L = c["a_A"] * A + c["a_F"] * F + rest
    return L if L.ndim else float(L)


def lea_parker_liquid_curve(T, Al2O3, Fe2O3, MgO=0.0, K2O=0.0, Na2O=0.0):
    r"""Liquid fraction against temperature, piecewise linear through the Lea-Parker points.

    Zero below the 1338 degC invariant point (1611.15 K), where the liquid appears at once;
    linear between :math:`L_{1338}`, :math:`L_{1400}` and :math:`L_{1450}`
    (:func:`lea_parker_liquid_fraction`), constant above 1450 degC. A modelling convention of
    1-D kiln models (Mastorakos 1999, Mujumdar 2006 [recalled]), not a phase diagram: the melt of
    commercial mixes with MgO and alkalis appears from about 1250-1280 degC.

    Parameters
    ----------
    T : float or array, K
        Temperature.
    Al2O3, Fe2O3, MgO, K2O, Na2O : float, -
        Clinker mass fractions.

    Returns
    -------
    float or ndarray, -
        Liquid mass fraction.

    Examples
    --------
    >>> round(lea_parker_liquid_curve(1698.15, 0.055, 0.033, 0.017) * 100, 2)
    25.41

    References
    ----------
    Lea & Parker (1934/35); team source folder reference/cement_lime.md section 2.
    """
    T = np.asarray(T, dtype=float)
    check_positive("T", T, "K")
    Tk = np.array([1611.15, 1673.15, 1723.15])
    Lk = np.array(
        [float(lea_parker_liquid_fraction(Al2O3, Fe2O3, MgO, K2O, Na2O, T=t)) for t in Tk]
    )
    L = np.where(T < Tk[0], 0.0, np.interp(T, Tk, Lk))
    return L if L.ndim else float(L)


# --------------------------------------------------------------------------------------------
# SimCem thermodynamic database
# --------------------------------------------------------------------------------------------


def _entry(phase: str, source: str | None) -> dict:
    phases = _thermo()["phases"]
    if phase not in phases:
        raise InputError("phase", phase, "one of " + ", ".join(phases))
    srcs = phases[phase]["sources"]
    if source is None:
        if len(srcs) > 1:
            raise InputError(
                f"{phase}.source", "not given", "one of " + ", ".join(srcs) + " (several exist)"
            )
        source = next(iter(srcs))
    if source not in srcs:
        raise InputError(f"{phase}.source", source, "one of " + ", ".join(srcs))
    return srcs[source]


def _coeffs(e: dict):
    cp = e["cp"]
    return tuple(float(cp.get(k, 0.0)) for k in "abcdeg")


def _entry_at(phase, source, T):
    """The database entry of ``phase`` and the checked temperature array ``T`` (a warning
    outside the fit's range)."""
    e = _entry(phase, source)
    T = np.asarray(T, dtype=float)
    check_positive("T", T, "K")
    off_ref = T[T != e["T0"]] if T.ndim else (T if T != e["T0"] else np.array([]))
    if np.size(off_ref):
        warn_out_of_range(
            f"T ({phase}, {source or 'database'})",
            off_ref,
            e["T_min"],
            e["T_max"],
            "the SimCem database fit",
        )
    return e, T


def simcem_phase_cp(phase, T, source=None):
    r"""Molar heat capacity of a phase from the SimCem database, J/(mol K).

    .. math:: c_p = a + bT + c/T^2 + d/\sqrt{T} + eT^2 + gT^3

    Parameters
    ----------
    phase : str
        A phase of ``data/clinker/thermodynamic_data.yaml`` (``C3S``, ``C2S_beta``, ``CaO`` ...).
    T : float or array, K
        Temperature.
    source : str or None
        Database source (``NIST``, ``HP2011``, ``NASA_GLENN`` ...); required when the phase has
        several.

    Returns
    -------
    float or ndarray, J/(mol K)

    Examples
    --------
    >>> round(simcem_phase_cp("C3S", 350.0), 1)
    183.9

    References
    ----------
    SimCem 1.0.0 ``free_database.xml`` (team source folder reference/cement_lime.md 0.1).
    """
    e, T = _entry_at(phase, source, T)
    a, b, c, d, ee, g = _coeffs(e)
    cp = a + b * T + c / T**2 + d / np.sqrt(T) + ee * T**2 + g * T**3
    return cp if cp.ndim else float(cp)


def _h_s(e: dict, T: np.ndarray):
    a, b, c, d, ee, g = _coeffs(e)
    T0 = float(e["T0"])
    dH = (
        a * (T - T0)
        + b / 2 * (T**2 - T0**2)
        - c * (1 / T - 1 / T0)
        + 2 * d * (np.sqrt(T) - math.sqrt(T0))
        + ee / 3 * (T**3 - T0**3)
        + g / 4 * (T**4 - T0**4)
    )
    dS = (
        a * np.log(T / T0)
        + b * (T - T0)
        - c / 2 * (1 / T**2 - 1 / T0**2)
        - 2 * d * (1 / np.sqrt(T) - 1 / math.sqrt(T0))
        + ee / 2 * (T**2 - T0**2)
        + g / 3 * (T**3 - T0**3)
    )
    return e["H_kJ_per_mol"] * 1000.0 + dH, e["S_J_per_mol_K"] + dS


def simcem_phase_enthalpy(phase, T, source=None):
    r"""Molar enthalpy of a phase (formation-enthalpy reference) from the SimCem database, J/mol.

    .. math:: H(T) = H(T_0) + \int_{T_0}^{T} c_p\,dT

    with :math:`H(298.15\,K) = \Delta_f H^\circ` (the database's "Elements298" reference), so
    reaction enthalpies are :math:`\sum \nu H`.

    Parameters
    ----------
    phase : str
        Phase name (see :func:`simcem_phase_cp`).
    T : float or array, K
        Temperature.
    source : str or None
        Database source.

    Returns
    -------
    float or ndarray, J/mol

    Examples
    --------
    >>> round(simcem_phase_enthalpy("C3S", 298.15) / 1000, 2)
    -2933.13

    References
    ----------
    SimCem 1.0.0 ``free_database.xml`` (team source folder reference/cement_lime.md 0.1).
    """
    e, T = _entry_at(phase, source, T)
    H, _ = _h_s(e, T)
    return H if np.ndim(H) else float(H)


def simcem_phase_entropy(phase, T, source=None):
    r"""Molar entropy of a phase from the SimCem database, J/(mol K).

    .. math:: S(T) = S(T_0) + \int_{T_0}^{T} \frac{c_p}{T}\,dT

    Parameters
    ----------
    phase : str
        Phase name (see :func:`simcem_phase_cp`).
    T : float or array, K
        Temperature.
    source : str or None
        Database source.

    Returns
    -------
    float or ndarray, J/(mol K)

    Examples
    --------
    >>> round(simcem_phase_entropy("C3S", 298.15), 2)
    168.6

    References
    ----------
    SimCem 1.0.0 ``free_database.xml`` (team source folder reference/cement_lime.md 0.1).
    """
    e, T = _entry_at(phase, source, T)
    _, S = _h_s(e, T)
    return S if np.ndim(S) else float(S)


def simcem_phase_gibbs(phase, T, source=None):
    r"""Molar Gibbs energy :math:`G = H - TS` of a phase from the SimCem database, J/mol.

    Parameters
    ----------
    phase : str
        Phase name (see :func:`simcem_phase_cp`).
    T : float or array, K
        Temperature.
    source : str or None
        Database source.

    Returns
    -------
    float or ndarray, J/mol

    Examples
    --------
    >>> g = simcem_phase_gibbs("C2S_beta", 969.9) - simcem_phase_gibbs("C2S_alphaprime", 969.9)
    >>> abs(g) < 100.0
    True

    References
    ----------
    SimCem 1.0.0 ``free_database.xml`` (team source folder reference/cement_lime.md 0.1).
    """
    e, T = _entry_at(phase, source, T)
    H, S = _h_s(e, T)
    G = H - T * S
    return G if np.ndim(G) else float(G)


def _reaction_terms(reaction):
    if isinstance(reaction, str):
        reactions = _thermo()["reactions"]
        if reaction not in reactions:
            raise InputError("reaction", reaction, "one of " + ", ".join(reactions))
        reaction = reactions[reaction]
    terms = []
    for key, nu in reaction.items():
        phase, _, source = str(key).partition("/")
        terms.append((phase, source or None, float(nu)))
    return terms


def simcem_reaction_enthalpy(reaction, T):
    r"""Reaction enthalpy :math:`\Delta H = \sum_i \nu_i H_i(T)` from the SimCem database, J/mol.

    Parameters
    ----------
    reaction : str or mapping
        A reaction of ``data/clinker/thermodynamic_data.yaml`` (``calcination_HP2011``,
        ``belite_beta``, ``alite_from_alphaprime_C2S``, ``aluminate``, ``ferrite`` ...) or a
        mapping ``"phase/source" -> moles`` (reactants negative).
    T : float or array, K
        Temperature (all phases at T).

    Returns
    -------
    float or ndarray, J/mol (per mole of reaction as written)

    Examples
    --------
    >>> round(simcem_reaction_enthalpy("belite_beta", 298.15) / 1000, 1)
    -125.8

    References
    ----------
    SimCem 1.0.0 ``free_database.xml``; team source folder reference/cement_lime.md 0.2.
    """
    return sum(nu * simcem_phase_enthalpy(ph, T, src) for ph, src, nu in _reaction_terms(reaction))


def simcem_reaction_gibbs(reaction, T):
    r"""Standard reaction Gibbs energy :math:`\Delta G^\circ = \sum_i \nu_i G_i(T)`, J/mol.

    The standard state of the gases is the ideal gas at 1 bar.

    Parameters
    ----------
    reaction : str or mapping
        As in :func:`simcem_reaction_enthalpy`.
    T : float or array, K
        Temperature.

    Returns
    -------
    float or ndarray, J/mol

    Examples
    --------
    >>> abs(simcem_reaction_gibbs("alite_from_alphaprime_C2S", 1523.9)) < 50.0
    True

    References
    ----------
    SimCem 1.0.0 ``free_database.xml``; team source folder reference/cement_lime.md 0.1.
    """
    return sum(nu * simcem_phase_gibbs(ph, T, src) for ph, src, nu in _reaction_terms(reaction))


# --------------------------------------------------------------------------------------------
# Mass balance and theoretical heat
# --------------------------------------------------------------------------------------------


def carbonate_co2_per_clinker(CaO, MgO=0.0):
    r"""CO2 released by the carbonates per kg of clinker, kg/kg, when all CaO and MgO come from them.

    .. math:: m_{CO_2} = \frac{M_{CO_2}}{M_{CaO}}\,C + \frac{M_{CO_2}}{M_{MgO}}\,M
        = 0.7848\,C + 1.0919\,M

    The raw meal's LOI (carbonate CO2 only) is then :math:`m_{CO_2}/(1 + m_{CO_2})`.

    Parameters
    ----------
    CaO, MgO : float or array, -
        Clinker mass fractions.

    Returns
    -------
    float or ndarray, kg CO2 per kg clinker

    Examples
    --------
    >>> round(carbonate_co2_per_clinker(0.65, 0.017), 3)
    0.529

    References
    ----------
    Stoichiometry (IUPAC atomic weights); team source folder reference/cement_lime.md 1.1.
    """
    C, M = np.asarray(CaO, dtype=float), np.asarray(MgO, dtype=float)
    mco2 = molar_mass("CO2")
    out = mco2 / molar_mass("CaO") * C + mco2 / molar_mass("MgO") * M
    return out if out.ndim else float(out)


def theoretical_heat_of_clinker_formation(
    CaO, SiO2, Al2O3, Fe2O3, MgO=0.0, carbonate_source="NASA_GLENN", alumina_source="corundum"
):
    r"""Theoretical heat of clinker formation at 25 degC from the SimCem database, J/kg clinker.

    Reactants CaCO3, MgCO3, alpha-quartz, corundum (or kaolinite) and hematite; products the
    Bogue phases (:func:`bogue_phase_composition`: C3S, beta-C2S, C3A, C4AF, C2F), periclase and
    CO2 gas, all at 298.15 K:

    .. math:: Q = \frac{1}{1\,\mathrm{kg}}\Big(\sum_{prod} n_i H_i - \sum_{reac} n_j H_j\Big)

    With ``alumina_source="kaolinite"`` the Al2O3 comes from kaolinite dehydroxylated to
    Al2O3 + 2 SiO2 + 2 H2O(g) (+141.67 kJ/mol, HP2011). The other 2-3 % of a clinker (SO3,
    alkalis, minors) are ignored.

    Parameters
    ----------
    CaO, SiO2, Al2O3, Fe2O3, MgO : float, -
        Clinker oxide mass fractions.
    carbonate_source : str
        Source of CaCO3, MgCO3 and MgO: ``NASA_GLENN`` or ``HP2011``.
    alumina_source : str
        ``corundum`` or ``kaolinite``.

    Returns
    -------
    float, J/kg clinker

    Notes
    -----
    Published values: "theoretically a minimum 1.6 GJ" per tonne of clinker; commonly
    1.65-1.80 MJ/kg [recalled]. NASA and HP2011 calcination enthalpies differ by 1.55 kJ/mol at
    298 K (about 1 % of the result).

    Examples
    --------
    >>> round(theoretical_heat_of_clinker_formation(0.65, 0.22, 0.055, 0.033, 0.017) / 1e6, 2)
    1.66

    References
    ----------
    SimCem 1.0.0 ``free_database.xml``; team source folder reference/cement_lime.md 3.2
    (1.66 MJ/kg for this example; 1.74 with kaolinite); 1library.net heat-balance calculation
    ("a minimum 1.6 GJ").
    """
    if carbonate_source not in ("NASA_GLENN", "HP2011"):
        raise InputError("carbonate_source", carbonate_source, "one of NASA_GLENN, HP2011")
    if alumina_source not in ("corundum", "kaolinite"):
        raise InputError("alumina_source", alumina_source, "one of corundum, kaolinite")
    _check_fraction("MgO", MgO)
    p = bogue_phase_composition(CaO, SiO2, Al2O3, Fe2O3)
    for k in ("C3S", "C2S", "C3A", "C4AF", "C2F"):
        if p[k] < -1e-12:
            raise InputError(
                f"bogue.{k}",
                f"{p[k]:.4g}",
                ">= 0 (the composition is outside Bogue's assumptions; LSF above the limit?)",
            )
    phase_of = {
        "C3S": ("C3S", "NIST"),
        "C2S": ("C2S_beta", "NIST"),
        "C3A": ("C3A", "HaneinCSV"),
        "C4AF": ("C4AF", "Hanein_thesis_2016"),
        "C2F": ("C2F", "HaneinCSV"),
    }

    def H(ph, src):
        return simcem_phase_enthalpy(ph, _T25, src)

    n_ca = CaO / molar_mass("CaO")
    n_mg = MgO / molar_mass("MgO")
    n_s = SiO2 / molar_mass("SiO2")
    n_a = Al2O3 / molar_mass("Al2O3")
    n_f = Fe2O3 / molar_mass("Fe2O3")
    prod = sum(p[k] / molar_mass(ph) * H(ph, src) for k, (ph, src) in phase_of.items())
    prod += n_mg * H("MgO", carbonate_source) + (n_ca + n_mg) * H("CO2", "HP2011")
    reac = (
        n_ca * H("CaCO3", carbonate_source)
        + n_mg * H("MgCO3", carbonate_source)
        + n_s * H("quartz_alpha", "NIST")
        + n_a * H("corundum", "NIST")
        + n_f * H("hematite", "HP2011")
    )
    q = prod - reac
    if alumina_source == "kaolinite":
        q += n_a * _thermo()["kaolinite_dehydroxylation_kJ_per_mol_298"] * 1000.0
    return float(q)


# --------------------------------------------------------------------------------------------
# Clinker-forming reactions: stoichiometry and mass-action rates
# --------------------------------------------------------------------------------------------

_RATE_SPECIES = ("CaCO3", "CaO", "CO2", "SiO2", "C2S", "C3S", "Al2O3", "C3A", "Fe2O3", "C4AF")
_SPECIES_PHASE = {"C2S": "C2S_beta"}


def clinker_reaction_stoichiometry():
    r"""Mass stoichiometry of the five clinker-forming reactions, kg per mol of reaction.

    1. CaCO3 -> CaO + CO2; 2. 2 CaO + SiO2 -> C2S; 3. C2S + CaO -> C3S; 4. 3 CaO + Al2O3 -> C3A;
    5. 4 CaO + Al2O3 + Fe2O3 -> C4AF. Entry :math:`\nu_{ij} M_j` (reactants negative); each
    row sums to zero (mass conservation).

    Returns
    -------
    tuple, kg/mol
        (reaction names, species names, ndarray (5, 10) in kg/mol).

    Examples
    --------
    >>> names, species, nu = clinker_reaction_stoichiometry()
    >>> bool(np.all(np.abs(nu.sum(axis=1)) < 1e-15))
    True

    References
    ----------
    Spang, Automatica 8 (1972) 309 ("basic reactions"); Mastorakos et al., Appl. Math. Modelling
    23 (1999) 55; team source folder reference/cement_lime.md 3.1.
    """
    rx = _models()["clinker_reactions"]
    nu = np.zeros((len(rx), len(_RATE_SPECIES)))
    for i, r in enumerate(rx):
        for sp, n in r["reactants"].items():
            nu[i, _RATE_SPECIES.index(sp)] -= n * molar_mass(_SPECIES_PHASE.get(sp, sp))
        for sp, n in r["products"].items():
            nu[i, _RATE_SPECIES.index(sp)] += n * molar_mass(_SPECIES_PHASE.get(sp, sp))
    return tuple(r["name"] for r in rx), _RATE_SPECIES, nu


def mastorakos_recalled_parameters():
    """Recalled, UNVERIFIED activation energies and pre-exponential orders of the five reactions.

    Returns
    -------
    dict
        ``E`` (ndarray, J/mol) and ``k0_order`` (ndarray, units unknown), each of the five
        reactions. A starting point for a calibration only (reference note section 3.3 [MEMORY]:
        E +-10 %, k0 order of magnitude): replace by Mastorakos et al. (1999) Table 2 when read.

    Examples
    --------
    >>> mastorakos_recalled_parameters()["E"].tolist()
    [175700.0, 240000.0, 420000.0, 310000.0, 330000.0]

    References
    ----------
    Team source folder reference/cement_lime.md section 3.3 (recalled from Mastorakos et al.
    1999 and Mujumdar & Ranade 2006).
    """
    rx = _models()["clinker_reactions"]
    return {
        "E": np.array([r["E_kJ_per_mol"] * 1000.0 for r in rx]),
        "k0_order": np.array([float(r["k0_order"]) for r in rx]),
    }


def mastorakos_clinker_rates(T, rho, k0, E):
    r"""Mass-action rates of the five clinker-forming reactions, mol/(m3 s).

    .. math::
        r_1 = k_1 \rho_{CaCO_3},\ r_2 = k_2 \rho_{C}^2 \rho_{S},\ r_3 = k_3 \rho_{C_2S} \rho_{C},\
        r_4 = k_4 \rho_{C}^3 \rho_{A},\ r_5 = k_5 \rho_{C}^4 \rho_{A} \rho_{F},\quad
        k_i = k_{0,i}\, e^{-E_i/(R T)}

    The species production rates are ``rates @ nu`` with ``nu`` from
    :func:`clinker_reaction_stoichiometry` (kg/(m3 s)). No default constants: the published
    ones (Mastorakos et al. 1999 Table 2) were not read; :func:`mastorakos_recalled_parameters`
    gives recalled, unverified values.

    Parameters
    ----------
    T : float, K
        Solid temperature.
    rho : mapping
        Mass concentrations, kg/m3 of bed: ``CaCO3``, ``CaO``, ``SiO2``, ``C2S``, ``Al2O3``,
        ``Fe2O3`` (missing ones are 0).
    k0 : sequence of 5 floats, mol/(m3 s) per (kg/m3)^order
        Pre-exponential factors (order 1, 3, 2, 4, 6).
    E : sequence of 5 floats, J/mol
        Activation energies.

    Returns
    -------
    ndarray (5,), mol/(m3 s)
        Reaction extents per second per unit bed volume.

    Examples
    --------
    >>> r = mastorakos_clinker_rates(1200.0, {"CaCO3": 1000.0}, [1e8, 0, 0, 0, 0],
    ...                              [175700.0, 0, 0, 0, 0])
    >>> round(float(r[0]), 3)
    2249.715

    References
    ----------
    E. Mastorakos, A. Massias, C.D. Tsakiroglou, D.A. Goussis, V.N. Burganos, A.C. Payatakes,
    CFD predictions for cement kilns including flame modelling, heat transfer and clinker
    chemistry, Appl. Math. Modelling 23 (1999) 55-76 (rate form as recalled in the team source
    folder reference/cement_lime.md 3.3).
    """
    check_positive("T", T, "K")
    allowed = {"CaCO3", "CaO", "SiO2", "C2S", "Al2O3", "Fe2O3"}
    for k, v in rho.items():
        if k not in allowed:
            raise InputError("rho", k, "one of " + ", ".join(sorted(allowed)))
        if not (math.isfinite(float(v)) and float(v) >= 0.0):
            raise InputError(f"rho.{k}", f"{float(v):g} kg/m3", ">= 0")
    k0 = np.asarray(k0, dtype=float)
    E = np.asarray(E, dtype=float)
    if k0.shape != (5,) or E.shape != (5,):
        raise InputError("k0, E", f"shapes {k0.shape}, {E.shape}", "5 values each")
    c = {s: float(rho.get(s, 0.0)) for s in allowed}
    k = k0 * np.exp(-E / (R_GAS * float(T)))
    C = c["CaO"]
    return k * np.array(
        [
            c["CaCO3"],
            C**2 * c["SiO2"],
            c["C2S"] * C,
            C**3 * c["Al2O3"],
            C**4 * c["Al2O3"] * c["Fe2O3"],
        ]
    )


# --------------------------------------------------------------------------------------------
# The clinker of a kiln: bed oxides, smooth melt fraction, outlet report
# --------------------------------------------------------------------------------------------

#: Oxide of each element of a bed species, and the atoms of the element per oxide formula.
_ELEMENT_OXIDE = {
    "Ca": ("CaO", 1),
    "Si": ("SiO2", 1),
    "Al": ("Al2O3", 2),
    "Fe": ("Fe2O3", 2),
    "Mg": ("MgO", 1),
    "K": ("K2O", 2),
    "Na": ("Na2O", 2),
    "S": ("SO3", 1),
}
#: Elements lost on ignition (carbonate CO2, water, organic matter).
_VOLATILE_ELEMENTS = ("C", "H", "O", "N")
#: Clinker phases of the species table, with the SimCem phase the Bogue result is named by.
CLINKER_PHASES = ("C3S", "C2S", "C3A", "C4AF")


def bed_oxide_flows(flows, species=None):
    r"""Oxide (ignited, clinker-basis) mass flows of a bed given by its species flows, kg/s.

    Every metal atom of the bed species is counted as its oxide (Ca as CaO, Si as SiO2, Al as
    Al2O3, Fe as Fe2O3, Mg as MgO, K as K2O, Na as Na2O, S as SO3); C, H, O, N are lost on
    ignition (carbonate CO2, moisture). A lumped species without a formula (``inert``, ``ash``)
    counts whole, as ``other``:

    .. math:: \dot m_{ox} = \sum_i \frac{\dot m_i}{M_i}\,\frac{n_{e,i}}{n_{e,ox}}\,M_{ox}

    Parameters
    ----------
    flows : mapping
        Bed species name -> mass flow, kg/s (floats or arrays of one shape).
    species : SpeciesTable, optional
        Defaults to the built-in table.

    Returns
    -------
    dict, kg/s
        ``CaO``, ``SiO2``, ``Al2O3``, ``Fe2O3``, ``MgO``, ``K2O``, ``Na2O``, ``SO3``, ``other``
        (zeros where absent).

    Examples
    --------
    >>> ox = bed_oxide_flows({"CaCO3": 1.0, "C2S": 0.5})
    >>> round(ox["CaO"], 4), round(ox["SiO2"], 4)
    (0.8859, 0.1744)

    References
    ----------
    Stoichiometry; the ignited basis of a raw meal analysis (loss on ignition), team source
    folder reference/cement_lime.md 1.1.
    """
    from rotarykiln.chemistry.species import default_species

    sp = species or default_species()
    zero = sum(np.zeros_like(np.asarray(v, dtype=float)) for v in flows.values()) + 0.0
    out = {ox: zero for ox, _ in _ELEMENT_OXIDE.values()}
    out["other"] = zero
    for name, q in flows.items():
        s = sp[name]
        q = np.asarray(q, dtype=float)
        counted = False
        for el, n in s.elements.items():
            if el in _ELEMENT_OXIDE:
                ox, per = _ELEMENT_OXIDE[el]
                out[ox] = out[ox] + q / s.molar_mass * n / per * molar_mass(ox)
                counted = True
            elif el not in _VOLATILE_ELEMENTS and not counted:
                out["other"] = out["other"] + q  # a lumped pseudo-element species
                counted = True
    return {k: (v if np.ndim(v) else float(v)) for k, v in out.items()}


def _smoothstep(x):
    x = np.clip(x, 0.0, 1.0)
    return x * x * (3.0 - 2.0 * x)


def lea_parker_melt_fraction(T, Al2O3, Fe2O3, MgO=0.0, K2O=0.0, Na2O=0.0, width=20.0):
    r"""Melt fraction of a clinker against temperature, vectorised and continuous (kiln form).

    The piecewise-linear curve of :func:`lea_parker_liquid_curve` through the Lea-Parker points
    at 1338, 1400 and 1450 degC (constant above), with the jump at the 1338 degC invariant
    point (1611.15 K) replaced by a C1 ramp (smoothstep) over ``width`` below it:

    .. math:: L(T) = L_{1338}\,s\!\left(\frac{T - (T_{1338} - w)}{w}\right),\quad
        s(x) = x^2(3 - 2x),\qquad T < T_{1338}

    so a Newton solver sees a rate that is zero below :math:`T_{1338} - w` and continuous.
    Compositions may be arrays (one per kiln cell).

    Parameters
    ----------
    T : float or array, K
        Temperature.
    Al2O3, Fe2O3, MgO, K2O, Na2O : float or array, -
        Clinker mass fractions (ignited basis).
    width : float, K
        Width of the onset ramp (> 0); 20 K by default, inside the +-30 K uncertainty of the
        melt onset of commercial mixes [recalled, cement_lime.md 2].

    Returns
    -------
    float or ndarray, -
        Liquid mass fraction.

    Examples
    --------
    >>> round(float(lea_parker_melt_fraction(1698.15, 0.055, 0.033, 0.017)) * 100, 2)
    25.41
    >>> float(lea_parker_melt_fraction(1590.0, 0.055, 0.033, 0.017))
    0.0

    References
    ----------
    Lea & Parker (1934/35) (coefficients: data/clinker/models.yaml, 1450 degC SEEN, 1400 and
    1338 degC recalled); team source folder reference/cement_lime.md section 2.
    """
    if not (math.isfinite(width) and width > 0.0):
        raise InputError("width", width, "> 0 K")
    T = np.asarray(T, dtype=float)
    check_positive("T", T, "K")
    Tk = (1611.15, 1673.15, 1723.15)
    L = [
        np.asarray(lea_parker_liquid_fraction(Al2O3, Fe2O3, MgO, K2O, Na2O, T=t), dtype=float)
        for t in Tk
    ]
    x1 = np.clip((T - Tk[0]) / (Tk[1] - Tk[0]), 0.0, 1.0)
    x2 = np.clip((T - Tk[1]) / (Tk[2] - Tk[1]), 0.0, 1.0)
    above = np.where(T < Tk[1], L[0] + x1 * (L[1] - L[0]), L[1] + x2 * (L[2] - L[1]))
    ramp = _smoothstep((T - (Tk[0] - width)) / width)
    out = np.where(T < Tk[0], L[0] * ramp, above)
    return out if out.ndim else float(out)


@dataclass(frozen=True)
class ClinkerReport:
    """The clinker leaving a kiln: phases, free lime, Bogue of the same oxides, heats.

    All fractions are mass fractions of the bed leaving the kiln (the clinker; unreacted
    carbonate included in the total), as floats.

    Attributes
    ----------
    phases : dict
        ``C3S``, ``C2S``, ``C3A``, ``C4AF`` of the kiln solution, -.
    free_lime : float
        Uncombined CaO, -.
    unreacted : dict
        The other bed species (SiO2, Al2O3, Fe2O3, CaCO3, MgO, ...), -.
    oxides : dict
        The clinker's oxides (ignited basis: CaO, SiO2, Al2O3, Fe2O3, MgO, ...), -.
    bogue : dict
        Bogue's potential composition of the same oxides (:func:`bogue_phase_composition`), -.
    bogue_free_lime : dict
        Bogue with the solution's free lime subtracted from CaO, -.
    heat_of_formation : float or None
        Heat of the reactions from the feed to this clinker at 298.15 K (formation enthalpies
        of the species table; CO2 released as gas), J/kg clinker; None without the feed.
    theoretical_heat : float
        Theoretical heat of clinker formation of the same oxides
        (:func:`theoretical_heat_of_clinker_formation`, carbonate raw meal), J/kg clinker.
    loss_on_ignition : float
        Mass lost by the clinker on ignition (residual carbonate CO2, moisture), -.
    mass_flow : float
        Bed mass flow at the outlet, kg/s.
    """

    phases: dict
    free_lime: float
    unreacted: dict
    oxides: dict
    bogue: dict
    bogue_free_lime: dict
    heat_of_formation: float | None
    theoretical_heat: float
    loss_on_ignition: float
    mass_flow: float

    def to_frame(self):
        """One row per quantity: the solution's phases beside Bogue's, in mass %."""
        import pandas as pd

        rows = []
        for p in CLINKER_PHASES:
            rows.append(
                (p, 100 * self.phases[p], 100 * self.bogue[p], 100 * self.bogue_free_lime[p])
            )
        rows.append(("CaO_free", 100 * self.free_lime, 0.0, 100 * self.free_lime))
        return pd.DataFrame(
            rows, columns=["phase", "kiln_pct", "bogue_pct", "bogue_with_free_lime_pct"]
        ).set_index("phase")


def _outlet_flows(source):
    """Bed species -> outlet flow (kg/s) of a kiln solution or of a mapping of flows."""
    flows = getattr(source, "bed_flows", source)
    out = {}
    for name, q in flows.items():
        a = np.asarray(q, dtype=float)
        out[str(name)] = float(a[-1]) if a.ndim else float(a)
    return out


def clinker_report(source, feed=None, species=None):
    r"""The outlet clinker of a kiln: phases, free lime, Bogue of the same oxides, heats.

    Phases and free lime are the outlet bed flows over the outlet bed flow. Beside them, Bogue's
    potential composition of the same oxides (:func:`bed_oxide_flows`, ignited basis), once as
    is and once with the free lime subtracted, scaled to the outlet mass (a clinker whose
    reactions ran to completion with pure phases has exactly Bogue's composition). The heat of
    formation is

    .. math:: Q = \frac{1}{\dot m_{out}}\Big(\sum_{out} \dot n_i \Delta_f H_i
        + \dot n_{CO_2}\Delta_f H_{CO_2} - \sum_{in} \dot n_i \Delta_f H_i\Big)

    with :math:`\dot n_{CO_2}` the carbon the bed lost (released as CO2), all at 298.15 K.

    Parameters
    ----------
    source : KilnSolution or mapping
        A kiln solution (its ``bed_flows``, the outlet at the last face) or a mapping bed
        species -> outlet mass flow, kg/s.
    feed : mapping, optional
        Bed species -> feed mass flow, kg/s (for the heat of formation).
    species : SpeciesTable, optional
        Defaults to the built-in table.

    Returns
    -------
    ClinkerReport, -
        Fractions as mass fractions (-), heats in J/kg clinker, the outlet flow in kg/s.

    Examples
    --------
    >>> r = clinker_report({"C3S": 0.5578, "C2S": 0.2099, "C3A": 0.0899, "C4AF": 0.1004,
    ...                     "MgO": 0.017, "CaO": 0.0})
    >>> round(r.phases["C3S"] * 100, 1), round(r.bogue["C3S"] * 100, 1)
    (57.2, 57.2)

    References
    ----------
    Bogue (1929); SimCem database heats (team source folder reference/cement_lime.md 1.2, 3.2).
    """
    from rotarykiln.chemistry.species import default_species

    sp = species or default_species()
    flows = _outlet_flows(source)
    for name, q in flows.items():
        if name not in sp or sp[name].phase != "bed":
            raise InputError(f"bed_flows.{name}", name, "a bed species")
        if not (math.isfinite(q) and q >= 0.0):
            raise InputError(f"bed_flows.{name}", q, ">= 0 kg/s")
    total = sum(flows.values())
    if total <= 0.0:
        raise InputError("bed_flows", total, "a positive outlet flow")
    w = {k: v / total for k, v in flows.items()}
    ox = bed_oxide_flows(flows, sp)
    ignited = sum(ox.values())
    oxides = {k: v / ignited for k, v in ox.items()}
    loi = 1.0 - ignited / total
    free_lime = w.get("CaO", 0.0)
    # Bogue on the ignited clinker, scaled back to the outlet mass
    scale = ignited / total
    fe = max(oxides["Fe2O3"], 1e-12)
    args = (oxides["CaO"], oxides["SiO2"], oxides["Al2O3"], fe, oxides["SO3"])
    bogue = {k: v * scale for k, v in bogue_phase_composition(*args).items()}
    bogue_fl = bogue_phase_composition(*args, free_lime=min(free_lime / scale, oxides["CaO"]))
    bogue_fl = {k: v * scale for k, v in bogue_fl.items()}
    phases = {p: w.get(p, 0.0) for p in CLINKER_PHASES}
    unreacted = {k: v for k, v in w.items() if k not in CLINKER_PHASES and k != "CaO"}
    heat = None
    if feed is not None:
        h = 0.0
        carbon = 0.0
        for sign, fl in ((1.0, flows), (-1.0, _outlet_flows(feed))):
            for name, q in fl.items():
                s = sp[name]
                if q == 0.0:
                    continue
                if s.h_f is None and _inert(s):
                    continue  # lumped inert matter (ash): it takes no part in the reactions
                if s.h_f is None:
                    raise InputError(f"species.{name}.h_f", None, "known (for the heat)")
                h += sign * q / s.molar_mass * s.h_f
                carbon -= sign * q / s.molar_mass * s.elements.get("C", 0.0)
        h += carbon * sp["CO2"].h_f
        heat = h / total
    theo = theoretical_heat_of_clinker_formation(
        oxides["CaO"], oxides["SiO2"], oxides["Al2O3"], fe, oxides["MgO"]
    )
    return ClinkerReport(
        phases=phases,
        free_lime=free_lime,
        unreacted=unreacted,
        oxides=oxides,
        bogue=bogue,
        bogue_free_lime=bogue_fl,
        heat_of_formation=heat,
        theoretical_heat=float(theo),
        loss_on_ignition=loi,
        mass_flow=total,
    )


def _inert(species) -> bool:
    """Whether a species is lumped inert matter (only the Ash or Inert pseudo-elements)."""
    return bool(species.elements) and set(species.elements) <= {"Ash", "Inert"}
