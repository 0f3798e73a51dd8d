"""One YAML reader, with one set of limits, for every YAML file the program reads from a user.

Case files, transient events files, species and reaction files all go through
:func:`read_yaml_file` (or :func:`load_yaml_text` for text already in memory, e.g. an app upload).
Each refuses, with one :class:`~rotarykiln.errors.InputError` line naming the file, before any
memory or time is spent on it:

- a file larger than :data:`MAX_YAML_BYTES` (refused by its size, before it is read or parsed);
- text that is not UTF-8;
- malformed YAML;
- nesting deeper than :data:`MAX_YAML_DEPTH`, more than :data:`MAX_YAML_ALIASES` aliases or
  :data:`MAX_YAML_VALUES` values once aliases are expanded ("billion laughs"), an alias that
  refers to itself, a number longer than :data:`MAX_NUMBER_CHARS` characters;
- a key given twice in one mapping (YAML would silently keep the last one).

No message repeats more of the file than a key or an anchor name, shortened; with
``content=False`` (files a case names) not even that: the message says what is wrong and where.
"""

from __future__ import annotations

import reprlib
from pathlib import Path
from typing import Any

import yaml

from rotarykiln.errors import InputError

__all__ = [
    "MAX_NUMBER_CHARS",
    "MAX_YAML_ALIASES",
    "MAX_YAML_BYTES",
    "MAX_YAML_DEPTH",
    "MAX_YAML_VALUES",
    "LimitedLoader",
    "YamlLimitError",
    "check_structure",
    "load_yaml_text",
    "read_file_within",
    "read_yaml_file",
    "short_repr",
    "show_value",
]

MAX_YAML_BYTES = 1_000_000
"""Largest YAML file read, bytes (a case or an events file is a few kB; the largest shipped YAML
file, a reaction file, 5 kB)."""
MAX_YAML_DEPTH = 20
"""Deepest nesting of mappings and lists (the built-in cases nest 6 levels)."""
MAX_YAML_ALIASES = 100
"""Most YAML aliases (``*name``) in a file."""
MAX_YAML_VALUES = 100_000
"""Most values (keys, scalars, lists and mappings, aliases expanded) in a file (built-in cases:
< 200)."""
MAX_NUMBER_CHARS = 100
"""Longest number written in a YAML file, characters."""

_REPR = reprlib.Repr()
_REPR.maxlevel, _REPR.maxdict, _REPR.maxlist, _REPR.maxtuple = 3, 4, 6, 6
_REPR.maxstring = _REPR.maxother = _REPR.maxlong = 50


def short_repr(value: Any, limit: int = 80) -> str:
    """``repr(value)`` in at most about ``limit`` characters, however large the value.

    Examples
    --------
    >>> short_repr(list(range(1000)))
    '[0, 1, 2, 3, 4, 5, ...]'
    """
    try:
        text = _REPR.repr(value)
    except (ValueError, RecursionError):  # an int over Python's digit limit
        return f"a {type(value).__name__} too long to show"
    return text if len(text) <= limit else text[: limit - 3] + "..."


def show_value(value: Any) -> str:
    """A value as a message shows it, on one line: text in double quotes (at most 50
    characters), the rest as :func:`short_repr` writes it.

    Examples
    --------
    >>> show_value("1e6 rpm"), show_value(3600)
    ('"1e6 rpm"', '3600')
    """
    if isinstance(value, str):
        text = value if len(value) <= 50 else value[:47] + "..."
        return '"' + "".join(c if c.isprintable() else repr(c)[1:-1] for c in text) + '"'
    return short_repr(value)


class YamlLimitError(yaml.YAMLError):
    """A YAML file over one of the limits above, or with a duplicate key (raised while reading).

    ``reason`` says what is wrong without any text of the file; ``detail`` may name a key or an
    anchor of the file (shortened).
    """

    def __init__(self, reason: str, mark=None, detail: str = ""):
        self.reason = reason
        self.line = mark.line + 1 if mark is not None else None
        where = f" (line {self.line})" if self.line is not None else ""
        self.detail = (detail or reason) + where
        self.quiet = reason + where
        super().__init__(self.detail)


