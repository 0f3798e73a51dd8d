"""Seeded fuzz of the input files that are not case files (issue 21): transient events files,
species files and reaction files. Every mutation of a shipped file (a value replaced or deleted
in its structure, or its text damaged: a line deleted or repeated, a character inserted, the file
cut short) is either read or refused with one InputError line, never another exception, and the
refusal is fast and in words.

The bases: ``rotarykiln/examples/barr_T4_startup.yaml`` (events, checked against the barr_T4 kiln), the
built-in species table ``chemistry/species.yaml`` as a user species file (its species renamed,
plus a NASA-7 and a polynomial c_p species), and the built-in reaction files
``chemistry/reactions/*.yaml``.

Budget: a fixed seed, 100-200 mutations per kind (about 6 s in all, 3 s of them building the
barr_T4 kiln the events are checked against). The same mutations at
scale: ``docs/scripts/fuzz_campaign_files.py``.
"""

from __future__ import annotations

import random
import re
import time
import warnings
from pathlib import Path

import pytest
import yaml

from fuzz_helpers import mutate
from rotarykiln.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
EVENTS_FILE = ROOT / "src" / "rotarykiln" / "examples" / "barr_T4_startup.yaml"
CHEMISTRY = ROOT / "src" / "rotarykiln" / "chemistry"
EVENTS_UNTIL = 36_000.0  # s: the example's run (10 h)
KINDS = ("events", "species", "reactions")

VALUES = [
    None,
    1,
    -1,
    0,
    3600,
    1.5,
    True,
    "abc",
    "",
    [1, 2],
    [],
    {"a": 1},
    {},
    float("nan"),
    1e308,
    -1e308,
    1e-308,
    "1 h",
    "-1 h",
    "1e9 h",
    "1e-3 s",
    "1e6 rpm",
    "1e-6 K",
    "0 kg/h",
    "1e9 kg/h",
    "2.2 NL/s",
    "9**9**9 m",
    "stop",
    "feed",
    "speed",
    "fuel_flow",
    "1 um",
    "C2H8:1",
    "x" * 300,
    "two\nlines",
]
TEXT_INSERTS = [
    ":",
    "{",
    "[",
    "]",
    "- ",
    "&a ",
    "*a",
    "*b",
    "\t",
    "!!python/object:os.system ",
    "'",
]
RAW = re.compile(r"Input should|Value error|\[type=|Traceback|pydantic")


KEYS = ("elements", "composition", "molar_mass", "cp", "h_f", "description")


def species_base() -> dict:
    """A user species file made from the built-in table: every species renamed (``_u``), and
    two with a temperature-dependent c_p (NASA-7, polynomial)."""
    table = yaml.safe_load((CHEMISTRY / "species.yaml").read_text(encoding="utf-8"))
    out = {"elements": table["elements"]}
    for phase in ("bed", "gas"):  # the first four of each phase: a file of a useful size
        names = list(table[phase])[:4]
        out[phase] = {
            f"{n}_u": {k: v for k, v in table[phase][n].items() if k in KEYS} for n in names
        }
    out["gas"]["CO_nasa"] = {  # GRI-Mech 3.0's CO under another name
        "elements": {"C": 1, "O": 1},
        "cp": {
            "nasa7": {
                "T_range": [200.0, 1000.0, 3500.0],
                "coefficients": [
                    [3.57953347, -6.1035368e-4, 1.01681433e-6, 9.07005884e-10, -9.04424499e-13],
                    [2.71518561, 2.06252743e-3, -9.98825771e-7, 2.30053008e-10, -2.03647716e-14],
                ],
            }
        },
    }
    out["bed"]["straw_u"] = {
        "composition": {"C": 0.47, "H": 0.06, "O": 0.47},
        "molar_mass": 0.024,
        "cp": {"polynomial": {"T_range": [250, 1000], "coefficients": [1500.0, 1.0]}},
    }
    return out


def bases() -> dict[str, list[tuple[str, str]]]:
    """The base files of each kind: (name, YAML text)."""
    reactions = sorted((CHEMISTRY / "reactions").glob("*.yaml"))
    return {
        "events": [(EVENTS_FILE.name, EVENTS_FILE.read_text(encoding="utf-8"))],
        "species": [("species_u.yaml", yaml.safe_dump(species_base(), sort_keys=False))],
        "reactions": [(p.name, p.read_text(encoding="utf-8")) for p in reactions],
    }


