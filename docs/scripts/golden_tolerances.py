"""How far each built-in kiln case's converged temperatures are determined by the solver: the
numbers behind the per-case ``TEMPERATURE_TOL`` of ``tests/test_golden_outputs.py``.

At each case's converged state ``x`` (its own cells, the solver's tolerance 1e-11 of the
reference heat ``Q_ref``), with the banded Jacobian ``J`` of the solver:

- tolerance: the largest ``|J^-1 r|`` over the temperature unknowns for 8 residuals ``r`` of
  random signs, each row ``1e-11 Q_ref``: how far from the root an iterate Newton accepts may
  lie (two builds of numpy may end on either side);
- round-off: the same for ``r`` of 2.2e-16 ``|J| |x|`` row by row (a unit round-off in every
  term of every balance);
- final residual and Newton correction: the solve's last ``max|R| / Q_ref`` and ``|J^-1 R|``.

Run: ``.venv/bin/python docs/scripts/golden_tolerances.py [CASE ...]`` (about a minute on two
cores); prints a Markdown table.
"""

from __future__ import annotations

import importlib.util
import sys
import warnings
from pathlib import Path

import numpy as np
from scipy.linalg import solve_banded

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.residual import KilnResidual
from rotarykiln.kiln.steady import newton
from rotarykiln.kiln.steady.solve import newton_options, solve_kiln

TOL = 1e-11
EPS = 2.2e-16
SAMPLES = 8


def _golden_cases() -> list[str]:
    path = Path(__file__).resolve().parents[2] / "tests" / "test_golden_outputs.py"
    spec = importlib.util.spec_from_file_location("golden", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod._kiln_cases()


def resolution(name: str) -> dict:
    """The four numbers of the module docstring for one built-in case, K."""
    kiln, cells = kiln_from_case(load_case(builtin_case_path(name)))
    x = solve_kiln(kiln, cells, tol=TOL).fluxes["x"]
    res = KilnResidual(kiln, cells)
    R = res(x)
    ab, bw = newton._banded_jacobian(
        res, x, R, step_floor=newton_options(res, tol=TOL, max_iter=60)["step_floor"]
    )
    n, nv = x.shape
    size, nt = n * nv, res.i_species
    cols = np.arange(size)
    jx = np.zeros(size)  # |J| |x| per row: ab[bw + i - j, j] = J[i, j]
    for d in range(-bw, bw + 1):
        rows = cols + d
        ok = (rows >= 0) & (rows < size)
        np.add.at(jx, rows[ok], np.abs(ab[bw + d, ok]) * np.abs(x.ravel()[cols[ok]]))

    def largest(r_of):
        out = 0.0
        for seed in range(SAMPLES):
            signs = np.random.default_rng(seed).choice([-1.0, 1.0], size)
            dx = solve_banded((bw, bw), ab, r_of(signs)).reshape(n, nv)
            out = max(out, float(np.abs(dx[:, :nt]).max()))
        return out

    correction = solve_banded((bw, bw), ab, -R.ravel()).reshape(n, nv)
    return {
        "tolerance": largest(lambda s: TOL * res.q_ref * s),
        "round-off": largest(lambda s: EPS * jx * s),
        "final residual": float(np.abs(R).max() / res.q_ref),
        "Newton correction": float(np.abs(correction[:, :nt]).max()),
    }


def main(names) -> None:
    warnings.simplefilter("ignore")
    print("| case | tolerance (K) | round-off (K) | final residual | Newton correction (K) |")
    print("|---|---|---|---|---|")
    for name in names or _golden_cases():
        r = resolution(name)
        print(f"| {name} | " + " | ".join(f"{v:.3g}" for v in r.values()) + " |", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
