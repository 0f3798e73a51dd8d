"""rotarykiln: a simulator of rotary kilns and rotating drums.

Layers (see docs/dev/architecture.md): ``units``/``errors`` at the bottom, ``geometry`` and
``regimes`` for the cross-section, physics packages above them, ``kiln`` and ``studies``
composing them, and ``case``/``cli``/``plot`` talking to people.
"""

# ``import rotarykiln as rk`` then ``rk.load_case``, ``rk.run`` (rotarykiln.api).
# Nothing heavy is imported here (numpy comes with the first model or error used): the
# ``rotarykiln`` command sets its signal handlers a few milliseconds after Python starts.
__all__ = [
    "ConvergenceError",
    "InputError",
    "OutOfRangeWarning",
    "Result",
    "__version__",
    "load_case",
    "run",
]


def __getattr__(name: str):
    if name in ("ConvergenceError", "InputError", "OutOfRangeWarning"):
        from rotarykiln import errors

        return getattr(errors, name)
    if name in ("Result", "load_case", "run"):  # the notebook API (rotarykiln.api)
        from rotarykiln import api

        return getattr(api, name)
    if name == "__version__":
        from importlib.metadata import PackageNotFoundError, version

        try:  # the one source of the version is pyproject.toml, read from the installed metadata
            return version("rotarykiln")
        except PackageNotFoundError:  # pragma: no cover - a source tree not installed
            return "0+unknown"
    raise AttributeError(f"module 'rotarykiln' has no attribute {name!r}")
