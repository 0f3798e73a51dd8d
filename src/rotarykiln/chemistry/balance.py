"""Element balances: of production rates (per cell) and of streams (kiln inlets vs outlets)."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from rotarykiln.chemistry.species import SpeciesTable, default_species
from rotarykiln.errors import ConvergenceError, InputError

__all__ = [
    "ELEMENT_RTOL",
    "element_production",
    "element_residuals",
    "check_element_balance",
    "element_flows",
    "check_stream_balance",
]

#: Relative closure required of element balances (issue 7).
ELEMENT_RTOL = 1e-8


def element_production(production, species: SpeciesTable | None = None) -> np.ndarray:
    r"""Net production of each element, kg/(s m).

    .. math:: \dot w_e = \sum_i \frac{a_{ei} M_e}{M_i}\, \dot w_i

    Parameters
    ----------
    production : array, shape (..., n_species)
        Species production rates in the order of ``species``, kg/(s m).
    species : SpeciesTable, optional

    Returns
    -------
    ndarray, shape (..., n_elements)
        Order of ``species.elements``.
    """
    sp = species or default_species()
    P = np.asarray(production, dtype=float)
    if P.shape[-1] != len(sp.species):
        raise InputError(
            "production", f"last axis {P.shape[-1]}", f"{len(sp.species)} (number of species)"
        )
    return P @ sp.element_mass_fractions().T


def element_residuals(production, species: SpeciesTable | None = None) -> np.ndarray:
    """Relative element residuals: |net| / sum |species contributions|, shape (..., n_elements).

    0 where an element is not involved.
    """
    sp = species or default_species()
    P = np.asarray(production, dtype=float)
    W = sp.element_mass_fractions()
    net = P @ W.T
    scale = np.abs(P) @ W.T
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(scale > 0, np.abs(net) / np.where(scale > 0, scale, 1.0), 0.0)


def check_element_balance(
    production, species: SpeciesTable | None = None, rtol: float = ELEMENT_RTOL
) -> float:
    """Check that reactions conserve every element; returns the largest relative residual.

    Raises
    ------
    ConvergenceError
        If a residual exceeds ``rtol``; diagnostics name the element and the cell.

    Examples
    --------
    >>> sp = default_species()
    >>> w = np.zeros(len(sp.species))
    >>> w[sp.index("CaCO3")], w[sp.index("CaO")], w[sp.index("CO2")] = -1.0, 0.56029, 0.43971
    >>> check_element_balance(w, sp, rtol=1e-4) < 1e-4
    True
    """
    sp = species or default_species()
    res = np.atleast_2d(element_residuals(production, sp))
    worst = float(res.max()) if res.size else 0.0
    if worst > rtol:
        cell, e = np.unravel_index(int(np.argmax(res)), res.shape)
        raise ConvergenceError(
            "element balance does not close",
            element=sp.elements[e],
            cell=int(cell),
            relative_residual=worst,
            tolerance=rtol,
        )
    return worst


def element_flows(
    mass_flows: Mapping[str, float], species: SpeciesTable | None = None
) -> dict[str, float]:
    """Mass flow of each element carried by species mass flows, kg/s.

    Parameters
    ----------
    mass_flows : mapping
        Species -> mass flow, kg/s (bed and gas species alike).

    Examples
    --------
    >>> round(element_flows({"CaCO3": 1.0})["C"], 5)
    0.12001
    """
    sp = species or default_species()
    W = sp.element_mass_fractions()
    elements = sp.elements
    out = dict.fromkeys(elements, 0.0)
    for name, q in mass_flows.items():
        column = W[:, sp.index(name, "mass_flows")] * q
        for k, e in enumerate(elements):
            out[e] += float(column[k])
    return out


def check_stream_balance(
    inlets: Mapping[str, float],
    outlets: Mapping[str, float],
    species: SpeciesTable | None = None,
    rtol: float = ELEMENT_RTOL,
) -> dict[str, float]:
    """Compare element flows in and out of a kiln; returns relative residual per element.

    The residual of element e is |in - out| / max(in, out). Raises :class:`ConvergenceError` if
    one exceeds ``rtol``.
    """
    fin = element_flows(inlets, species)
    fout = element_flows(outlets, species)
    res = {}
    for e in fin:
        scale = max(abs(fin[e]), abs(fout[e]))
        res[e] = abs(fin[e] - fout[e]) / scale if scale > 0 else 0.0
    worst = max(res, key=res.get) if res else None
    if worst is not None and res[worst] > rtol:
        raise ConvergenceError(
            "element balance of the streams does not close",
            element=worst,
            inlet=fin[worst],
            outlet=fout[worst],
            relative_residual=res[worst],
            tolerance=rtol,
        )
    return res
