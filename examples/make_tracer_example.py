"""Write examples/tracer_synthetic.csv: a synthetic tracer curve for trying `rotarykiln rtd fit`.

The curve is the open-open axial dispersion E(t) (rotarykiln.rtd.dispersion) with tau = 40 min and
Pe = 60, sampled every 2 min from 10 to 90 min, scaled to a mass fraction peaking near 1 %, with
2 % multiplicative noise (seed 1). Fitting it should return tau ~ 40 min and Pe ~ 60.
"""

from pathlib import Path

import numpy as np
import pandas as pd

from rotarykiln.outputs import write_frame_atomic
from rotarykiln.rtd.dispersion import open_open_exit_age

t_min = np.arange(10.0, 90.1, 2.0)
e = open_open_exit_age(t_min * 60.0, 40 * 60.0, 60.0)
rng = np.random.default_rng(1)
c = 0.01 * e / e.max() * (1 + 0.02 * rng.standard_normal(t_min.size))
frame = pd.DataFrame({"time [min]": t_min, "mass fraction": np.round(np.clip(c, 0, None), 7)})
write_frame_atomic(Path(__file__).with_name("tracer_synthetic.csv"), frame)
