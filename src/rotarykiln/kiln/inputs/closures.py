"""The choice of every heat-transfer closure of the kiln model, by name (see docs/heat.md)."""

from __future__ import annotations

from dataclasses import dataclass

from rotarykiln.errors import InputError, check_range

__all__ = [
    "Closures",
    "SEED004_CLOSURES",
    "GAS_WALL",
    "GAS_BED",
    "COVERED_WALL",
    "GAS_EMISSIVITY",
    "BED_CONDUCTIVITY",
    "RADIATION_MODELS",
]

GAS_WALL = ("tscheng1979", "gorog1982")
GAS_BED = ("tscheng1979", "gorog1982")
COVERED_WALL = ("li2005", "tscheng1979", "wachters_kramers1964")
GAS_EMISSIVITY = ("johansson2011", "smith1982")
BED_CONDUCTIVITY = ("given", "maxwell", "zehner_schlunder")
RADIATION_MODELS = ("grey", "banded")


@dataclass(frozen=True)
class Closures:
    """Choice of every closure by name (see docs/heat.md).

    ``gas_wall`` in {tscheng1979, gorog1982}; ``gas_bed`` in {tscheng1979, gorog1982};
    ``covered_wall`` in {li2005, tscheng1979, wachters_kramers1964}; ``radiation`` on/off;
    ``gas_emissivity`` in {johansson2011, smith1982} or a constant in [0, 1);
    ``bed_conductivity`` in {given, maxwell, zehner_schlunder} (``given`` uses the measured
    bulk value of the solid, falling back to zehner_schlunder); ``convection_factor`` (-, > 0,
    default 1: the correlations as published) multiplies the gas-wall and gas-bed convection
    coefficients, a handle for calibration to plant data, not a default to change;
    ``near_bed_mixing`` (W/(m2 K), None: off): a layered freeboard, the bed exchanging (by
    convection and gas radiation) with a near-bed gas layer fed from the core gas through this
    mixing coefficient in series (the layer's temperature lies between bed and core);
    ``bed_radiation``: the bed conductivity gains the radiation between particles,
    :func:`rotarykiln.heat.bed_conductivity.radiative_bed_conductivity` (Damkohler /
    Zehner-Bauer-Schlunder, growing as d_p T^3); ``exposed_bed_penetration``: the heat
    reaching the exposed bed surface penetrates the bed through a penetration-theory
    resistance (Wachters & Kramers over the bed's circulation time) in series;
    ``radiation_model`` in {grey, banded}: the freeboard exchange with one grey gas
    (absorptivity equal to the emissivity at the gas temperature) or with every grey gas of the
    WSGG ``gas_emissivity`` model in the network, the surfaces' radiation weighted at their own
    temperature (:func:`rotarykiln.heat.radiation.freeboard_radiation_bands`; a constant or a
    line emissivity stays grey).
    """

    gas_wall: str = "tscheng1979"
    gas_bed: str = "tscheng1979"
    covered_wall: str = "li2005"
    radiation: bool = True
    gas_emissivity: str | float = "johansson2011"
    bed_conductivity: str = "given"
    convection_factor: float = 1.0
    radiation_model: str = "grey"
    near_bed_mixing: float | None = None
    bed_radiation: bool = False
    exposed_bed_penetration: bool = False

    def __post_init__(self):
        for name, value, allowed in (
            ("closures.gas_wall", self.gas_wall, GAS_WALL),
            ("closures.gas_bed", self.gas_bed, GAS_BED),
            ("closures.covered_wall", self.covered_wall, COVERED_WALL),
            ("closures.bed_conductivity", self.bed_conductivity, BED_CONDUCTIVITY),
            ("closures.radiation_model", self.radiation_model, RADIATION_MODELS),
        ):
            if value not in allowed:
                raise InputError(name, value, "one of " + ", ".join(allowed))
        if isinstance(self.gas_emissivity, str):
            if self.gas_emissivity not in GAS_EMISSIVITY:
                raise InputError(
                    "closures.gas_emissivity",
                    self.gas_emissivity,
                    "one of " + ", ".join(GAS_EMISSIVITY) + " or a number in [0, 1)",
                )
        else:
            check_range("closures.gas_emissivity", self.gas_emissivity, 0.0, 1.0, closed_low=True)
        check_range("closures.convection_factor", self.convection_factor, 0.0, 100.0)
        if self.near_bed_mixing is not None:
            check_range(
                "closures.near_bed_mixing", self.near_bed_mixing, 0.0, 1e4, closed_high=True
            )


#: Closures of seed 004 (Gorog et al. 1982 gas-bed and gas-wall, Tscheng & Watkinson 1979
#: covered wall), with the 0.62 exponent of the gas-bed law (notes 004, section 8.4).
SEED004_CLOSURES = Closures(
    gas_wall="gorog1982",
    gas_bed="gorog1982",
    covered_wall="tscheng1979",
    radiation=True,
    gas_emissivity="johansson2011",
    bed_conductivity="given",
)
