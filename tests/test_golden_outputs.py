"""Golden outputs of every built-in kiln case, from the command line: the profiles to 1e-6 K and
the summary numbers to 1e-9 (relative), so that a change of the code's structure that should not
change the physics is seen to change nothing.

The files in tests/golden/ are the output of ``rotarykiln run NAME --no-plots`` (the
``kiln_profiles.csv`` and ``kiln_summary.json`` of each case). A change that is meant to change
the physics regenerates them, in a commit of its own that names the cause::

    ROTARYKILN_WRITE_GOLDEN=1 python -m pytest tests/test_golden_outputs.py
"""

from __future__ import annotations

import json
import math
import os
import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path, list_builtin_cases
from rotarykiln.cli import main

GOLDEN = Path(__file__).with_name("golden")
WRITE = os.environ.get("ROTARYKILN_WRITE_GOLDEN") == "1"
TEMPERATURE_TOL = 1e-6  # K
RELATIVE_TOL = 1e-9


def _kiln_cases() -> list[str]:
    return [n for n in list_builtin_cases() if load_case(builtin_case_path(n)).has_kiln_model]


@pytest.mark.parametrize("name", _kiln_cases())
def test_builtin_case_gives_its_golden_outputs(name, tmp_path, monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")
    out = tmp_path / "out"
    with _quiet():
        assert main(["run", name, "--no-plots", "--out", str(out)]) == 0
    stem = name.replace("/", "__")
    csv, js = out / "kiln_profiles.csv", out / "kiln_summary.json"
    if WRITE:
        GOLDEN.mkdir(exist_ok=True)
        shutil.copy(csv, GOLDEN / f"{stem}_profiles.csv")
        shutil.copy(js, GOLDEN / f"{stem}_summary.json")
        pytest.skip("golden outputs written")
    want, got = pd.read_csv(GOLDEN / f"{stem}_profiles.csv"), pd.read_csv(csv)
    assert list(got.columns) == list(want.columns)
    for col in want.columns:
        a, b = got[col].to_numpy(float), want[col].to_numpy(float)
        if col.startswith("T_") and col.endswith("_K"):
            np.testing.assert_allclose(a, b, rtol=0, atol=TEMPERATURE_TOL, err_msg=col)
        else:
            scale = max(float(np.nanmax(np.abs(b))) if b.size else 0.0, 1e-300)
            np.testing.assert_allclose(a, b, rtol=0, atol=RELATIVE_TOL * scale, err_msg=col)
    want_s = json.loads((GOLDEN / f"{stem}_summary.json").read_text())
    got_s = json.loads(js.read_text())
    assert set(got_s) == set(want_s)
    for key, w in want_s.items():
        g = got_s[key]
        if isinstance(w, int | float) and not isinstance(w, bool) and w is not None:
            if math.isfinite(w):
                assert g == pytest.approx(w, rel=RELATIVE_TOL, abs=1e-12), key
        elif not key.endswith(("_csv", "_png", "_json")):
            assert g == w, key


class _quiet:
    """Warnings of the run (real ones, documented in each case's header) are not the subject."""

    def __enter__(self):
        import warnings

        self._ctx = warnings.catch_warnings()
        self._ctx.__enter__()
        warnings.simplefilter("ignore")
        return self

    def __exit__(self, *exc):
        return self._ctx.__exit__(*exc)