class LimitedLoader(yaml.SafeLoader):
    """A YAML safe loader that refuses nesting deeper than :data:`MAX_YAML_DEPTH`, more than
    :data:`MAX_YAML_ALIASES` aliases or :data:`MAX_YAML_VALUES` values once aliases are
    expanded ("billion laughs"), recursive aliases, numbers longer than
    :data:`MAX_NUMBER_CHARS` characters (before they reach a recursion limit, memory or
    ``int()``), and a key given twice in a mapping.
    """

    def __init__(self, stream):
        super().__init__(stream)
        self._depth = 0
        self._aliases = 0
        self._values = 0
        self._sizes: dict[int, int] = {}  # id(node) -> values in it, aliases expanded

    def compose_node(self, parent, index):
        if self.check_event(yaml.AliasEvent):
            event = self.peek_event()
            node = self.anchors.get(event.anchor)
            if node is not None:
                size = self._sizes.get(id(node))
                if size is None:
                    raise YamlLimitError(
                        "an alias refers to itself",
                        event.start_mark,
                        f"alias *{str(event.anchor)[:40]} refers to itself",
                    )
                self._aliases += 1
                self._values += size
                if self._aliases > MAX_YAML_ALIASES:
                    raise YamlLimitError(
                        f"more than {MAX_YAML_ALIASES} YAML aliases", event.start_mark
                    )
                self._check_values(event.start_mark)
            return super().compose_node(parent, index)
        self._depth += 1
        if self._depth > MAX_YAML_DEPTH:
            raise YamlLimitError(
                f"nested deeper than {MAX_YAML_DEPTH} levels", self.peek_event().start_mark
            )
        start = self._values
        node = super().compose_node(parent, index)
        self._depth -= 1
        self._values += 1
        self._check_values(node.start_mark)
        self._sizes[id(node)] = self._values - start
        return node

    def _check_values(self, mark) -> None:
        if self._values > MAX_YAML_VALUES:
            raise YamlLimitError(
                f"more than {MAX_YAML_VALUES} values once YAML aliases are expanded", mark
            )

    def _short_number(self, node) -> None:
        if len(node.value) > MAX_NUMBER_CHARS:
            raise YamlLimitError(
                f"a number of {len(node.value)} characters (at most {MAX_NUMBER_CHARS})",
                node.start_mark,
            )

    def construct_yaml_int(self, node):
        self._short_number(node)
        return super().construct_yaml_int(node)

    def construct_yaml_float(self, node):
        self._short_number(node)
        return super().construct_yaml_float(node)

    def construct_mapping(self, node, deep=False):
        # a key twice in one mapping (``events:`` twice): YAML keeps the last one silently.
        # Keys merged in with ``<<: *base`` may be overridden, as YAML intends.
        if isinstance(node, yaml.MappingNode):
            seen = set()
            for key_node, _ in node.value:
                if key_node.tag == "tag:yaml.org,2002:merge":
                    continue
                key = self.construct_object(key_node, deep=True)
                try:
                    duplicate = key in seen
                    seen.add(key)
                except TypeError:  # an unhashable key: the safe loader refuses it below
                    continue
                if duplicate:
                    raise YamlLimitError(
                        "a key given twice",
                        key_node.start_mark,
                        f"key {show_value(key)} given twice",
                    )
        return super().construct_mapping(node, deep=deep)


LimitedLoader.add_constructor("tag:yaml.org,2002:int", LimitedLoader.construct_yaml_int)
LimitedLoader.add_constructor("tag:yaml.org,2002:float", LimitedLoader.construct_yaml_float)


def _one_line(text: str, limit: int = 120) -> str:
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 3] + "..."


def load_yaml_text(
    text: str | bytes, label: str, *, what: str = "YAML file", content: bool = True
) -> Any:
    """Parse YAML text (or UTF-8 bytes) into Python objects within the limits above.

    Parameters
    ----------
    text : str or bytes
        The YAML; bytes must be UTF-8 and at most :data:`MAX_YAML_BYTES` long.
    label : str
        How messages name the text (a file name, ``"upload.yaml"``).
    what : str
        What the text is, in messages (``"case file"``, ``"events file"``).
    content : bool
        False: messages name no key, anchor or parser text of the file (a file a case names).

    Returns
    -------
    object
        The parsed YAML (not validated): a mapping, a list, a scalar or None.

    Raises
    ------
    InputError
        One line naming ``label``: too large, not UTF-8, malformed YAML, over a limit of
        :class:`LimitedLoader`, a duplicate key.

    Examples
    --------
    >>> load_yaml_text("events: []\\nevents: []\\n", "ev.yaml", what="events file")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: ev.yaml: key "events" given twice (line 2)
    """
    size = len(text)
    if size > MAX_YAML_BYTES:
        raise InputError(
            label,
            message=f"{label}: {size / 1e6:.3g} MB is too large for a {what} (at most "
            f"{MAX_YAML_BYTES / 1e6:g} MB; {_hint(what)})",
        )
    if isinstance(text, bytes | bytearray):
        try:
            text = bytes(text).decode("utf-8")
        except UnicodeDecodeError as exc:
            line = text[: exc.start].count(b"\n") + 1
            raise InputError(
                label,
                message=f"{label}: not UTF-8 text (byte 0x{text[exc.start]:02x} at line {line}); "
                f"save the {what} as UTF-8",
            ) from None
    try:
        return yaml.load(text, Loader=LimitedLoader)  # noqa: S506 (a SafeLoader)
    except YamlLimitError as exc:
        raise InputError(
            label, message=f"{label}: {exc.detail if content else exc.quiet}"
        ) from None
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        if not content:
            raise InputError(label, message=f"{label}: malformed YAML{where}") from None
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        raise InputError(
            label, message=f"{label}: malformed YAML{where}: {_one_line(problem)}"
        ) from None
    except RecursionError:  # a guard; the depth limit refuses such files first
        raise InputError(
            label, message=f"{label}: nested too deeply (at most {MAX_YAML_DEPTH} levels)"
        ) from None


