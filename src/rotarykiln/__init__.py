"""rotarykiln: a simulator of rotary kilns and rotating drums.

Layers (see docs/architecture.md): ``units``/``errors`` at the bottom, ``geometry`` and
``regimes`` for the cross-section, physics packages above them, ``kiln`` and ``studies``
composing them, and ``case``/``cli``/``plot`` talking to people.
"""

from importlib.metadata import PackageNotFoundError, version

from rotarykiln.errors import ConvergenceError, InputError, OutOfRangeWarning

try:  # the one source of the version is pyproject.toml, read from the installed metadata
    __version__ = version("rotarykiln")
except PackageNotFoundError:  # pragma: no cover - running from a source tree not installed
    __version__ = "0+unknown"

__all__ = ["ConvergenceError", "InputError", "OutOfRangeWarning", "__version__"]
