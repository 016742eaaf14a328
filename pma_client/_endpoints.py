"""Each endpoint described once: its method, path, request body and result type.

A function here takes an endpoint's body fields as keyword arguments, named exactly like
the JSON fields, and returns the :class:`Call` to make. :class:`~pma_client.PMAClient` and
:class:`~pma_client.AsyncPMAClient` expose each function as a method of the same name,
signature and docstring, differing only in how they send the call.

Arguments left as None are omitted from the body, so the service applies its own default
(the API refuses ``null`` for most fields). Values are not checked here: the service
validates them and a refusal raises :class:`~pma_client.PMAValidationError`.
"""

from __future__ import annotations

import io
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any, Generic, Literal, TypeVar

import numpy as np

from pma_client._models import (
    DesignReport,
    FailureStrandCount,
    GapArea,
    Health,
    Hysteresis,
    HysteresisSweep,
    Material,
    MinBraidAngle,
    OpenSimActuator,
    PressureSweep,
    Reference,
    SScale,
    StrandCountSweep,
    materials_from_json,
)

T = TypeVar("T")


@dataclass(frozen=True)
class Call(Generic[T]):
    """One request to make, and how to read its answer into a ``T``.

    ``decode`` turns the body into what ``parse`` reads; None means JSON.
    """

    method: Literal["GET", "POST"]
    path: str
    parse: Callable[[Any], T]
    body: Mapping[str, Any] | None = None
    decode: Callable[[bytes], Any] | None = None


def npy_record(content: bytes) -> dict[str, Any]:
    """The fields of a ``.npy`` record answer: numbers as floats, curves as arrays."""
    try:
        record = np.load(io.BytesIO(content), allow_pickle=False)
    except (EOFError, ValueError) as error:  # empty, cut off, or not .npy at all
        raise ValueError(f"the .npy answer is not a .npy file: {error}") from error
    names = record.dtype.names if isinstance(record, np.ndarray) else None
    if not names or record.shape != ():
        raise ValueError("the .npy answer is not one record")
    return {name: record[name].item() if record[name].ndim == 0 else record[name] for name in names}


def _post(path: str, parse: Callable[[Any], T], fields: Mapping[str, Any]) -> Call[T]:
    return Call("POST", path, parse, {k: v for k, v in fields.items() if v is not None})


# Every body builder below passes ``locals()`` (read first thing, so it holds exactly the
# keyword arguments): the argument names are the JSON field names.


def health() -> Call[Health]:
    """Whether the service answers (``GET /healthz``).

    Returns
    -------
    Health
        ``status`` is ``"ok"``.

    Raises
    ------
    PMAError
        The service answered with an error status.
    """
    return Call("GET", "/healthz", Health.from_json)


def min_braid_angle(
    *,
    strand_diameter_m: float,
    strand_count: int,
    theoretical_diameter_m: float | None = None,
    strand_length_m: float | None = None,
    turns: float | None = None,
) -> Call[MinBraidAngle]:
    """Minimum braid angle θ_min (eq 8) and the contractile range (eq 9).

    ``POST /api/v1/min-braid-angle``.

    Parameters
    ----------
    strand_diameter_m : float
        D_s, diameter of one strand [m].
    strand_count : int
        N, total number of strands [-].
    theoretical_diameter_m, strand_length_m, turns : float, optional
        The braid's size: D_o [m], or b [m] with n [-] (D_o = b/(n·π)). With b the
        lengths of eq 9 are returned too.

    Returns
    -------
    MinBraidAngle

    Raises
    ------
    PMAValidationError
        The input was refused, e.g. more strands than fit around the braid.
    PMAError
        Any other error status, or an unexpected response.
    """
    return _post("/api/v1/min-braid-angle", MinBraidAngle.from_json, locals())


