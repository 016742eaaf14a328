"""Fuzzing pma_core's public functions: any input gives a result or a ValueError, never
another exception (TypeError, ZeroDivisionError, IndexError, ...)."""

from __future__ import annotations

import contextlib
import inspect
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pma_core import braid, force, friction, gap, geometry, hysteresis, strength

MODULES = (braid, force, friction, gap, geometry, hysteresis, strength)
SKIP = {"hysteresis_curves"}  # fuzzed separately: it takes a whole design and a point count


def _public_functions() -> list[Callable[..., Any]]:
    found: list[Callable[..., Any]] = []
    for module in MODULES:
        for name, obj in vars(module).items():
            if (
                inspect.isfunction(obj)
                and obj.__module__ == module.__name__
                and not name.startswith("_")
                and not name.endswith("_kernel")
                and name not in SKIP
            ):
                found.append(obj)
    return found


numbers = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.floats(-1e3, 1e3),
    st.sampled_from([0.0, 1e-300, 1e300, -1.0, 0.5, np.pi / 4, 240.0]),
)
arguments = st.one_of(numbers, st.lists(numbers, min_size=0, max_size=4).map(np.array))


@pytest.mark.parametrize("function", _public_functions(), ids=lambda f: f.__name__)
@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_only_value_errors_escape(function: Callable[..., Any], data: st.DataObject) -> None:
    required = [
        p
        for p in inspect.signature(function).parameters.values()
        if p.default is inspect.Parameter.empty
    ]
    args = [data.draw(arguments, label=p.name) for p in required]
    with np.errstate(all="ignore"), contextlib.suppress(ValueError):
        function(*args)


@settings(max_examples=200, deadline=None)
@given(
    design=st.tuples(*(numbers for _ in range(8))),
    s_scale=st.one_of(st.none(), numbers),
    points=st.integers(-5, 50),
)
def test_hysteresis_curves_only_raises_value_error(
    design: tuple[float, float, float, float, float, float, float, float],
    s_scale: float | None,
    points: int,
) -> None:
    with np.errstate(all="ignore"), contextlib.suppress(ValueError):
        b, n, d_s, count, p, f_s, e, nu = design
        hysteresis.hysteresis_curves(b, n, d_s, count, p, f_s, e, nu, s_scale, points)


@settings(max_examples=300, deadline=None)
@given(
    st.floats(1e-6, 1e-2),
    st.integers(2, 100_000),
    st.floats(1e-4, 1.0),
    st.floats(1.0, 1e8),
)
def test_valid_designs_give_finite_numbers(d_s: float, n: int, d_o: float, p: float) -> None:
    if d_s * n >= np.pi * d_o:
        with pytest.raises(ValueError, match="cannot fit"):
            braid.min_braid_angle(d_s, n, d_o)
        return
    theta = braid.min_braid_angle(d_s, n, d_o)
    values = [
        theta,
        braid.max_contraction(d_s, n, d_o),
        gap.max_gap_area(d_o, d_s, n, 1),
        strength.failure_strand_count(p, d_o, d_s, 75e6),
        friction.s_scale(p, d_s, 3e9, 0.4),
        force.static_force(p, d_o, theta),
    ]
    assert np.all(np.isfinite(values))
