"""Axial solids transport in rotating drums: bed-depth profiles, hold-up and residence time.

- :mod:`~rotarykiln.transport.kramers`: Kramers-Croockewit / Saeman bed-depth ODE.
- :mod:`~rotarykiln.transport.scott`: Scott's (1986) model with dams and internal weirs.
- :mod:`~rotarykiln.transport.correlations`: the classical empirical correlations.
- :mod:`~rotarykiln.transport.saeman`: Saeman's kinematics and McTait's dimensionless forms.
- :mod:`~rotarykiln.transport.scaleup`: dimensionless scale-up groups (Abouzeid's, Scott's Psi).
- :mod:`~rotarykiln.transport.charts`: design charts for a user kiln.
"""

from rotarykiln.transport.kramers import kramers_profile, kramers_uniform_depth
from rotarykiln.transport.result import BedProfile
from rotarykiln.transport.scott import scott_profile
from rotarykiln.transport.weirs import Weir, dam_radius_from_height

__all__ = [
    "BedProfile",
    "Weir",
    "dam_radius_from_height",
    "kramers_profile",
    "kramers_uniform_depth",
    "scott_profile",
]
