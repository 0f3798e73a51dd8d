r"""Product yields of a solved reacting kiln: at its outlet, and over a residence time distribution.

- :func:`outlet_yield`: a bed species' outlet flow over the total (wet) feed, e.g. the char
  yield of a pyrolysis kiln;
- :func:`segregated_yields`: the outlet composition of the bed when its residence time
  distribution is carried by particle classes in segregated flow, each crossing the converged
  kiln's bed temperature profile at its own speed (the rotaryPyrolysis script's treatment of its
  RTD, Pichler et al. 2021), beside the kiln's own plug flow or axial dispersion inside the
  balances (:mod:`rotarykiln.kiln.bed.dispersion`).

References
----------
M. Pichler, B. Haddadi, C. Jordan, H. Norouzi, M. Harasek, J. Anal. Appl. Pyrolysis 158 (2021)
105171 (script rotaryPyrolysis v1.0.1: char yield over the wet feed, segregated RTD classes);
O. Levenspiel, Chemical Reaction Engineering, 3rd ed. (1999), ch. 11 (segregated flow) and
ch. 13 (closed-closed dispersion RTD).
"""

from __future__ import annotations

import numpy as np

__all__ = ["outlet_yield", "segregated_yields"]

R_GAS = 8.314462618  # J/(mol K)


def outlet_yield(solution, species: str, feed: float | None = None) -> float:
    r"""Outlet flow of the bed species ``species`` over the total solids feed, -.

    .. math:: Y_i = \dot m_i(L) \,/\, \sum_k \dot m_{k,0}

    with :math:`\dot m_{k,0}` the fed flows, moisture included (the char yield of a pyrolysis
    kiln is over the wet feed, as Pichler et al. 2021 report it).

    Parameters
    ----------
    solution : KilnSolution
        A solved kiln (:func:`~rotarykiln.kiln.steady.solve.solve_kiln`).
    species : str
        A bed species of its mechanism (``"char"``).
    feed : float, optional
        The flow to divide by, kg/s (default the solution's total feed).

    Returns
    -------
    float, -

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> sol = SimpleNamespace(bed_flows={"char": np.array([0.0, 1.7e-3])},
    ...                       feed={"wood": 8.325e-3, "H2O(l)": 8.33e-6})
    >>> round(outlet_yield(sol, "char"), 4)
    0.204

    References
    ----------
    M. Pichler et al., J. Anal. Appl. Pyrolysis 158 (2021) 105171.
    """
    feed = feed if feed is not None else sum(solution.feed.values())
    return float(solution.bed_flows[species][-1] / feed)