def _hint(what: str) -> str:
    return "a case is a few kB" if what == "case file" else f"a {what} is a few kB"


def read_yaml_file(
    path: str | Path,
    *,
    what: str = "YAML file",
    label: str | None = None,
    content: bool = True,
) -> Any:
    """Read a YAML file into Python objects within the limits above (not validated).

    The size is checked before anything is read (at most :data:`MAX_YAML_BYTES` + 1 bytes are
    ever read: a growing file or ``/dev/zero`` is refused as well).

    Parameters
    ----------
    path : str or Path
        The file.
    what : str
        What the file is, in messages (``"case file"``, ``"events file"``, ``"species file"``).
    label : str, optional
        How messages name the file (default: ``path`` as given).
    content : bool
        False: messages name no key, anchor or parser text of the file.

    Raises
    ------
    InputError
        One line naming the file: missing, unreadable, too large, not UTF-8, malformed YAML,
        over a limit of :class:`LimitedLoader`, a duplicate key.

    Examples
    --------
    >>> read_yaml_file("no/such/file.yaml", what="species file")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: no/such/file.yaml: no such species file
    """
    label = str(path) if label is None else label
    raw = read_file_within(path, MAX_YAML_BYTES, label=label, what=what, note=f"; {_hint(what)}")
    return load_yaml_text(raw, label, what=what, content=content)


def read_file_within(
    path, max_bytes: int, *, label: str, what: str, field: str | None = None, note: str = ""
) -> bytes:
    """The bytes of the file ``path``, refused in one line when it is missing, a folder,
    unreadable, not a file name, or larger than ``max_bytes``: the size is checked before
    reading, and at most ``max_bytes`` + 1 bytes are read (a growing file or a device such as
    ``/dev/zero`` cannot exhaust memory). The one reader of every input file's bytes.

    Parameters
    ----------
    path : str or Path
        The file.
    max_bytes : int
        The size limit, bytes.
    label : str
        How messages name the file (``"--data: run.csv"``).
    what : str
        What the file is (``"species file"``, ``"tracer file"``).
    field : str, optional
        The field of the :class:`InputError` (default: ``label``).
    note : str
        Appended to the limit in the "too large" message.

    Examples
    --------
    >>> read_file_within("no/such.csv", 100, label="--data: no/such.csv", what="data file")
    Traceback (most recent call last):
    ...
    rotarykiln.errors.InputError: --data: no/such.csv: no such data file
    """
    field = label if field is None else field
    path = Path(path)
    try:
        size = path.stat().st_size
        raw = b""
        if size <= max_bytes:
            with path.open("rb") as fh:
                raw = fh.read(max_bytes + 1)
    except FileNotFoundError:
        raise InputError(field, message=f"{label}: no such {what}") from None
    except IsADirectoryError:
        raise InputError(field, message=f"{label}: a folder, not a {what}") from None
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        raise InputError(field, message=f"{label}: cannot read ({reason})") from None
    except ValueError:  # a NUL character in the path
        raise InputError(field, message=f"{label}: not a file name") from None
    if size > max_bytes or len(raw) > max_bytes:
        shown = f"{size / 1e6:.3g} MB" if size > max_bytes else "more than that"
        raise InputError(
            field,
            message=f"{label}: {shown} is too large for a {what} "
            f"(at most {max_bytes / 1e6:g} MB{note})",
        )
    return raw


def check_structure(data: Any, source: str) -> None:
    """Refuse data (from YAML or Python) nested deeper than :data:`MAX_YAML_DEPTH` (cycles
    included), with more than :data:`MAX_YAML_VALUES` values, or integers of more than
    :data:`MAX_NUMBER_CHARS` digits: without recursion, in at most that many steps.

    Raises
    ------
    InputError
        One line naming the place (a dotted path of keys and indices).
    """
    stack = [(data, 1, "")]
    count = 0
    while stack:
        node, depth, path = stack.pop()
        count += 1
        if count > MAX_YAML_VALUES:
            raise InputError(source, message=f"{source}: more than {MAX_YAML_VALUES} values")
        if isinstance(node, dict | list | tuple):
            if depth > MAX_YAML_DEPTH:
                raise InputError(
                    path,
                    message=f"{_place(path, source)}: nested deeper than {MAX_YAML_DEPTH} levels",
                )
            items = node.items() if isinstance(node, dict) else enumerate(node)
            for key, value in items:
                name = key if isinstance(key, int | str) else short_repr(key, 40)
                name = str(name)[:40]
                stack.append((value, depth + 1, f"{path}.{name}" if path else name))
        elif isinstance(node, int) and node.bit_length() > 3.33 * MAX_NUMBER_CHARS:
            raise InputError(
                path,
                message=f"{_place(path, source)}: an integer of more than {MAX_NUMBER_CHARS} digits",
            )


def _place(path: str, source: str) -> str:
    return path or source