def _text_mutation(text: str, rng: random.Random) -> bytes:
    lines = text.splitlines(keepends=True) or ["\n"]
    op = rng.choice(("delete", "repeat", "insert", "cut", "latin1", "indent"))
    i = rng.randrange(len(lines))
    if op == "delete":
        del lines[i]
    elif op == "repeat":  # often a key twice
        lines.insert(i, lines[i])
    elif op == "insert":
        line = lines[i]
        at = rng.randrange(len(line) + 1)
        lines[i] = line[:at] + rng.choice(TEXT_INSERTS) + line[at:]
    elif op == "indent":
        lines[i] = rng.choice(("  ", " ", "\t")) + lines[i]
    elif op == "cut":
        out = "".join(lines)
        return out[: rng.randrange(len(out) + 1)].encode("utf-8")
    else:
        return "".join(lines).encode("utf-8") + "# caf\xe9\n".encode("latin-1")
    return "".join(lines).encode("utf-8")


def mutations(kind: str, n: int, seed: int):
    """``n`` mutated files of ``kind``: (base name, description, bytes of the file)."""
    rng = random.Random(f"{kind}-{seed}")
    files = bases()[kind]
    for _ in range(n):
        name, text = rng.choice(files)
        if rng.random() < 0.35:
            yield name, "text", _text_mutation(text, rng)
            continue
        data, path, value = mutate(yaml.safe_load(text), VALUES, rng)
        try:
            dumped = yaml.safe_dump(data, allow_unicode=True, sort_keys=False)
        except yaml.YAMLError:
            continue
        yield name, "/".join(map(str, path)) + f" = {value!r}"[:60], dumped.encode("utf-8")


def barr_kiln():
    from rotarykiln.case import load_case
    from rotarykiln.cases import builtin_case_path
    from rotarykiln.kiln.from_case import kiln_from_case

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return kiln_from_case(load_case(builtin_case_path("barr_T4")))[0]


def read_file(kind: str, path: Path, kiln=None):
    """Read (and check) the file ``path`` of ``kind`` as the program does; its result."""
    if kind == "events":
        from rotarykiln.transient_file import parse_transient, read_transient_file

        return parse_transient(read_transient_file(path), kiln, EVENTS_UNTIL)
    if kind == "species":
        from rotarykiln.chemistry.species import load_species

        return load_species(path)
    from rotarykiln.chemistry.reaction import load_reactions

    return load_reactions(path)


@pytest.fixture(scope="module")
def kiln():
    return barr_kiln()


def test_the_bases_are_read():
    for kind in KINDS:
        assert bases()[kind]


#: Mutations per kind in the suite (a pure-Python YAML parse of a species file is ~25 ms).
BUDGET = {"events": 200, "species": 100, "reactions": 200}


@pytest.mark.parametrize("kind", KINDS)
def test_mutated_files_are_read_or_refused_in_one_line(tmp_path, kiln, kind):
    path = tmp_path / f"{kind}.yaml"
    accepted = refused = 0
    for name, what, content in mutations(kind, BUDGET[kind], seed=21):
        path.write_bytes(content)
        t = time.perf_counter()
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                read_file(kind, path, kiln)
            accepted += 1
        except InputError as exc:
            msg = str(exc)
            assert "\n" not in msg and len(msg) < 1000, (name, what, msg)
            assert not RAW.search(msg), (name, what, msg)
            refused += 1
        assert time.perf_counter() - t < 2.0, (name, what)
    # both outcomes occur: the mutations are neither all harmless nor all fatal
    assert accepted > 5 and refused > 5, (accepted, refused)


@pytest.mark.parametrize(
    ("spec", "message"),
    [
        ({"elements": {"O": 1e308}}, "elements.O: 1e+308 is not in (0, 1e+06]"),
        ({"elements": {"H": 1e-9}}, "a molar mass of 1.008e-09 g/mol is not a molar mass in"),
        ({"composition": {"C": 1.0}, "molar_mass": 1e-308}, "molar_mass: 1e-308 is not a"),
    ],
)
def test_species_of_unphysical_molar_mass_are_refused(spec, message):
    # found by the campaign: 1e308 atoms of O made a species of infinite molar mass
    from rotarykiln.chemistry.species import load_species

    with pytest.raises(InputError, match=re.escape(message)):
        load_species({"gas": {"X_u": {**spec, "cp": 1000.0}}})
