"""Files a case names (issue 21, security): only files beside the case file, never a file's
content in a message.

A canary file outside the case folder holds a random string; every way of naming it (an
absolute path, ``..``, a symbolic link leading out) is refused, and the string appears in no
message. A case given as data (a Python mapping, an app upload) names no file at all.
"""

from __future__ import annotations

import secrets
from pathlib import Path

import pytest
import yaml

from rotarykiln.case import (
    case_file_path,
    load_case,
    parse_case,
    read_case_data,
)
from rotarykiln.case_io import case_to_yaml
from rotarykiln.cases import builtin_case_path
from rotarykiln.chemistry.species import load_species
from rotarykiln.cli import main
from rotarykiln.errors import InputError

SPECIES = {"bed": {"polymer": {"elements": {"C": 2, "H": 4}, "cp": 1500.0}}}
BASE = yaml.safe_load(Path(builtin_case_path("limestone_calcination")).read_text())


@pytest.fixture()
def folders(tmp_path):
    """(case folder, canary file outside it, the canary's random string)."""
    canary = "canary-" + secrets.token_hex(12)
    outside = tmp_path / "outside"
    outside.mkdir()
    secret = outside / "secret.yaml"
    secret.write_text(f"{canary}\n", encoding="utf-8")  # a YAML string: the whole content
    (outside / "keys.yaml").write_text(f"{canary}: 1\nbed: {canary}\n", encoding="utf-8")
    case_dir = tmp_path / "case"
    case_dir.mkdir()
    return case_dir, outside, canary


def _case_file(case_dir: Path, species) -> Path:
    data = {**BASE, "chemistry": {**BASE["chemistry"], "species": species}}
    path = case_dir / "case.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return path


def _refused(path: Path, canary: str, *fragments: str) -> str:
    with pytest.raises(InputError) as err:
        load_case(path)
    text = str(err.value)
    assert "\n" not in text and canary not in text, text
    assert text.startswith("chemistry.species: "), text
    for fragment in fragments:
        assert fragment in text, text
    return text


def test_an_absolute_path_is_refused_without_reading_it(folders):
    case_dir, outside, canary = folders
    for target in (outside / "secret.yaml", outside / "keys.yaml"):
        _refused(_case_file(case_dir, str(target)), canary, "is not accepted", "beside the case")
    # a system file: refused with the path as typed, its content never shown
    hostname = Path("/etc/hostname")
    text = _refused(_case_file(case_dir, str(hostname)), canary, '"/etc/hostname"')
    if hostname.is_file():
        content = hostname.read_text(errors="replace").strip()
        assert not content or content not in text.replace("/etc/hostname", "")


@pytest.mark.parametrize(
    "typed", ["../outside/secret.yaml", "sub/../../outside/keys.yaml", "./../outside/secret.yaml"]
)
def test_a_path_leaving_the_folder_is_refused(folders, typed):
    case_dir, _, canary = folders
    (case_dir / "sub").mkdir()
    _refused(_case_file(case_dir, typed), canary, "is not accepted")


def test_a_symbolic_link_leading_out_is_refused(folders):
    case_dir, outside, canary = folders
    (case_dir / "link.yaml").symlink_to(outside / "secret.yaml")
    (case_dir / "keys.yaml").symlink_to(outside / "keys.yaml")
    (case_dir / "out").symlink_to(outside, target_is_directory=True)
    for typed in ("link.yaml", "keys.yaml", "out/secret.yaml", "out/keys.yaml"):
        _refused(_case_file(case_dir, typed), canary, "is not accepted")


def test_a_file_beside_the_case_that_is_no_species_file_is_not_shown(folders):
    case_dir, _, canary = folders
    contents = {
        "text.yaml": f"{canary}\n",
        "mapping.yaml": f"{canary}: 1\n",
        "bed.yaml": f"bed: {canary}\n",
        "nested.yaml": f"bed: {{polymer: {{elements: {canary}}}}}\n",
        "broken.yaml": f"bed: [{canary}\n",
        "twice.yaml": f"{canary}: 1\n{canary}: 2\n",
        "latin1.yaml": None,
    }
    for name, content in contents.items():
        path = case_dir / name
        if content is None:
            path.write_bytes(f"bed: {canary} caf\xe9\n".encode("latin-1"))
        else:
            path.write_text(content, encoding="utf-8")
        _refused(_case_file(case_dir, name), canary, f'"{name}"')


def test_a_species_file_beside_the_case_still_works_and_is_kept_inline(folders):
    case_dir, _, _ = folders
    (case_dir / "chem").mkdir()
    (case_dir / "chem" / "my_species.yaml").write_text(yaml.safe_dump(SPECIES))
    path = _case_file(case_dir, "chem/my_species.yaml")
    case = load_case(path)
    assert case.chemistry.species == SPECIES  # the file's mapping, not its name
    # the case written back names no file: it loads from any folder, and as data
    again = parse_case(yaml.safe_load(case_to_yaml(case)))
    assert again == case
    # read_case_data: the same mapping for callers that validate later (sweeps)
    assert parse_case(read_case_data(path)) == case
    # a missing file beside the case: named as typed
    path = _case_file(case_dir, "nowhere.yaml")
    with pytest.raises(InputError, match=r'chemistry\.species: "nowhere.yaml" is not a file'):
        load_case(path)


def test_a_case_given_as_data_names_no_file(folders, monkeypatch):
    case_dir, outside, canary = folders
    (case_dir / "my_species.yaml").write_text(yaml.safe_dump(SPECIES))
    monkeypatch.chdir(case_dir)  # even a file in the working folder
    for typed in ("my_species.yaml", str(case_dir / "my_species.yaml"), str(outside / "keys.yaml")):
        data = {**BASE, "chemistry": {**BASE["chemistry"], "species": typed}}
        for kwargs in ({}, {"source": str(case_dir / "case.yaml")}, {"base_dir": None}):
            with pytest.raises(InputError, match="a case given as data names no file") as err:
                parse_case(data, **kwargs)
            assert canary not in str(err.value)
    # inline species are accepted as data
    data = {**BASE, "chemistry": {**BASE["chemistry"], "species": SPECIES}}
    assert parse_case(data).chemistry.species == SPECIES


def test_case_file_path_checks(tmp_path):
    (tmp_path / "a.yaml").write_text("bed: {}\n")
    assert case_file_path("f", "a.yaml", tmp_path, "x") == (tmp_path / "a.yaml").resolve()
    for typed in ("", "   ", ".", "a\0.yaml", "x" * 300, str(tmp_path / "a.yaml"), 12):
        with pytest.raises(InputError, match="is not accepted"):
            case_file_path("f", typed, tmp_path, "x")
    loop = tmp_path / "loop.yaml"
    loop.symlink_to(loop)
    with pytest.raises(InputError):
        case_file_path("f", "loop.yaml", tmp_path, "x")


def test_the_cli_refuses_in_one_line(folders, capsys):
    case_dir, outside, canary = folders
    path = _case_file(case_dir, str(outside / "secret.yaml"))
    code = main(["run", str(path), "--out", str(case_dir / "out"), "--no-plots"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1 and canary not in err
    assert "chemistry.species" in err


def test_load_species_from_a_file_that_is_not_one_is_not_shown(folders):
    _, outside, canary = folders
    with pytest.raises(InputError) as err:
        load_species(outside / "secret.yaml")
    assert canary not in str(err.value) and "not a species file" in str(err.value)
