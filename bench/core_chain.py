"""The whole hysteresis chain on 10^6 points against numpy's floor and a plain Python loop.

``.venv/bin/python -m bench.core_chain [--points N] [--loop-points M] [--repeat R]``

1. ``hysteresis_curves`` (eqs 10, 19, 29-31 on the paper's test muscle) against the floor:
   numpy computing only the static force (eq 10) over an array of the same size,
   ``np.pi*D_o**2*P/4*(3*np.cos(theta)**2-1)``. Target: within 3x of the floor.
2. The same chain as a plain Python loop with the math module. Target: numpy >= 50x faster.
   The loop is timed on the first ``--loop-points`` points of the same stroke and scaled
   linearly to ``--points`` (a Python loop is linear in its length); its results are checked
   against numpy's on those points.

Timings are the best of ``--repeat`` runs (timeit). Minor page faults per call are printed
because they, not arithmetic, set most of the chain's time in a default process.

The numpy figures are measured twice: in this (default) process, and in a child process
that first calls ``app.server.tune_allocator()``, the glibc setting ``pma-calculator serve``
applies to the service. The targets are judged on the service's configuration (the
child); the default process is printed for comparison. The Python loop is timed here.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import resource
import subprocess
import sys
import timeit
from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from bench._common import PAPER_MUSCLE_ARGS, Table, best_of, header
from pma_core.geometry import theoretical_diameter
from pma_core.hysteresis import HysteresisCurves, hysteresis_curves

FloatArray = npt.NDArray[np.float64]
FLOOR_TARGET = 3.0
LOOP_TARGET = 50.0


def chain(points: int) -> HysteresisCurves:
    """The measured subject: the full chain for the paper's test muscle."""
    return hysteresis_curves(*PAPER_MUSCLE_ARGS, points=points)


def floor(theta: FloatArray, d_o: float, pressure: float) -> FloatArray:
    """Eq 10 alone over the braid angles: the least numpy work on an array this size."""
    result: FloatArray = np.pi * d_o**2 * pressure / 4 * (3 * np.cos(theta) ** 2 - 1)
    return result


def python_chain(curves: HysteresisCurves, points: int, count: int) -> list[list[float]]:
    """The same per-point chain as ``hysteresis_curves``, in plain Python (math module).

    The per-design scalars (D_o, theta_min, S_scale, ...) are the ones numpy computed once;
    the loop does the per-point work for the first ``count`` of ``points`` points.
    """
    b, n, _d_s, _n_s, pressure, f_s, _e, _nu = PAPER_MUSCLE_ARGS
    d_o = float(theoretical_diameter(b, n))
    theta_min = curves.min_braid_angle_rad
    cos_min = math.cos(theta_min)
    eps_max = 1.0 - math.cos(curves.max_braid_angle_rad) / cos_min
    step = eps_max / (points - 1)
    force_scale = math.pi * d_o * d_o * pressure / 4.0
    friction_scale = (
        (b * math.sin(theta_min) * cos_min) ** 2 / n * (f_s * pressure / curves.s_scale)
    )
    sqrt, acos = math.sqrt, math.acos
    angle, length, contraction, static, friction, contracting, extending = (
        [0.0] * count for _ in range(7)
    )
    for i in range(count):
        eps = i * step
        c = (1.0 - eps) * cos_min
        f_static = force_scale * (3.0 * c * c - 1.0)
        f_friction = friction_scale / (sqrt(1.0 - c * c) * c)
        down = f_static - f_friction
        contraction[i] = eps
        angle[i] = acos(c)
        length[i] = b * c
        static[i] = f_static
        friction[i] = f_friction
        contracting[i] = down if down > 0.0 else 0.0
        extending[i] = f_static + f_friction
    return [angle, length, contraction, static, friction, contracting, extending]


def _check_loop(loop: list[list[float]], curves: HysteresisCurves, count: int) -> float:
    arrays = (
        curves.braid_angle_rad,
        curves.length_m,
        curves.contraction,
        curves.force_static_n,
        curves.friction_force_n,
        curves.force_contracting_n,
        curves.force_extending_n,
    )
    worst = 0.0
    for values, array in zip(loop, arrays, strict=True):
        expected = array[:count]
        got = np.asarray(values)
        scale = np.maximum(np.abs(expected), 1e-300)
        worst = max(worst, float(np.max(np.abs(got - expected) / scale, initial=0.0)))
    if worst > 1e-9:
        raise AssertionError(f"Python loop differs from numpy by {worst:.2e} (relative)")
    return worst


def _faults_per_call(fn: Callable[[], object], calls: int) -> float:
    fn()
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    for _ in range(calls):
        fn()
    return (resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before) / calls


