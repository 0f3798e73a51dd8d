"""Where the heat goes in Barr's fired pilot kiln: energy map and bias per third (issue 23).

For every trial (T2, T3, T4, T6, T9) the built-in case is solved as it is, and per third of the
kiln (feed end 0-1.83 m, middle, burner end 3.67-5.5 m) the script prints, in kW:

- ``gas>bed``: what the gas gives the bed surface (convection + radiation, gas -> bed path);
- ``gas>wall``: what the gas gives the exposed wall (convection + radiation);
- ``wall>bed``: what the wall passes to the bed (covered-wall contact + direct radiation
  through the gas);
- ``shell``: the shell loss; ``gas drop``: the enthalpy the gas loses over the third (its sum
  over the thirds plus the exhaust is what the burner put in);
- ``bed gain``: the enthalpy the bed gains over the third, model and measured (the sand's
  h(T) between the measured bed temperatures interpolated at the ends of the third, the feed
  at 298.15 K at z = 0);

and the exhaust (the gas leaving at the feed end), then the mean bias (model - measured, K) of
the bed, the gas 2.5 cm above the bed, the gas 10 cm off the wall and the inner wall in each
third. ``--variant`` solves instead with model choices changed in every trial alike (a YAML
mapping merged into each case, e.g. ``"{closures: {radiation_model: banded}}"``).

Usage::

    python docs/scripts/barr_energy_map.py            # the five trials as built in
    python docs/scripts/barr_energy_map.py --trials T2 T9
    python docs/scripts/barr_energy_map.py --variant "{burner: {reference_temperature: 25 degC}}"
"""

from __future__ import annotations

import argparse
import copy
import warnings

import numpy as np
import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case
from rotarykiln.kiln.residual import KilnResidual
from rotarykiln.kiln.steady.solve import solve_kiln

TRIALS = ("T2", "T3", "T4", "T6", "T9")
THIRDS = ("feed", "middle", "burner")
PROFILES = (
    ("bed", "bed"),
    ("gas", "gas above bed"),
    ("gas_wall", "gas off wall"),
    ("wall", "wall"),
)


def _merge(base: dict, extra: dict) -> dict:
    for key, value in extra.items():
        if isinstance(value, dict) and isinstance(base.get(key), dict):
            _merge(base[key], value)
        else:
            base[key] = value
    return base


def solve_trial(trial: str, variant: dict | None = None):
    """The kiln and solution of a built-in Barr case, with ``variant`` merged in."""
    raw = yaml.safe_load(builtin_case_path(f"barr_{trial}").read_text())
    _merge(raw, copy.deepcopy(variant or {}))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the Li film fit's extrapolation, reported elsewhere
        kiln, cells = kiln_from_case(parse_case(raw))
        return kiln, solve_kiln(kiln, cells)


def _thirds(z, length):
    edges = np.linspace(0.0, length, 4)
    return [(z >= lo) & (z < hi) for lo, hi in zip(edges[:-1], edges[1:], strict=True)]


