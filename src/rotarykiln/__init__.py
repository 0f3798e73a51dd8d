"""rotarykiln: a simulator of rotary kilns and rotating drums.

Layers (see docs/architecture.md): ``units``/``errors`` at the bottom, ``geometry`` and
``regimes`` for the cross-section, physics packages above them, ``kiln`` and ``studies``
composing them, and ``case``/``cli``/``plot`` talking to people.
"""

from rotarykiln.errors import ConvergenceError, InputError, OutOfRangeWarning

__version__ = "0.1.0"

__all__ = ["ConvergenceError", "InputError", "OutOfRangeWarning", "__version__"]