def _numpy_times(points: int, repeat: int) -> tuple[float, float, float]:
    """Chain and floor seconds per call, and the chain's minor page faults per call."""
    b, n, _d_s, _n_s, pressure, *_ = PAPER_MUSCLE_ARGS
    d_o = float(theoretical_diameter(b, n))
    theta = chain(points).braid_angle_rad.copy()
    t_chain = best_of(lambda: chain(points), number=3, repeat=repeat)
    t_floor = best_of(lambda: floor(theta, d_o, pressure), number=3, repeat=repeat)
    return t_chain, t_floor, _faults_per_call(lambda: chain(points), 5)


def _service_times(points: int, repeat: int) -> tuple[float, float, float]:
    """:func:`_numpy_times` in a child process tuned like the service (tune_allocator)."""
    command = [sys.executable, "-m", "bench.core_chain", "--points", str(points)]
    command += ["--repeat", str(repeat), "--numpy-only", "--tune-allocator"]
    env = {k: v for k, v in os.environ.items() if not k.startswith("MALLOC_")}
    done = subprocess.run(command, env=env, capture_output=True, text=True, check=True, timeout=600)
    t_chain, t_floor, faults = json.loads(done.stdout)
    return float(t_chain), float(t_floor), float(faults)


def main(argv: list[str] | None = None) -> int:
    """Measure and print the figures."""
    parser = argparse.ArgumentParser(prog="python -m bench.core_chain", description=__doc__)
    parser.add_argument("--points", type=int, default=10**6)
    parser.add_argument("--loop-points", type=int, default=10**5)
    parser.add_argument("--repeat", type=int, default=15)
    parser.add_argument("--numpy-only", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--tune-allocator", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    points, count, repeat = args.points, min(args.loop_points, args.points), args.repeat
    if args.numpy_only:
        if args.tune_allocator:
            from app.server import tune_allocator

            tune_allocator()
        print(json.dumps(_numpy_times(points, repeat)))
        return 0
    tuned_env = sorted(k for k in os.environ if k.startswith("MALLOC_"))

    header(
        f"core chain: hysteresis_curves, {points:,} points, paper test muscle",
        f"best of {repeat} timeit repeats for numpy; Python loop timed on the first "
        f"{count:,} points (best of {max(5, repeat // 2)}) and scaled x{points / count:g}",
        "numpy timed twice: default process (this one"
        + (f", but {', '.join(tuned_env)} set" if tuned_env else "")
        + ") and a child with app.server.tune_allocator() (the service's setting, judged)",
    )
    b, n, _d_s, _n_s, pressure, *_ = PAPER_MUSCLE_ARGS
    d_o = float(theoretical_diameter(b, n))
    curves = chain(points)
    theta = curves.braid_angle_rad.copy()

    t_chain, t_floor, faults_chain = _numpy_times(points, repeat)
    s_chain, s_floor, s_faults = _service_times(points, repeat)
    loop_runs = timeit.repeat(
        lambda: python_chain(curves, points, count), number=1, repeat=max(5, repeat // 2)
    )
    t_loop_subset = min(loop_runs)
    t_loop = t_loop_subset * points / count
    worst = _check_loop(python_chain(curves, points, count), curves, count)
    faults_floor = _faults_per_call(lambda: floor(theta, d_o, pressure), 5)

    vs_floor, vs_loop = s_chain / s_floor, t_loop / s_chain
    table = Table()
    table.add(
        "chain (numpy) per call",
        f"service {s_chain * 1e3:.2f} ms; default process {t_chain * 1e3:.2f} ms",
    )
    table.add(
        "floor: eq 10 alone per call",
        f"service {s_floor * 1e3:.2f} ms; default process {t_floor * 1e3:.2f} ms",
    )
    table.add(
        "minor page faults per call",
        f"chain: service {s_faults:.0f}, default {faults_chain:.0f}; floor (default)"
        f" {faults_floor:.0f}",
    )
    table.add(
        f"Python loop, {count:,} points",
        f"{t_loop_subset * 1e3:.1f} ms (max rel. diff to numpy {worst:.1e})",
    )
    table.add(f"Python loop scaled to {points:,}", f"{t_loop:.3f} s")
    table.add(
        "chain / floor (service)",
        f"{vs_floor:.2f}x",
        f"<= {FLOOR_TARGET:g}x",
        vs_floor <= FLOOR_TARGET,
    )
    table.add(
        "Python loop / chain (service)",
        f"{vs_loop:.0f}x",
        f">= {LOOP_TARGET:g}x",
        vs_loop >= LOOP_TARGET,
    )
    table.add("chain / floor (default process)", f"{t_chain / t_floor:.2f}x", "(informative)")
    table.add("Python loop / chain (default process)", f"{t_loop / t_chain:.0f}x", "(informative)")
    table.print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
