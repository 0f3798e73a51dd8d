"""The hot, nearly stoichiometric limestone kiln of the dissociation and combustion tests."""

import yaml

from rotarykiln.case import parse_case
from rotarykiln.cases import builtin_case_path
from rotarykiln.kiln.from_case import kiln_from_case


def hot_kiln(products):
    """limestone_fired with 10 % excess air, the secondary air from a cooler at 1000 K, 8
    instead of 12 Nm3/h of gas for three times the limestone: (case dict, kiln)."""
    data = yaml.safe_load(builtin_case_path("limestone_fired").read_text())
    b = data["burner"]
    b["products"] = products
    data["operation"]["feed"] = "126 kg/h"
    b["fuel_flow"] = "8 Nm3/h"
    b["secondary_air"]["temperature"] = "1000 K"
    fuel = 8.0 * 0.95 * 2 + 8.0 * 0.03 * 3.5  # Nm3/h of O2 for the natural gas
    air = 1.10 * fuel / 0.21
    b["primary_air"]["flow"] = f"{0.25 * air:.6g} Nm3/h"
    b["secondary_air"]["flow"] = f"{0.75 * air:.6g} Nm3/h"
    kiln, _ = kiln_from_case(parse_case(data))
    return data, kiln