def gap_area(
    *,
    strand_diameter_m: float,
    strand_count: int,
    parallel_strands: int | None = None,
    braid_angle_deg: float | None = None,
    theoretical_diameter_m: float | None = None,
    strand_length_m: float | None = None,
    turns: float | None = None,
) -> Call[GapArea]:
    """Braid gap at a braid angle (eqs 12, 14) and its maximum at 45° (eq 15).

    ``POST /api/v1/gap-area``.

    Parameters
    ----------
    strand_diameter_m : float
        D_s [m].
    strand_count : int
        N [-].
    parallel_strands : int, optional
        S, parallel strands per path of the weave [-]; the service's default is 1.
    braid_angle_deg : float, optional
        θ [deg], within [θ_min, 90° − θ_min]; the service's default is 45.
    theoretical_diameter_m, strand_length_m, turns : float, optional
        The braid's size: D_o [m], or b [m] with n [-].

    Returns
    -------
    GapArea

    Raises
    ------
    PMAValidationError
        The input was refused.
    PMAError
        Any other error status, or an unexpected response.
    """
    return _post("/api/v1/gap-area", GapArea.from_json, locals())


def failure_strand_count(
    *,
    pressure_pa: float,
    strand_diameter_m: float,
    tensile_strength_pa: float,
    braid_angle_deg: float | None = None,
    safety_factor: float | None = None,
    theoretical_diameter_m: float | None = None,
    strand_length_m: float | None = None,
    turns: float | None = None,
) -> Call[FailureStrandCount]:
    """Fewest strands that hold the pressure (eq 20), at θ and at the 45° worst case.

    ``POST /api/v1/failure-strand-count``.

    Parameters
    ----------
    pressure_pa : float
        P, gauge pressure [Pa].
    strand_diameter_m : float
        D_s [m].
    tensile_strength_pa : float
        σ_u of the strand material [Pa].
    braid_angle_deg : float, optional
        θ [deg]; the service's default is 54.7356, fully contracted, as in the paper.
    safety_factor : float, optional
        k ≥ 1 dividing the tensile strength [-]; the service's default is 1.
    theoretical_diameter_m, strand_length_m, turns : float, optional
        The braid's size: D_o [m], or b [m] with n [-].

    Returns
    -------
    FailureStrandCount

    Raises
    ------
    PMAValidationError
        The input was refused.
    PMAError
        Any other error status, or an unexpected response.
    """
    return _post("/api/v1/failure-strand-count", FailureStrandCount.from_json, locals())


def s_scale(
    *,
    strand_diameter_m: float,
    pressure_pa: float,
    youngs_modulus_pa: float,
    poisson_ratio: float,
) -> Call[SScale]:
    """Contact-area scale factor S_scale (eq 34) from Hertz contact (eqs 32, 33).

    ``POST /api/v1/s-scale``.

    Parameters
    ----------
    strand_diameter_m : float
        D_s [m].
    pressure_pa : float
        P [Pa].
    youngs_modulus_pa : float
        E of the strand material [Pa].
    poisson_ratio : float
        ν of the strand material, 0 ≤ ν < 0.5 [-].

    Returns
    -------
    SScale

    Raises
    ------
    PMAValidationError
        The input was refused.
    PMAError
        Any other error status, or an unexpected response.
    """
    return _post("/api/v1/s-scale", SScale.from_json, locals())


def hysteresis(
    *,
    strand_diameter_m: float,
    strand_count: int,
    pressure_pa: float,
    friction_coefficient: float,
    youngs_modulus_pa: float,
    poisson_ratio: float,
    s_scale: float | None = None,
    points: int | None = None,
    theoretical_diameter_m: float | None = None,
    strand_length_m: float | None = None,
    turns: float | None = None,
) -> Call[Hysteresis]:
    """Force against contraction with friction hysteresis (eqs 10, 29-31).

    ``POST /api/v1/hysteresis``.

    Parameters
    ----------
    strand_diameter_m : float
        D_s [m].
    strand_count : int
        N [-].
    pressure_pa : float
        P [Pa].
    friction_coefficient : float
        f_s, strand on strand [-].
    youngs_modulus_pa : float
        E [Pa].
    poisson_ratio : float
        ν [-].
    s_scale : float, optional
        A measured S_scale [-], used instead of eq 34.
    points : int, optional
        Number of points along the stroke, 2 to 100 000; the service's default is 201.
    theoretical_diameter_m, strand_length_m, turns : float, optional
        The actuator's size: b [m] is needed, with n [-] or D_o [m].

    Returns
    -------
    Hysteresis
        Scalars, and numpy arrays of length ``points``.

    Raises
    ------
    PMAValidationError
        The input was refused.
    PMAError
        Any other error status, or an unexpected response.
    """
    # The curves come as a .npy record: with 100 000 points, formatting them as JSON takes
    # the service ten times longer than computing them.
    call = _post("/api/v1/hysteresis?format=npy-record", Hysteresis.from_json, locals())
    return replace(call, decode=npy_record)


