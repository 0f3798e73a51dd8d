"""The data-file reader of studies.io (issue 21): a size limit before parsing, a row and a column
limit, UTF-8 text, and refusals in one line that never echo a value raw."""

from __future__ import annotations

import pytest

from rotarykiln.errors import InputError
from rotarykiln.studies.io import MAX_DATA_BYTES, MAX_DATA_ROWS, read_data_csv, shown


def _refused(path, match, **kwargs) -> str:
    with pytest.raises(InputError, match=match) as e:
        read_data_csv(path, "--data", **kwargs)
    assert "\n" not in str(e.value)
    return str(e.value)


def test_a_file_over_the_size_limit_is_refused_before_it_is_read(tmp_path):
    big = tmp_path / "big.csv"
    with big.open("wb") as fh:  # a sparse file: nothing is written, nothing must be read
        fh.truncate(MAX_DATA_BYTES + 1)
    msg = _refused(big, "too large for a data file")
    assert "--data" in msg and "20 MB" in msg


def test_rows_over_the_limit_are_refused(tmp_path):
    p = tmp_path / "rows.csv"
    p.write_text("a,b\n" + "1,2\n" * (MAX_DATA_ROWS + 1))
    _refused(p, "more than 100,000 rows")
    p.write_text("a,b\n" + "1,2\n" * MAX_DATA_ROWS)  # at the limit: read
    assert len(read_data_csv(p, "--data")) == MAX_DATA_ROWS


def test_text_that_is_not_utf8_or_not_a_table_is_refused_in_one_line(tmp_path):
    p = tmp_path / "d.csv"
    p.write_bytes("a,b\n1,\xe9\n".encode("latin-1"))
    _refused(p, r"not UTF-8 text \(byte 0xe9 at line 2\)")
    p.write_bytes(b"a,b\n1,\x002\n")
    _refused(p, "not a text file")
    p.write_text(",".join(f"c{i}" for i in range(500)) + "\n")
    _refused(p, "more than 100 columns")
    p.write_text("")
    _refused(p, "not a readable CSV table")
    p.write_text('a,b\n1,"2\n')  # an unterminated quote
    _refused(p, "not a readable CSV table")
    _refused(tmp_path / "missing.csv", "no such data file")
    _refused(tmp_path, "a folder, not a data file")


def test_a_byte_order_mark_is_accepted(tmp_path):
    p = tmp_path / "bom.csv"
    p.write_bytes("a,b\n1,2\n".encode("utf-8-sig"))
    assert list(read_data_csv(p, "--data").columns) == ["a", "b"]


def test_a_file_name_with_a_newline_is_escaped(tmp_path):
    msg = _refused(tmp_path / "a\nb.csv", "no such data file")
    assert "\\n" in msg


def test_shown_escapes_control_characters_and_shortens():
    assert shown("1.5 kg/h") == "1.5 kg/h"
    assert shown("1\n2") == repr("1\n2")
    assert shown("\x1b[31mred") == repr("\x1b[31mred")
    assert len(shown("x" * 10_000)) == 60
