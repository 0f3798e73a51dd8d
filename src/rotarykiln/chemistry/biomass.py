r"""Biomass (wood) pyrolysis: the built-in mechanism, and mechanisms with user species.

The reactions are data (``reactions/wood_pyrolysis.yaml``, species in ``species.yaml``); this
module assembles them:

- :func:`wood_pyrolysis_mechanism`: the wood scheme of the rotaryPyrolysis default case
  (primary steps of Di Blasi & Branca 2001 with the intermediate-solid route of Park et al.
  2010, tar held in the bed cracked to gas (Lidén et al. 1988) and char (Di Blasi 1993),
  drying of Chan et al. 1985), with the primary tar split :math:`\psi` between vapour and bed as
  a parameter and, optionally, the cracking of the tar vapour in the freeboard;
- :func:`tar_escape_fraction`: :math:`\psi(N)` as the rotaryPyrolysis script has it, bounded
  to [0, 1];
- :func:`mechanism_from_files`: a :class:`~rotarykiln.chemistry.mechanism.Mechanism` on the
  built-in species extended by user species (YAML), from built-in reaction names and user
  reaction files, every reaction checked against the extended table (element balance,
  known species) at load.

Every step is first order in the reactant's hold-up at the bed temperature,
:math:`r_j = A_j e^{-E_j/(R T_b)} m'_{i}` (kg/(s m)), the rate law ``arrhenius``.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable, Sequence
from pathlib import Path

import numpy as np

from rotarykiln.chemistry.mechanism import Mechanism
from rotarykiln.chemistry.reaction import (
    REACTIONS_DIR,
    builtin_reactions,
    load_reactions,
    reaction_from_dict,
)
from rotarykiln.chemistry.species import SpeciesTable, default_species, load_species
from rotarykiln.chemistry.yaml_files import read_yaml
from rotarykiln.errors import InputError, check_range

__all__ = [
    "WOOD_PYROLYSIS",
    "WOOD_PYROLYSIS_FILE",
    "tar_escape_fraction",
    "wood_pyrolysis_mechanism",
    "mechanism_from_files",
]

WOOD_PYROLYSIS_FILE = REACTIONS_DIR / "wood_pyrolysis.yaml"

#: The bed reactions of the built-in wood mechanism (without the freeboard cracking).
WOOD_PYROLYSIS = (
    "wood_to_gas",
    "wood_to_tar_vapour",
    "wood_to_tar_bed",
    "wood_to_intermediate_solid",
    "intermediate_solid_to_char",
    "bed_tar_to_gas",
    "bed_tar_to_char",
    "wood_drying_chan",
)

#: Pre-exponential factor of the primary tar step, 1/s (Di Blasi & Branca 2001).
A_TAR = 1.08e10


def tar_escape_fraction(speed_rpm):
    r"""Fraction of the primary tar leaving the bed as vapour, as in the rotaryPyrolysis script.

    .. math:: \psi = \min(1, \max(0, 0.57 + 0.06\,N)),\qquad N \text{ in rpm}

    The script gives no source for it (presumably the paper of Pichler et al. 2021) and does not
    bound it: above 7.2 rpm it passes 1 and the tar held in the bed would be formed negative.
    Here it is clipped to [0, 1].

    Parameters
    ----------
    speed_rpm : float or array
        Kiln rotation, rpm (>= 0).

    Returns
    -------
    float or array, -

    Examples
    --------
    >>> round(tar_escape_fraction(2.0), 2), tar_escape_fraction(10.0)
    (0.69, 1.0)

    References
    ----------
    M. Pichler et al., J. Anal. Appl. Pyrolysis 158 (2021) 105171 (script rotaryPyrolysis
    v1.0.1); the formula is not documented in the script.
    """
    n = np.asarray(speed_rpm, dtype=float)
    check_range("speed (rpm)", n, 0.0, 1e3, closed_low=True, closed_high=True)
    out = np.clip(0.57 + 0.06 * n, 0.0, 1.0)
    return out if out.ndim else float(out)


def wood_pyrolysis_mechanism(
    tar_escape: float = 0.69,
    *,
    drying: bool = True,
    freeboard_cracking: bool = False,
    species: SpeciesTable | None = None,
    kirchhoff: bool = False,
) -> Mechanism:
    r"""The built-in wood pyrolysis mechanism with the primary tar split ``tar_escape``.

    Reactions (mass-based, per kg of reactant; heats > 0 endothermic):

    =============================  ===========  ========  =========
    step                           A (1/s)      E kJ/mol  dh kJ/kg
    =============================  ===========  ========  =========
    wood -> gas                    4.38e9       152.7     +80
    wood -> tar (psi vapour)       1.08e10 psi  148       +80
    wood -> tar(l) (1 - psi bed)   1.08e10 (1-  148       +80
                                   psi)
    wood -> intermediate solid     3.75e6       111.7     +80
    intermediate solid -> char     1.38e10      161.0     -300
    tar(l) -> gas                  4.28e6       108       -42
    tar(l) -> char                 1.0e5        108       -42
    H2O(l) -> H2O (drying)         5.13e10      88        +2257
    tar -> gas (freeboard, opt.)   4.28e6       107.5     -42
    =============================  ===========  ========  =========

    Parameters
    ----------
    tar_escape : float
        :math:`\psi`, fraction of the primary tar leaving the bed as vapour, in [0, 1]
        (:func:`tar_escape_fraction`; 0.69 at 2 rpm).
    drying : bool
        Include the drying step (Chan et al. 1985).
    freeboard_cracking : bool
        Include the cracking of the tar vapour at the gas temperature (Lidén et al. 1988,
        per freeboard volume); the rotaryPyrolysis script has none.
    species : SpeciesTable, optional
        A table holding the built-in species (default :func:`default_species`), e.g. one
        extended by :func:`~rotarykiln.chemistry.species.load_species`.
    kirchhoff : bool
        Shift the heats with temperature (:class:`Mechanism`).

    Returns
    -------
    Mechanism
        Rates in kg/(s m), heats in J/kg of reactant.

    Examples
    --------
    >>> m = wood_pyrolysis_mechanism(0.69)
    >>> len(m.reactions), round(m.reactions[1].params["A"] / 1e10, 4)
    (8, 0.7452)

    References
    ----------
    C. Di Blasi, C. Branca, Ind. Eng. Chem. Res. 40 (2001) 5547-5556; W.C. Park, A. Atreya,
    H.R. Baum, Combust. Flame 157 (2010) 481-494; A.G. Lidén, F. Berruti, D.S. Scott, Chem.
    Eng. Commun. 65 (1988) 207-221; C. Di Blasi, Combust. Sci. Technol. 90 (1993) 315-340;
    W.R. Chan, M. Kelbon, B.B. Krieger, Fuel 64 (1985) 1505-1513.
    """
    check_range("tar_escape", tar_escape, 0.0, 1.0, closed_low=True, closed_high=True)
    sp = species or default_species()
    pool = load_reactions(WOOD_PYROLYSIS_FILE, sp)
    names = [n for n in WOOD_PYROLYSIS if drying or n != "wood_drying_chan"]
    if freeboard_cracking:
        names.append("tar_cracking_freeboard")
    chosen = []
    for n in names:
        r = pool[n]
        if n == "wood_to_tar_vapour":
            r = dataclasses.replace(r, params={**r.params, "A": A_TAR * tar_escape})
        elif n == "wood_to_tar_bed":
            r = dataclasses.replace(r, params={**r.params, "A": A_TAR * (1.0 - tar_escape)})
        chosen.append(r)
    return Mechanism(tuple(chosen), sp, kirchhoff=kirchhoff)


def mechanism_from_files(
    species=None,
    reactions: Sequence = (),
    files: Iterable = (),
    *,
    kirchhoff: bool = False,
) -> Mechanism:
    """A mechanism on the built-in species extended by user species.

    Parameters
    ----------
    species : path, mapping or SpeciesTable, optional
        User species (:func:`~rotarykiln.chemistry.species.load_species`); None: the
        built-in table.
    reactions : sequence of str or mapping
        Built-in reaction names, or reaction mappings (the YAML form of
        :func:`~rotarykiln.chemistry.reaction.reaction_from_dict`).
    files : iterable of Path
        YAML files with a ``reactions:`` list (and optionally a ``species:`` section, loaded
        before its reactions).
    kirchhoff : bool

    Returns
    -------
    Mechanism
        Every reaction checked against the extended table at load: an undefined species, an
        element-unbalanced stoichiometry, an unknown rate law: one-line :class:`InputError`.

    Examples
    --------
    >>> m = mechanism_from_files(
    ...     {"bed": {"lignin": {"composition": {"C": 0.5, "H": 0.06, "O": 0.44},
    ...                         "molar_mass": 0.024022, "cp": 1500.0}}},
    ...     ["wood_to_gas", {"name": "lignin_to_char", "stoichiometry": {"lignin": -1,
    ...      "char": 1}, "basis": "lignin", "rate": {"law": "arrhenius", "A": 1e8,
    ...      "E": 1.4e5}, "heat": "100 kJ/kg"}])
    >>> m.names
    ('wood_to_gas', 'lignin_to_char')

    References
    ----------
    The YAML forms of docs/chemistry.md (reactions) and docs/pyrolysis.md (species).
    """
    if isinstance(species, SpeciesTable):
        sp = species
    elif species is None:
        sp = default_species()
    else:
        sp = load_species(species)
    file_reactions = []
    for path in files:
        path = Path(path)
        data = read_yaml(path, "reaction file")
        if isinstance(data, dict) and data.get("species") is not None:
            sp = load_species(data["species"], base=sp)
        file_reactions.append(path)
    known = builtin_reactions(sp)
    chosen = []
    for i, item in enumerate(reactions):
        if isinstance(item, str):
            if item not in known:
                raise InputError(
                    f"reactions[{i}]", item, f"a built-in reaction ({', '.join(sorted(known))})"
                )
            chosen.append(known[item])
        else:
            chosen.append(reaction_from_dict(item, sp, where=f"reactions[{i}]"))
    for path in file_reactions:
        chosen.extend(load_reactions(path, sp).values())
    return Mechanism(tuple(chosen), sp, kirchhoff=kirchhoff)
