"""Annular dams and internal weirs (constrictions) of a rotating drum."""

from __future__ import annotations

from dataclasses import dataclass

from rotarykiln.errors import InputError, check_nonnegative, check_positive

__all__ = ["Weir", "dam_radius_from_height"]


def dam_radius_from_height(height, drum_radius, field: str = "dam") -> float:
    """Radius of the opening of an annular dam, :math:`R_c = R - h_{dam}`, m.

    Parameters
    ----------
    height : float, m
        Dam height above the drum wall, in [0, R).
    drum_radius : float, m
        Drum inner radius.
    field : str
        Name of the dam in error messages.

    Returns
    -------
    float, m

    Raises
    ------
    InputError
        When the dam reaches or passes the drum axis (``height >= drum_radius``): the opening
        would vanish and no solids could leave.

    Examples
    --------
    >>> round(dam_radius_from_height(0.0095, 0.0465), 6)
    0.037

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 3
    (dams and weirs).
    """
    check_positive("drum radius", drum_radius, "m")
    check_nonnegative(f"{field}.height", height, "m")
    if height >= drum_radius:
        raise InputError(
            f"{field}.height",
            f"{height:.6g} m",
            f"< the drum radius ({drum_radius:.6g} m): the dam would close the drum",
        )
    return float(drum_radius - height)


@dataclass(frozen=True)
class Weir:
    """An annular constriction inside the drum.

    Attributes
    ----------
    position : float, m
        Distance from the **discharge** end (Scott's x), in (0, L).
    radius : float, m
        Radius of the opening, in (0, R].

    Examples
    --------
    >>> Weir(position=0.1, radius=0.037)
    Weir(position=0.1, radius=0.037)

    References
    ----------
    Scott, W. J. (1986) The transport of solids in rotating drums, PhD thesis, Edinburgh, ch. 3
    (internal weirs).
    """

    position: float
    radius: float

    @classmethod
    def from_height(cls, position: float, height: float, drum_radius: float) -> Weir:
        """Weir given by its height above the wall (m) instead of its opening radius."""
        return cls(float(position), dam_radius_from_height(height, drum_radius, "weir"))

    def height(self, drum_radius: float) -> float:
        """Height above the wall, m."""
        return float(drum_radius - self.radius)
