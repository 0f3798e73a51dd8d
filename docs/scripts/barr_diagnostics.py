"""The two diagnostic tables of docs/validation.md, "Barr's fired pilot kiln" (issue 10).

``feed``: the bed RMSE of T2, T3, T4, T6 and T9 when the sand's feed temperature is changed from the
measured ambient (298.15 K) to 350-500 K, everything else as in the built-in cases. A
diagnostic of what fitting an inlet temperature would do; the cases keep the measured feed.

``gaps``: gas minus bed and wall minus bed, measured and computed, averaged over the mid-kiln
wall positions (1.33-3.38 m), the bed and gas readings interpolated there.

Usage::

    python docs/scripts/barr_diagnostics.py feed
    python docs/scripts/barr_diagnostics.py gaps
"""

from __future__ import annotations

import argparse
import copy
import warnings

import numpy as np
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.commands.kiln_runs import run_kiln_case

TRIALS = ("T2", "T3", "T4", "T6", "T9")
FEEDS_K = (298.15, 350.0, 400.0, 450.0, 500.0)


def _raw(trial):
    return yaml.safe_load(builtin_case_path(f"barr_{trial}").read_text())


def _solve(raw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the Li film fit's extrapolation, reported elsewhere
        return run_kiln_case(parse_case(raw))


def feed_table():
    """Bed RMSE (K) per trial and feed temperature."""
    print("feed K  " + "  ".join(f"{t:>5}" for t in TRIALS) + "   mean")
    for feed in FEEDS_K:
        row = []
        for t in TRIALS:
            raw = copy.deepcopy(_raw(t))
            raw["operation"]["feed_temperature"] = f"{feed} K"
            row.append(_solve(raw).measured_rmse()["bed"])
        cells = "  ".join(f"{v:5.1f}" for v in row)
        print(f"{feed:6.1f}  {cells}  {np.mean(row):5.1f}")


def gap_table():
    """Mean gas - bed and wall - bed (K) over the mid-kiln wall positions."""
    for t in TRIALS:
        sol = _solve(_raw(t))
        m = sol.measurements
        z = np.asarray(m["z_wall"])
        z = z[(z >= 0.8) & (z <= 3.5)]
        bed = np.interp(z, m["z_bed"], m["t_bed"])
        gas = np.interp(z, m["z_gas"], m["t_gas"])
        wall = np.interp(z, m["z_wall"], m["t_wall"])
        p_bed, p_gas = sol.bed_temperature_at(z), sol.gas_temperature_at(z)
        p_wall = sol.wall_temperature_at(z)
        print(
            f"{t}: gas-bed measured {np.mean(gas - bed):5.0f} model {np.mean(p_gas - p_bed):5.0f}"
            f" | wall-bed measured {np.mean(wall - bed):4.0f} model {np.mean(p_wall - p_bed):4.0f}"
        )


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("table", choices=("feed", "gaps"))
    args = parser.parse_args()
    {"feed": feed_table, "gaps": gap_table}[args.table]()


if __name__ == "__main__":
    main()