def design(
    *,
    strand_diameter_m: float,
    strand_count: int,
    pressure_pa: float,
    parallel_strands: int | None = None,
    material: str | None = None,
    youngs_modulus_pa: float | None = None,
    poisson_ratio: float | None = None,
    tensile_strength_pa: float | None = None,
    friction_coefficient: float | None = None,
    safety_factor: float | None = None,
    s_scale: float | None = None,
    gap_area_limit_m2: float | None = None,
    theoretical_diameter_m: float | None = None,
    strand_length_m: float | None = None,
    turns: float | None = None,
) -> Call[DesignReport]:
    """Every quantity of one actuator, and the warnings that apply.

    ``POST /api/v1/design``.

    Parameters
    ----------
    strand_diameter_m : float
        D_s [m].
    strand_count : int
        N [-].
    pressure_pa : float
        P [Pa].
    parallel_strands : int, optional
        S [-]; the service's default is 1.
    material : str, optional
        A preset id of :meth:`materials` (e.g. ``"nylon"``); the four properties below
        override its values. Without a preset all four must be given.
    youngs_modulus_pa, poisson_ratio, tensile_strength_pa, friction_coefficient : float, optional
        E [Pa], ν [-], σ_u [Pa], f_s [-].
    safety_factor : float, optional
        k ≥ 1 [-]; the service's default is 1.
    s_scale : float, optional
        A measured S_scale [-], used instead of eq 34.
    gap_area_limit_m2 : float, optional
        Largest acceptable braid gap before the bladder warning [m²]; the service's
        default is 1 mm².
    theoretical_diameter_m, strand_length_m, turns : float, optional
        The braid's size: D_o [m], or any two of b [m], n [-] and D_o.

    Returns
    -------
    DesignReport
        With ``warnings``, a tuple of :class:`DesignWarning`.

    Raises
    ------
    PMAValidationError
        The input was refused, e.g. an unknown material.
    PMAError
        Any other error status, or an unexpected response.
    """
    return _post("/api/v1/design", DesignReport.from_json, locals())


def strand_count_sweep(
    *,
    strand_diameter_m: float,
    strand_count_min: int,
    strand_count_max: int,
    parallel_strands: int | None = None,
    theoretical_diameter_m: float | None = None,
    strand_length_m: float | None = None,
    turns: float | None = None,
) -> Call[StrandCountSweep]:
    """θ_min (eq 8), ε_max and the maximum gap area (eq 15) for each N of a range.

    ``POST /api/v1/sweeps/strand-count``. Only counts that fit around the braid are
    returned; ``strand_count_limit`` says where the range was cut.

    Parameters
    ----------
    strand_diameter_m : float
        D_s [m].
    strand_count_min, strand_count_max : int
        The range of N, both included [-].
    parallel_strands : int, optional
        S [-]; the service's default is 1.
    theoretical_diameter_m, strand_length_m, turns : float, optional
        The braid's size: D_o [m], or b [m] with n [-].

    Returns
    -------
    StrandCountSweep

    Raises
    ------
    PMAValidationError
        The input was refused.
    PMAError
        Any other error status, or an unexpected response.
    """
    return _post("/api/v1/sweeps/strand-count", StrandCountSweep.from_json, locals())


