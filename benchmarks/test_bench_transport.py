"""Speed of the transport models (pytest-benchmark; targets from issue 3, never asserted).

- one Kramers profile with 1,000 output points: median <= 1 ms
- one Scott profile (check-value case): median <= 20 ms
- 10^5 operating points of a correlation / the uniform Kramers depth: <= 50 ms
"""

import numpy as np

from rotarykiln.transport.correlations import sullivan_residence_time
from rotarykiln.transport.kramers import kramers_profile, kramers_uniform_depth
from rotarykiln.transport.saeman import mctait_residence_time
from rotarykiln.transport.scott import scott_profile

RPM = np.pi / 30
N = 100_000
_rng = np.random.default_rng(0)
Q = _rng.uniform(1e-6, 1e-5, N)
R = _rng.uniform(0.15, 0.25, N)
RPMS = _rng.uniform(1.0, 5.0, N) * RPM


def test_kramers_profile_1000_points(benchmark):
    p = benchmark(
        kramers_profile,
        62 / 3600,
        density=1500,
        length=2.0,
        radius=0.2,
        speed=3 * RPM,
        slope=np.radians(1),
        repose=np.radians(35),
        n_points=1000,
    )
    assert p.z.size == 1000


def test_kramers_profile_with_dam_1000_points(benchmark):
    benchmark(
        kramers_profile,
        62 / 3600,
        density=1500,
        length=2.0,
        radius=0.2,
        speed=3 * RPM,
        slope=np.radians(1),
        repose=np.radians(35),
        dam_height=0.05,
        n_points=1000,
    )


def test_scott_profile(benchmark):
    benchmark(
        scott_profile,
        0.00337,
        density=1780,
        length=0.216,
        radius=0.0465,
        speed=38.5 * RPM,
        slope=0.0,
        dynamic_angle=np.radians(28),
        static_angle=np.radians(24.5),
        discharge_radius=0.0262,
    )


def test_scott_profile_inclined(benchmark):
    benchmark(
        scott_profile,
        0.003,
        density=1780,
        length=3.0,
        radius=0.0465,
        speed=34.5 * RPM,
        slope=np.radians(2),
        dynamic_angle=np.radians(28),
        static_angle=np.radians(24.5),
        discharge_radius=0.037,
    )


def test_uniform_depth_1e5(benchmark):
    benchmark(kramers_uniform_depth, Q, R, RPMS, np.radians(3), np.radians(35))


def test_sullivan_1e5(benchmark):
    benchmark(sullivan_residence_time, 20.0, 2 * R, RPMS, np.radians(2), np.radians(35))


def test_mctait_1e5(benchmark):
    y = _rng.uniform(0.01, 1.0, N)
    benchmark(mctait_residence_time, 36.6, 3.66, RPMS, np.radians(3), np.radians(40), y)
