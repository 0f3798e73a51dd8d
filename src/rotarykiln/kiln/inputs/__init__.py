"""The kiln model's inputs: :class:`Kiln` and its branches, and the choice of closures."""

from rotarykiln.kiln.inputs.closures import SEED004_CLOSURES, Closures
from rotarykiln.kiln.inputs.kiln import Bed, Chemistry, Drum, Feed, Firing, GasInlet, Kiln, Wall

__all__ = [
    "Bed",
    "Chemistry",
    "Closures",
    "Drum",
    "Feed",
    "Firing",
    "GasInlet",
    "Kiln",
    "SEED004_CLOSURES",
    "Wall",
]
