"""Resolve the braid geometry a body gives: D_o alone, or any two of b, n and D_o (eq 1)."""

from __future__ import annotations

from dataclasses import dataclass

from app.errors import field_error
from app.fields import STRAND_LENGTH_RANGE_M, THEORETICAL_DIAMETER_RANGE_M, TURNS_RANGE
from pma_core import geometry


@dataclass(frozen=True)
class Geometry:
    """Braid geometry in SI units; ``strand_length_m`` and ``turns`` unknown as None."""

    theoretical_diameter_m: float
    strand_length_m: float | None
    turns: float | None


def resolve_geometry(
    theoretical_diameter_m: float | None,
    strand_length_m: float | None,
    turns: float | None,
    *,
    need_length: bool = False,
) -> Geometry:
    """Return the geometry, or raise a 422 naming the field that is missing or extra."""
    d_o, b, n = theoretical_diameter_m, strand_length_m, turns
    given = sum(v is not None for v in (d_o, b, n))
    if given == 3:
        raise field_error(
            "theoretical_diameter_m",
            "give either theoretical_diameter_m, or strand_length_m with turns, not both:"
            " D_o = b/(n·π) would be given twice",
        )
    if d_o is None and b is None and n is None:
        raise field_error(
            "theoretical_diameter_m",
            "give the braid's size: theoretical_diameter_m (D_o), or strand_length_m (b)"
            " with turns (n)",
        )
    if given == 1 and d_o is None:
        missing = "turns" if b is not None else "strand_length_m"
        raise field_error(
            missing,
            f"{missing} is needed with {'strand_length_m' if b else 'turns'}"
            " to give the braid's size, D_o = b/(n·π)",
        )
    if need_length and b is None and n is None:
        raise field_error(
            "strand_length_m",
            "this calculation needs the actuator's size: give strand_length_m (b) with"
            " theoretical_diameter_m or turns",
        )
    return _complete(d_o, b, n)


def _complete(d_o: float | None, b: float | None, n: float | None) -> Geometry:
    if d_o is None:
        assert b is not None
        assert n is not None
        d_o = _derived("theoretical_diameter_m", geometry.theoretical_diameter(b, n), "turns")
    elif b is not None:
        n = _derived("turns", geometry.turns(b, d_o), "strand_length_m")
    elif n is not None:
        b = _derived("strand_length_m", geometry.strand_length(n, d_o), "turns")
    return Geometry(d_o, b, n)


_RANGES = {
    "theoretical_diameter_m": (*THEORETICAL_DIAMETER_RANGE_M, " m"),
    "strand_length_m": (*STRAND_LENGTH_RANGE_M, " m"),
    "turns": (*TURNS_RANGE, ""),
}


def _derived(name: str, value: float, blamed: str) -> float:
    """A quantity worked out from eq 1, held to the bounds it has when given directly."""
    result = float(value)
    low, high, unit = _RANGES[name]
    if not low <= result <= high:
        raise field_error(
            blamed,
            f"the braid's size gives {name} = {result:.4g}{unit} by eq 1 (D_o = b/(n·π)),"
            f" outside the {low:g}{unit} to {high:g}{unit} the calculator accepts",
        )
    return result
