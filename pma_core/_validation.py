"""Argument checks shared by the model functions.

Every check is one vectorized comparison over the whole array; the message names the
parameter, the first offending value and the reason.
"""

from __future__ import annotations

import math
from typing import Any, TypeAlias

import numpy as np
import numpy.typing as npt

FloatArray: TypeAlias = npt.NDArray[np.float64]
#: What the model functions return: a numpy scalar for scalar input, else an array.
Floats: TypeAlias = Any


def as_floats(name: str, value: npt.ArrayLike) -> FloatArray:
    """Return ``value`` as a float array, refusing NaN and infinities."""
    if type(value) is float or type(value) is int:
        # Fast path for plain Python numbers (the API's case): no numpy reductions.
        if not math.isfinite(value):
            raise ValueError(f"{name} must be a finite number, got {value:g}")
        return np.asarray(value, dtype=np.float64)
    array = np.asarray(value, dtype=np.float64)
    finite = np.isfinite(array)
    if not all_true(finite):
        raise ValueError(f"{name} must be a finite number, got {_first(array, ~finite)}")
    return array


def positive(name: str, value: npt.ArrayLike) -> FloatArray:
    """Return ``value`` as floats after checking every element is > 0."""
    array = as_floats(name, value)
    bad = array <= 0
    if any_true(bad):
        raise ValueError(f"{name} must be greater than 0, got {_first(array, bad)}")
    return array


def at_least(name: str, value: npt.ArrayLike, minimum: float, reason: str) -> FloatArray:
    """Return ``value`` as floats after checking every element is >= ``minimum``."""
    array = as_floats(name, value)
    bad = array < minimum
    if any_true(bad):
        raise ValueError(
            f"{name} must be at least {minimum:g} ({reason}), got {_first(array, bad)}"
        )
    return array


def within(name: str, value: npt.ArrayLike, low: float, high: float, reason: str) -> FloatArray:
    """Return ``value`` as floats after checking ``low <= value < high``."""
    array = as_floats(name, value)
    bad = (array < low) | (array >= high)
    if any_true(bad):
        raise ValueError(
            f"{name} must lie in [{low:g}, {high:g}) ({reason}), got {_first(array, bad)}"
        )
    return array


def scalar_or_array(array: FloatArray) -> Floats:
    """Unwrap a 0-d result to a numpy scalar so scalar input gives scalar output."""
    return array[()]


def any_true(mask: npt.NDArray[np.bool_]) -> bool:
    # A 0-d mask is a numpy bool: truth-test it without a reduction.
    return bool(mask) if mask.ndim == 0 else bool(mask.any())


def all_true(mask: npt.NDArray[np.bool_]) -> bool:
    return bool(mask) if mask.ndim == 0 else bool(mask.all())


def _first(array: FloatArray, mask: npt.NDArray[np.bool_]) -> str:
    return f"{array[mask].flat[0]:g}"
