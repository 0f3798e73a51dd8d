"""Small helpers shared by the closures."""

import numpy as np


def span(values):
    """``[min, max]`` of an array with more than two elements (for short warning messages)."""
    arr = np.asarray(values, dtype=float)
    if arr.size > 2:
        return np.array([np.nanmin(arr), np.nanmax(arr)])
    return arr
