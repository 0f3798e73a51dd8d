"""One YAML loader with one set of limits for every YAML file read (issue 21): case files,
transient events files, species and reaction files, and a species file a case names. Each
hostile file is refused quickly with one InputError line that names the file and repeats none
of its expanded content."""

from __future__ import annotations

import time
from pathlib import Path

import pytest
import yaml

from rotarykiln.case import load_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.reaction import load_reactions
from rotarykiln.chemistry.species import load_species
from rotarykiln.errors import InputError
from rotarykiln.transient_file import read_transient_file
from rotarykiln.yaml_limits import MAX_YAML_BYTES, load_yaml_text, read_yaml_file

BASE = yaml.safe_load(Path(builtin_case_path("limestone_calcination")).read_text())


def _named_species(path: Path) -> None:
    """A case beside ``path`` naming it as its species file."""
    case = path.parent / "the_case.yaml"
    data = {**BASE, "chemistry": {**BASE["chemistry"], "species": path.name}}
    case.write_text(yaml.safe_dump(data), encoding="utf-8")
    load_case(case)


READERS = {
    "case": load_case,
    "events": read_transient_file,
    "species": load_species,
    "reactions": load_reactions,
    "named species": _named_species,
}


def nested(levels: int) -> str:
    return "\n".join(" " * i + f"k{i}:" for i in range(levels)) + "\n" + " " * levels + "x: 1\n"


LAUGHS = 'a: &a ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]\n' + "".join(
    f"{chr(98 + i)}: &{chr(98 + i)} [" + ", ".join([f"*{chr(97 + i)}"] * 9) + "]\n"
    for i in range(8)
)
# content, the message's fragments, and those of a file a case names (no key of it shown)
HOSTILE = {
    "latin1": ("events: caf\xe9\n".encode("latin-1"), ["not UTF-8", "0xe9"], ["not UTF-8"]),
    "deep": (("k: " + "{a: " * 5000 + "1" + "}" * 5000).encode(), ["nested deeper than"], None),
    "deep_block": (nested(1000).encode(), ["nested deeper than 20 levels"], None),
    "deep_flow": (("k: " + "[" * 5000 + "]" * 5000 + "\n").encode(), ["nested deeper than"], None),
    "laughs": (LAUGHS.encode(), ["more than 100000 values", "aliases"], None),
    "duplicate": (
        b"events: []\nstart: cold\nevents: []\n",
        ['key "events" given twice (line 3)'],
        ["a key given twice (line 3)"],
    ),
    "inner_duplicate": (
        b"x:\n  y: 1\n  y: 2\n",
        ['key "y" given twice (line 3)'],
        ["a key given twice (line 3)"],
    ),
    "self_alias": (b"k: &k [1, *k]\n", ["alias *k refers to itself"], ["an alias refers"]),
    "long_number": (("k: " + "9" * 5000 + "\n").encode(), ["a number of 5000 characters"], None),
}


def _refused_quickly(reader, path, fragments, seconds=2.0) -> str:
    start = time.perf_counter()
    with pytest.raises(InputError) as err:
        reader(path)
    elapsed = time.perf_counter() - start
    text = str(err.value)
    assert "\n" not in text and len(text) < 400, text
    assert "lol" not in text, text  # an alias bomb's expansion is never shown
    for fragment in fragments:
        assert fragment in text, text
    assert elapsed < seconds, f"refused in {elapsed:.2f} s: {text}"
    return text


@pytest.mark.parametrize("kind", sorted(HOSTILE))
@pytest.mark.parametrize("reader", sorted(READERS))
def test_hostile_yaml_is_refused_in_one_line_by_every_reader(tmp_path, reader, kind):
    content, fragments, quiet = HOSTILE[kind]
    path = tmp_path / f"{kind}.yaml"
    path.write_bytes(content)
    if reader == "named species":  # a file a case names: no key or anchor of it is shown
        text = _refused_quickly(READERS[reader], path, ["chemistry.species", *(quiet or fragments)])
        assert '"events"' not in text and '"y"' not in text and "*k" not in text
    else:
        _refused_quickly(READERS[reader], path, [str(path), *fragments])


@pytest.mark.parametrize("reader", sorted(READERS))
def test_a_60_mb_file_is_refused_by_its_size_before_it_is_read(tmp_path, reader):
    path = tmp_path / "huge.yaml"
    with path.open("wb") as fh:  # sparse: 60 MB on paper, nothing written
        fh.truncate(60_000_000)
    _refused_quickly(READERS[reader], path, ["60 MB is too large", "at most 1 MB"], seconds=0.5)


def test_a_file_just_over_the_limit_and_a_growing_one(tmp_path):
    path = tmp_path / "big.yaml"
    path.write_bytes(b"#" * (MAX_YAML_BYTES + 1))
    with pytest.raises(InputError, match="too large for a species file"):
        read_yaml_file(path, what="species file")
    with pytest.raises(InputError, match="too large for a YAML file"):
        read_yaml_file("/dev/zero")


def test_anchors_merges_and_the_shipped_files_still_load(tmp_path):
    text = "base: &b {x: 1, y: 2}\nother:\n  <<: *b\n  y: 3\n"
    assert load_yaml_text(text, "t.yaml")["other"] == {"x": 1, "y": 3}
    root = Path(__file__).resolve().parents[1]
    files = [*(root / "src" / "rotarykiln").rglob("*.yaml"), *(root / "examples").glob("*.yaml")]
    assert len(files) > 20
    for path in files:
        read_yaml_file(path)  # no duplicate key, no limit reached by a shipped file


def test_load_yaml_text_limits_text_in_memory():
    with pytest.raises(InputError, match=r"^upload\.yaml: 2 MB is too large for a case file"):
        load_yaml_text("#" * 2_000_000, "upload.yaml", what="case file")
    with pytest.raises(InputError, match=r"^upload\.yaml: nested deeper than 20 levels"):
        load_yaml_text("[" * 100_000, "upload.yaml")
    with pytest.raises(InputError, match=r"^upload\.yaml: not UTF-8 text \(byte 0xff at line 2\)"):
        load_yaml_text(b"a: 1\n\xff\n", "upload.yaml")
    with pytest.raises(InputError) as err:
        load_yaml_text("secret: 1\nsecret: 2\n", "upload.yaml", content=False)
    assert str(err.value) == "upload.yaml: a key given twice (line 2)"