def energy_map(kiln, sol) -> dict:
    """Heat flows per third (W): the paths, shell loss, gas drop, bed gain (model, measured);
    and the exhaust (W, the gas's sensible enthalpy leaving, 298.15 K basis)."""
    res = KilnResidual(kiln, len(sol.z))
    ex = res.exchange
    f = sol.fluxes
    dz = np.diff(sol.z_nodes)
    qg = np.stack([sol.gas_flows[s] for s in res.gas_names], axis=-1)
    gas = res.gas_state(0.5 * (qg[1:] + qg[:-1]))
    rad_gw, rad_gb, rad_wb = (0.0, 0.0, 0.0)
    if kiln.closures.radiation:
        rad_gw, rad_gb, rad_wb = ex.radiation(gas, sol.t_gas, sol.t_bed, sol.t_wall, paths=True)
    per_m = {
        "gas>bed": f["q_gas_bed_conv"] + rad_gb,
        "gas>wall": f["q_gas_wall_conv"] + rad_gw,
        "wall>bed": f["q_covered_wall_bed"] + rad_wb,
        "shell": f["q_shell_loss"],
    }
    # every path of the network is in the sums: the gas loses gas>bed + gas>wall
    solid = kiln.bed.material
    h_model = solid.enthalpy(sol.t_bed_nodes) * kiln.feed_flow
    m = sol.measurements
    zb = np.concatenate([[0.0], np.asarray(m["z_bed"])])
    tb = np.concatenate([[kiln.feed.temperature], np.asarray(m["t_bed"])])
    out = {}
    for i, sel in enumerate(_thirds(sol.z, kiln.drum.length)):
        row = {k: float(np.sum(v[sel] * dz[sel])) for k, v in per_m.items()}
        row["gas drop"] = row["gas>bed"] + row["gas>wall"]
        lo, hi = kiln.drum.length * i / 3, kiln.drum.length * (i + 1) / 3
        j0, j1 = np.searchsorted(sol.z_nodes, [lo - 1e-9, hi - 1e-9])
        row["bed gain"] = float(h_model[min(j1, len(h_model) - 1)] - h_model[j0])
        t_lo, t_hi = np.interp([lo, hi], zb, tb)  # beyond the last reading: held
        row["bed gain measured"] = float(
            kiln.feed_flow * (solid.enthalpy(np.array(t_hi)) - solid.enthalpy(np.array(t_lo)))
        )
        out[THIRDS[i]] = row
    out["exhaust"] = float(sol.energy_sheet.get("exhaust_loss_W", np.nan))
    return out


def biases(sol, length: float) -> dict:
    """Mean bias (model - measured, K) per profile and third (NaN where nothing is measured)."""
    m = sol.measurements
    at = {
        "bed": sol.bed_temperature_at,
        "gas": sol.gas_temperature_at,
        "gas_wall": sol.gas_temperature_at,
        "wall": sol.wall_temperature_at,
    }
    out = {}
    for key, _ in PROFILES:
        z, t = np.asarray(m[f"z_{key}"]), np.asarray(m[f"t_{key}"])
        d = at[key](z) - t
        edges = np.linspace(0.0, length, 4)
        edges[-1] += 1e-9
        out[key] = [
            float(np.mean(d[(z >= a) & (z < b)])) if np.any((z >= a) & (z < b)) else np.nan
            for a, b in zip(edges[:-1], edges[1:], strict=True)
        ] + [float(np.mean(d))]
    return out


def report(trials, variant=None) -> None:
    for trial in trials:
        kiln, sol = solve_trial(trial, variant)
        fl = sol.burner
        em = energy_map(kiln, sol)
        r = sol.measured_rmse()
        print(
            f"\n{trial}: LHV {fl['fuel_lhv_input_W'] / 1e3:.1f} kW, excess air "
            f"{fl['excess_air']:.2f}, T_ad {fl['adiabatic_temperature_K']:.0f} K | RMSE bed "
            f"{r['bed']:.1f} gas {r['gas']:.1f} gas off wall {r['gas_wall']:.1f} wall "
            f"{r['wall']:.1f} K"
        )
        keys = ("gas>bed", "gas>wall", "wall>bed", "shell", "gas drop", "bed gain")
        print(f"  {'kW':8s}" + "".join(f"{k:>10s}" for k in keys) + f"{'bed meas.':>10s}")
        for third in THIRDS:
            row = em[third]
            cells = "".join(f"{row[k] / 1e3:10.2f}" for k in keys)
            print(f"  {third:8s}{cells}{row['bed gain measured'] / 1e3:10.2f}")
        print(f"  exhaust {em['exhaust'] / 1e3:.2f} kW, shell total {sol.shell_loss / 1e3:.2f} kW")
        b = biases(sol, kiln.drum.length)
        print(f"  {'bias K':14s}" + "".join(f"{t:>8s}" for t in (*THIRDS, "all")))
        for key, label in PROFILES:
            print(f"  {label:14s}" + "".join(f"{v:+8.0f}" for v in b[key]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trials", nargs="+", default=list(TRIALS), choices=TRIALS)
    parser.add_argument("--variant", default=None, help="YAML mapping merged into every case")
    args = parser.parse_args()
    report(args.trials, yaml.safe_load(args.variant) if args.variant else None)


if __name__ == "__main__":
    main()
