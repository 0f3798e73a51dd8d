"""Seeded fuzz of the data files (issue 21): calibration data (``rotarykiln calibrate --data``)
and tracer curves (``rotarykiln rtd fit``). Every mutation of a valid file (a cell replaced by an
odd value, a line deleted or repeated, a column added, a character or a byte inserted, the file
cut short or a huge value written) is either read and used or refused with one InputError line,
never another exception, and the refusal is fast.

The bases: a calibration data set of the cheap model
:func:`rotarykiln.studies.examples.exponential_heating` (fitted here, a few evaluations) and the
shipped tracer curve ``examples/tracer_synthetic.csv`` (read, analysed and fitted, open-open).

Budget: a fixed seed, 60 mutations per kind and seed (a few seconds in all). The same mutations
at scale, through the CLI: ``docs/scripts/fuzz_campaign_data.py``.
"""

from __future__ import annotations

import random
import time
import warnings
from pathlib import Path

import pytest

from rotarykiln.errors import ConvergenceError, InputError

ROOT = Path(__file__).resolve().parents[1]
TRACER_FILE = ROOT / "examples" / "tracer_synthetic.csv"
KINDS = ("calibration", "tracer")

CALIBRATION_TEXT = "quantity,z,value,uncertainty\n" + "".join(
    f"bed,{z},{700 - 400 * 2.718281828 ** (-0.6 * z):.2f},5\n" for z in (0.25, 0.75, 1.25, 1.75)
)

CELLS = [
    "",
    "abc",
    "nan",
    "inf",
    "-inf",
    "1e308",
    "-1e308",
    "1e-300",
    "1e400",
    "0",
    "-1",
    "1e15",
    "0x10",
    "1_000",
    "1,5",
    '"1\n2"',
    '"',
    "'",
    "#",
    "é",
    "\u202e",
    "\x1b[31m",
    "9" * 400,
    "x" * 5000,
    "bed_outlet_temperature_K",
    "gas",
    "None",
    " ",
]


def _mutate(text: str, rng: random.Random) -> bytes:
    """One random damage of a CSV text, as bytes (some are not UTF-8)."""
    lines = text.splitlines(keepends=True)
    op = rng.randrange(12)
    i = rng.randrange(len(lines))
    if op <= 3:  # a cell replaced
        cells = lines[i].rstrip("\n").split(",")
        cells[rng.randrange(len(cells))] = rng.choice(CELLS)
        lines[i] = ",".join(cells) + "\n"
    elif op == 4:  # a line deleted
        del lines[i]
    elif op == 5:  # a line repeated (sometimes past the row limit)
        lines[i:i] = [lines[i]] * rng.choice([1, 5, 1000, 100_001])
    elif op == 6:  # a column added or removed
        lines = [
            (line.rstrip("\n") + ",1\n") if rng.random() < 0.8 else line.split(",", 1)[-1]
            for line in lines
        ]
    elif op == 7:  # a character inserted
        line = lines[i]
        k = rng.randrange(len(line) + 1)
        lines[i] = line[:k] + rng.choice([",", '"', "\n", "\t", "\r", "#", ";", " "]) + line[k:]
    elif op == 8:  # the file cut short
        cut = "".join(lines)
        return cut[: rng.randrange(len(cut) + 1)].encode()
    elif op == 9:  # a byte that is not UTF-8, or a NUL
        raw = "".join(lines).encode()
        k = rng.randrange(len(raw) + 1)
        return raw[:k] + rng.choice([b"\xe9", b"\xff\xfe", b"\x00", b"\xc3"]) + raw[k:]
    elif op == 10:  # many columns in the header
        lines[0] = lines[0].rstrip("\n") + "," * rng.choice([3, 150, 10_000]) + "\n"
    else:  # the header replaced
        lines[0] = rng.choice(["", "a,b\n", "time,C\n", "time [kg],C\n", "z,value\n", "\n"])
    return "".join(lines).encode("utf-8", "surrogatepass")


def _mutations(kind: str, n: int, seed: int):
    """``n`` damaged files of ``kind`` ("calibration" or "tracer"): (index, bytes)."""
    base = CALIBRATION_TEXT if kind == "calibration" else TRACER_FILE.read_text()
    rng = random.Random(f"{kind}-{seed}")
    for i in range(n):
        yield i, _mutate(base, rng)


def use_file(kind: str, path: Path) -> None:
    """Read the file as the command would, and use it: the calibration data fitted with the
    exponential heating model, the tracer curve analysed and fitted (open-open)."""
    if kind == "calibration":
        from rotarykiln.studies.calibration import calibrate, read_measurements
        from rotarykiln.studies.examples import EXPONENTIAL_CASE, exponential_heating

        data = read_measurements(path)
        calibrate(
            exponential_heating,
            EXPONENTIAL_CASE,
            ["heat.exchange=1 1/m [0.01 1/m, 10 1/m]"],
            data,
            max_nfev=20,
        )
    else:
        from rotarykiln.rtd.fitting import fit_tracer
        from rotarykiln.rtd.tracer import analyse_tracer, read_tracer_csv

        t, signal, _ = read_tracer_csv(path)
        fit_tracer(analyse_tracer(t, signal), model="open-open", length=1.95)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("seed", [1, 2])
def test_mutated_data_files_are_used_or_refused_in_one_line(kind, seed, tmp_path):
    outcomes = {"accepted": 0, "refused": 0, "solver": 0}
    for i, raw in _mutations(kind, 60, seed):
        path = tmp_path / f"{kind}{i}.csv"
        path.write_bytes(raw)
        t0 = time.perf_counter()
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                use_file(kind, path)
            outcomes["accepted"] += 1
        except InputError as exc:
            msg = str(exc)
            assert "\n" not in msg and "\r" not in msg, (kind, i, msg)
            assert len(msg) < 1000, (kind, i, msg[:200])
            outcomes["refused"] += 1
        except ConvergenceError:  # a clean failure of the fit of a damaged curve
            outcomes["solver"] += 1
        assert time.perf_counter() - t0 < 3.0, (kind, i)
    # the mutations exercise both branches
    assert outcomes["refused"] > 10 and outcomes["accepted"] > 5, outcomes


def test_the_unmutated_files_are_accepted(tmp_path):
    p = tmp_path / "data.csv"
    p.write_text(CALIBRATION_TEXT)
    use_file("calibration", p)
    use_file("tracer", TRACER_FILE)
