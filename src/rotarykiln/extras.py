"""The optional parts of rotarykiln and the package each needs.

``pip install rotarykiln`` runs every model from a case file or the command line. Studies, a Dask
cluster and the interactive app need more: ``pip install "rotarykiln[studies]"`` (SALib's designs,
Parquet result stores), ``"rotarykiln[cluster]"`` (Dask distributed), ``"rotarykiln[app]"``
(Dash), or ``"rotarykiln[all]"``. :func:`require` imports such a package or says, in one line,
which extra to install.
"""

from __future__ import annotations

import importlib
from types import ModuleType

from rotarykiln.errors import InputError

__all__ = ["EXTRAS", "MissingExtraError", "require"]

EXTRAS: dict[str, str] = {
    "SALib": "studies",
    "pyarrow": "studies",
    "dask": "cluster",
    "distributed": "cluster",
    "dash": "app",
}
"""Top-level module -> the extra that installs it."""


class MissingExtraError(InputError):
    """An optional package is not installed; the message names the ``pip install`` to run."""


def require(module: str, purpose: str) -> ModuleType:
    """Import ``module`` (a dotted name) or raise :class:`MissingExtraError` naming the extra.

    Parameters
    ----------
    module : str
        The module to import, e.g. ``"SALib.sample.sobol"``.
    purpose : str
        What needs it, as the user would say it (``"rotarykiln sweep"``, ``"a Sobol study"``).

    Examples
    --------
    >>> require("json", "reading JSON").__name__
    'json'
    >>> require("no_such_module_xyz", "a test")
    Traceback (most recent call last):
    ...
    rotarykiln.extras.MissingExtraError: a test needs no_such_module_xyz, which is not installed: pip install no_such_module_xyz
    """
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        top = module.split(".")[0]
        missing = (getattr(exc, "name", None) or top).split(".")[0]
        extra = EXTRAS.get(top) or EXTRAS.get(missing)
        how = f'pip install "rotarykiln[{extra}]"' if extra else f"pip install {missing}"
        raise MissingExtraError(
            purpose, message=f"{purpose} needs {missing}, which is not installed: {how}"
        ) from None
