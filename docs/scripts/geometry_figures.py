"""Make the figures of docs/geometry.md: the regime map and a cross-section (run from the repo root)."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402

from rotarykiln.outputs import save_figure_atomic  # noqa: E402
from rotarykiln.plot import cross_section_figure, regime_map_figure  # noqa: E402
from rotarykiln.regimes import froude_number  # noqa: E402

out = Path("docs/figures")
fr = float(froude_number(5 * 2 * np.pi / 60, 3.0))
save_figure_atomic(out / "regime_map.png", regime_map_figure(0.3, fr), dpi=80)
save_figure_atomic(out / "cross_section.png", cross_section_figure(0.3, 3.0), dpi=80)