def pressure_sweep(
    *,
    strand_diameter_m: float,
    tensile_strength_pa: float,
    youngs_modulus_pa: float,
    poisson_ratio: float,
    pressure_min_pa: float,
    pressure_max_pa: float,
    safety_factor: float | None = None,
    points: int | None = None,
    theoretical_diameter_m: float | None = None,
    strand_length_m: float | None = None,
    turns: float | None = None,
) -> Call[PressureSweep]:
    """S_scale (eq 34) and the failure strand counts (eq 20) over a range of pressures.

    ``POST /api/v1/sweeps/pressure``.

    Parameters
    ----------
    strand_diameter_m : float
        D_s [m].
    tensile_strength_pa : float
        σ_u [Pa].
    youngs_modulus_pa : float
        E [Pa].
    poisson_ratio : float
        ν [-].
    pressure_min_pa, pressure_max_pa : float
        The range of P, both included [Pa].
    safety_factor : float, optional
        k ≥ 1 [-]; the service's default is 1.
    points : int, optional
        Number of pressures, 2 to 10 000; the service's default is 101.
    theoretical_diameter_m, strand_length_m, turns : float, optional
        The braid's size: D_o [m], or b [m] with n [-].

    Returns
    -------
    PressureSweep

    Raises
    ------
    PMAValidationError
        The input was refused.
    PMAError
        Any other error status, or an unexpected response.
    """
    return _post("/api/v1/sweeps/pressure", PressureSweep.from_json, locals())


def hysteresis_sweep(
    *,
    strand_diameter_m: float,
    strand_count: int,
    pressures_pa: Sequence[float],
    friction_coefficient: float,
    youngs_modulus_pa: float,
    poisson_ratio: float,
    strand_length_m: float | None = None,
    turns: float | None = None,
    theoretical_diameter_m: float | None = None,
    points: int | None = None,
) -> Call[HysteresisSweep]:
    """The hysteresis curves (eqs 10, 29-31) at several pressures, S_scale from eq 34.

    ``POST /api/v1/sweeps/hysteresis``.

    Parameters
    ----------
    strand_diameter_m : float
        D_s [m].
    strand_count : int
        N [-].
    pressures_pa : sequence of float
        P of each curve [Pa], 1 to 16 of them.
    friction_coefficient : float
        f_s [-].
    youngs_modulus_pa, poisson_ratio : float
        E [Pa] and ν [-] of the strand material.
    strand_length_m, turns, theoretical_diameter_m : float, optional
        b [m], n [-], D_o [m]: two of them, b among them.
    points : int, optional
        Points per curve, 2 to 10 000 (service default 201).

    Returns
    -------
    HysteresisSweep

    Raises
    ------
    PMAValidationError
        The input was refused.
    PMAError
        Any other error status, or an unexpected response.
    """
    fields = {**locals(), "pressures_pa": [float(p) for p in pressures_pa]}
    return _post("/api/v1/sweeps/hysteresis", HysteresisSweep.from_json, fields)


def opensim_export(
    *,
    strand_diameter_m: float,
    strand_count: int,
    strand_length_m: float | None = None,
    turns: float | None = None,
    theoretical_diameter_m: float | None = None,
    name: str | None = None,
    cord_length_m: float | None = None,
) -> Call[OpenSimActuator]:
    """The braid as an OpenSim ``McKibbenActuator`` (thread_length = b, number_of_turns = n).

    ``POST /api/v1/export/opensim``. Give b with n or with D_o.

    Parameters
    ----------
    strand_diameter_m : float
        D_s [m].
    strand_count : int
        N [-].
    strand_length_m, turns, theoretical_diameter_m : float, optional
        b [m], n [-], D_o [m]: two of them, b among them.
    name : str, optional
        Component name in the XML (default "pma").
    cord_length_m : float, optional
        Length of the unbraided end cords [m] (default 0).

    Returns
    -------
    OpenSimActuator

    Raises
    ------
    PMAValidationError
        The input was refused.
    PMAError
        Any other error status, or an unexpected response.
    """
    return _post("/api/v1/export/opensim", OpenSimActuator.from_json, locals())


def materials() -> Call[tuple[Material, ...]]:
    """The strand material presets, with the source of every number.

    ``GET /api/v1/materials``.

    Returns
    -------
    tuple of Material
        In the order the service lists them; ``id`` is the ``material`` of :meth:`design`.

    Raises
    ------
    PMAError
        The service answered with an error status, or an unexpected response.
    """
    return Call("GET", "/api/v1/materials", materials_from_json)


def reference() -> Call[Reference]:
    """The paper's measured data: its braid, Table 1 and the fitted S_scale values.

    ``GET /api/v1/reference``.

    Returns
    -------
    Reference

    Raises
    ------
    PMAError
        The service answered with an error status, or an unexpected response.
    """
    return Call("GET", "/api/v1/reference", Reference.from_json)