def segregated_yields(kiln, solution, peclet: float = 5.0, n_classes: int = 200) -> dict:
    r"""Outlet bed composition of the RTD classes in segregated flow, as the rotaryPyrolysis
    script treats its particle classes: every class crosses the converged kiln's bed
    temperature profile (frozen, shared by all classes) at its own speed.

    The bed reactions of the mechanism are first order (law ``arrhenius``), so a class of
    residence-time factor :math:`\theta` leaves cell j with

    .. math:: m_{out} = \exp\!\big(\theta\,\Delta t_j\,K(T_j)\big)\,m_{in},\qquad
              \Delta t_j = A_{bed,j}\,\Delta z/\dot V_j

    :math:`\Delta t_j` (s) the plug-flow time in the cell at the bed's volume flow
    :math:`\dot V` (m3/s, the depth law's: :meth:`~rotarykiln.kiln.residual.KilnResidual.volume_flow`)
    and :math:`K(T)` (1/s) the rate matrix of the mechanism at the cell's bed temperature. The
    classes are ``n_classes`` intervals of the closed-closed axial dispersion RTD at ``peclet``
    (:func:`rotarykiln.rtd.dispersion.closed_closed_cdf`, mean :math:`\tau = \sum_j \Delta t_j`),
    each at its mean :math:`\theta`, weighted by its share of the feed; the outlet is
    :math:`\sum_c w_c\,m_{out}(\theta_c)`.

    Parameters
    ----------
    kiln : Kiln
        A reacting kiln whose bed reactions use the ``arrhenius`` law.
    solution : KilnSolution
        Its converged solution (normally in plug flow: the classes carry the RTD).
    peclet : float
        Bed Peclet number u L / D of the RTD, -.
    n_classes : int
        Number of residence-time classes.

    Returns
    -------
    dict
        ``"rtd"`` and ``"plug"``: bed species -> outlet mass flow over the total feed (-), for
        the RTD average and the plug-flow class; ``"tau"``: the mean residence time (s);
        ``"classes"``.

    Examples
    --------
    >>> import warnings
    >>> from rotarykiln.case import load_case
    >>> from rotarykiln.cases import builtin_case_path
    >>> from rotarykiln.kiln.from_case import kiln_from_case
    >>> from rotarykiln.kiln.steady.solve import solve_kiln
    >>> case = load_case(builtin_case_path("rotary_pyrolysis"))
    >>> kiln, _ = kiln_from_case(case.replace({"bed.axial_dispersion": "plug"}))
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore")
    ...     sol = solve_kiln(kiln, 40)
    >>> r = segregated_yields(kiln, sol, peclet=5.0, n_classes=50)
    >>> round(r["tau"]), bool(r["rtd"]["char"] < r["plug"]["char"])
    (552, True)

    References
    ----------
    M. Pichler et al., J. Anal. Appl. Pyrolysis 158 (2021) 105171 (the segregated classes);
    O. Levenspiel, Chemical Reaction Engineering, 3rd ed. (1999), ch. 11 and 13.
    """
    from scipy.linalg import expm

    from rotarykiln.kiln.residual import KilnResidual
    from rotarykiln.rtd.dispersion import closed_closed_cdf

    x = solution.fluxes["x"]
    res = KilnResidual(kiln, x.shape[0])
    geo = res.geometry(x)
    _, _, qb, _ = res.faces(x)
    v = res.volume_flow(qb)
    dt = geo.bed_area * res.dz / (0.5 * (v[1:] + v[:-1]))  # s per cell, mean class
    tau = float(dt.sum())
    sp = kiln.chemistry.mechanism.species
    names = list(sp.bed_names)
    idx = {s: i for i, s in enumerate(names)}
    T = solution.t_bed  # cell means, K
    K = np.zeros((T.size, len(names), len(names)))
    for r in kiln.chemistry.mechanism.reactions:
        if r.phase != "bed" or r.law.name != "arrhenius":
            continue
        k = r.params["A"] * np.exp(-r.params["E"] / (R_GAS * T))
        b = idx[r.basis]
        for s, i in idx.items():
            K[:, i, b] += r.mass_stoichiometry[sp.index(s)] * k
    m0 = np.zeros(len(names))
    for s, q in kiln.feed.flows.items():
        m0[idx[s]] = q
    m0 = m0 / m0.sum()
    edges = np.concatenate([[0.0], np.geomspace(0.02, 8.0, n_classes - 1), [np.inf]])
    cdf = np.concatenate([[0.0], closed_closed_cdf(edges[1:-1] * tau, tau, peclet), [1.0]])
    w = np.diff(cdf)
    mid = np.concatenate([0.5 * (edges[1:-2] + edges[2:-1]), [edges[-2] * 1.2]])
    mid = np.concatenate([[0.5 * edges[1]], mid])[: w.size]

    # eigen-decomposition of each cell's rate matrix: exp(theta dt K) for all classes at once
    # (expm where the eigenvectors are ill-conditioned)
    modes = []
    for j in range(T.size):
        lam, V = np.linalg.eig(K[j])
        if np.linalg.cond(V) < 1e8:
            modes.append((lam, V, np.linalg.inv(V)))
        else:
            modes.append(None)

    def outlet(theta):
        th = np.atleast_1d(np.asarray(theta, dtype=float))
        m = np.broadcast_to(m0, (th.size, m0.size)).astype(complex)
        for j in range(T.size):
            if modes[j] is None:
                E = expm(th[:, None, None] * dt[j] * K[j][None])
                m = np.einsum("cij,cj->ci", E, m)
            else:
                lam, V, Vi = modes[j]
                m = (np.exp(np.outer(th * dt[j], lam)) * (m @ Vi.T)) @ V.T
        return m.real

    m_cls = outlet(mid)
    avg = (w[:, None] * m_cls).sum(0) / w.sum()
    plug = outlet(np.array([1.0]))[0]
    return {
        "rtd": dict(zip(names, avg, strict=True)),
        "plug": dict(zip(names, plug, strict=True)),
        "tau": tau,
        "classes": n_classes,
    }
