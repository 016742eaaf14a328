"""Typed results of the API: one frozen dataclass per response, built by ``from_json``.

Field names, units and meanings are those of the API's JSON (``/openapi.json``). Fields a
newer server adds are ignored, so an older client keeps working. Arrays are read-only
numpy arrays: float64, or int64 for strand counts. Results holding arrays compare by
identity (``eq=False``): compare their arrays with :func:`numpy.array_equal` instead.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Self

import numpy as np
import numpy.typing as npt

#: A one-dimensional, read-only array of floats.
FloatArray = npt.NDArray[np.float64]
#: A one-dimensional, read-only array of whole numbers (strand counts).
IntArray = npt.NDArray[np.int64]

Json = Mapping[str, Any]


def _number(data: Json, key: str) -> float:
    value = data[key]
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise TypeError(f"{key} should be a number, got {value!r}")
    return float(value)


def _optional_number(data: Json, key: str) -> float | None:
    return None if data[key] is None else _number(data, key)


def _whole(data: Json, key: str) -> int:
    value = data[key]
    if isinstance(value, bool) or not isinstance(value, int):
        raise TypeError(f"{key} should be a whole number, got {value!r}")
    return value


def _text(data: Json, key: str) -> str:
    value = data[key]
    if not isinstance(value, str):
        raise TypeError(f"{key} should be a string, got {value!r}")
    return value


def _array(
    data: Json, key: str, kinds: str, dtype: type[np.generic], ndim: int = 1
) -> npt.NDArray[Any]:
    raw = np.asarray(data[key])
    if raw.ndim != ndim or (raw.size and raw.dtype.kind not in kinds):
        raise TypeError(f"{key} should be a {'table' if ndim == 2 else 'list'} of numbers")
    array = raw.astype(dtype)
    array.flags.writeable = False
    return array


def _floats(data: Json, key: str) -> FloatArray:
    return _array(data, key, "iuf", np.float64)


def _rows(data: Json, key: str) -> FloatArray:
    return _array(data, key, "iuf", np.float64, ndim=2)


def _wholes(data: Json, key: str) -> IntArray:
    return _array(data, key, "iu", np.int64)


def _objects(data: Json, key: str) -> list[Json]:
    value = data[key]
    if not isinstance(value, list) or not all(isinstance(item, Mapping) for item in value):
        raise TypeError(f"{key} should be a list of objects")
    return value


@dataclass(frozen=True)
class Health:
    """``GET /healthz``.

    Attributes
    ----------
    status : str
        ``"ok"`` while the service answers.
    """

    status: str

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(status=_text(data, "status"))


@dataclass(frozen=True)
class MinBraidAngle:
    """``POST /api/v1/min-braid-angle``: θ_min (eq 8) and the contractile range (eq 9).

    Attributes
    ----------
    min_braid_angle_deg : float
        θ_min, eq 8 [deg].
    max_braid_angle_deg : float
        θ_max = min(54.7356°, 90° − θ_min) [deg].
    jamming_angle_deg : float
        90° − θ_min, where the braid locks [deg].
    max_contraction : float
        1 − cos θ_max / cos θ_min [-].
    theoretical_diameter_m : float
        D_o used [m].
    max_length_m, min_length_m, stroke_m : float or None
        b·cos θ_min (eq 9), b·cos θ_max (eq 19) and their difference [m]; None without b.
    """

    min_braid_angle_deg: float
    max_braid_angle_deg: float
    jamming_angle_deg: float
    max_contraction: float
    theoretical_diameter_m: float
    max_length_m: float | None
    min_length_m: float | None
    stroke_m: float | None

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            min_braid_angle_deg=_number(data, "min_braid_angle_deg"),
            max_braid_angle_deg=_number(data, "max_braid_angle_deg"),
            jamming_angle_deg=_number(data, "jamming_angle_deg"),
            max_contraction=_number(data, "max_contraction"),
            theoretical_diameter_m=_number(data, "theoretical_diameter_m"),
            max_length_m=_optional_number(data, "max_length_m"),
            min_length_m=_optional_number(data, "min_length_m"),
            stroke_m=_optional_number(data, "stroke_m"),
        )


@dataclass(frozen=True)
class GapArea:
    """``POST /api/v1/gap-area``: the braid gap at θ (eqs 12, 14) and its maximum (eq 15).

    Attributes
    ----------
    braid_angle_deg : float
        θ [deg].
    node_spacing_m : float
        G, eq 12 [m].
    gap_width_m : float
        Z, eq 14 [m]; 0 where the strands touch.
    gap_area_m2 : float
        Z²/(2·tan θ) at θ [m²].
    max_gap_area_m2 : float
        Z²/2 at 45°, eq 15 [m²].
    """

    braid_angle_deg: float
    node_spacing_m: float
    gap_width_m: float
    gap_area_m2: float
    max_gap_area_m2: float

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            braid_angle_deg=_number(data, "braid_angle_deg"),
            node_spacing_m=_number(data, "node_spacing_m"),
            gap_width_m=_number(data, "gap_width_m"),
            gap_area_m2=_number(data, "gap_area_m2"),
            max_gap_area_m2=_number(data, "max_gap_area_m2"),
        )


@dataclass(frozen=True)
class FailureStrandCount:
    """``POST /api/v1/failure-strand-count``, and ``failure_strand_count`` of a design.

    Attributes
    ----------
    braid_angle_deg : float
        θ at which eq 20 is evaluated [deg].
    min_strand_count_exact : float
        N of eq 20, a real number [-].
    min_strand_count : int
        ceil(N): the fewest whole strands that hold [-].
    worst_case_braid_angle_deg : float
        45°, where the strand stress peaks [deg].
    worst_case_min_strand_count_exact : float
        N of eq 20 at 45° [-].
    worst_case_min_strand_count : int
        ceil(N) at 45° [-].
    """

    braid_angle_deg: float
    min_strand_count_exact: float
    min_strand_count: int
    worst_case_braid_angle_deg: float
    worst_case_min_strand_count_exact: float
    worst_case_min_strand_count: int

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            braid_angle_deg=_number(data, "braid_angle_deg"),
            min_strand_count_exact=_number(data, "min_strand_count_exact"),
            min_strand_count=_whole(data, "min_strand_count"),
            worst_case_braid_angle_deg=_number(data, "worst_case_braid_angle_deg"),
            worst_case_min_strand_count_exact=_number(data, "worst_case_min_strand_count_exact"),
            worst_case_min_strand_count=_whole(data, "worst_case_min_strand_count"),
        )


@dataclass(frozen=True)
class OpenSimActuator:
    """``POST /api/v1/export/opensim``: the braid as an OpenSim ``McKibbenActuator``.

    Attributes
    ----------
    thread_length : float
        OpenSim thread_length = b [m].
    number_of_turns : float
        OpenSim number_of_turns = n [-].
    cord_length : float
        OpenSim cord_length [m].
    max_length_m, min_length_m : float
        Braided length at θ_min (eq 9) and at θ_max [m].
    xml : str
        The ``<McKibbenActuator>`` element for an .osim model.
    """

    thread_length: float
    number_of_turns: float
    cord_length: float
    max_length_m: float
    min_length_m: float
    xml: str

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            thread_length=_number(data, "thread_length"),
            number_of_turns=_number(data, "number_of_turns"),
            cord_length=_number(data, "cord_length"),
            max_length_m=_number(data, "max_length_m"),
            min_length_m=_number(data, "min_length_m"),
            xml=_text(data, "xml"),
        )


@dataclass(frozen=True)
class SScale:
    """``POST /api/v1/s-scale``: the contact-area scale factor (eqs 32-34).

    Attributes
    ----------
    s_scale : float
        S_scale, eq 34 [-].
    contact_radius_m : float
        a_c of the sphere contact, eq 33 [m].
    flat_contact_radius_m : float
        a_c of flat strands, D_s/2 [m].
    compressive_force_n : float
        F_comp = P·D_s² [N].
    """

    s_scale: float
    contact_radius_m: float
    flat_contact_radius_m: float
    compressive_force_n: float

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            s_scale=_number(data, "s_scale"),
            contact_radius_m=_number(data, "contact_radius_m"),
            flat_contact_radius_m=_number(data, "flat_contact_radius_m"),
            compressive_force_n=_number(data, "compressive_force_n"),
        )


@dataclass(frozen=True, eq=False)
class Hysteresis:
    """``POST /api/v1/hysteresis``: force against contraction with friction (eqs 10, 29-31).

    Every array has ``points`` values, evenly spaced in contraction from 0 to the maximum.

    Attributes
    ----------
    s_scale : float
        S_scale used: the measured one given, or eq 34 [-].
    min_braid_angle_deg, max_braid_angle_deg : float
        θ_min (eq 8) and θ_max [deg].
    braid_angle_deg : FloatArray
        θ at each point [deg].
    length_m : FloatArray
        L = b·cos θ, eq 19 [m].
    contraction : FloatArray
        1 − L/L_max [-].
    force_static_n : FloatArray
        F_static, eq 10 [N].
    friction_force_n : FloatArray
        F_friction, eq 30 [N].
    force_contracting_n : FloatArray
        F_static − F_friction, eq 31, clipped at 0 [N].
    force_extending_n : FloatArray
        F_static + F_friction, eq 31 [N].
    """

    s_scale: float
    min_braid_angle_deg: float
    max_braid_angle_deg: float
    braid_angle_deg: FloatArray
    length_m: FloatArray
    contraction: FloatArray
    force_static_n: FloatArray
    friction_force_n: FloatArray
    force_contracting_n: FloatArray
    force_extending_n: FloatArray

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's fields (its JSON object or its .npy record)."""
        return cls(
            s_scale=_number(data, "s_scale"),
            min_braid_angle_deg=_number(data, "min_braid_angle_deg"),
            max_braid_angle_deg=_number(data, "max_braid_angle_deg"),
            braid_angle_deg=_floats(data, "braid_angle_deg"),
            length_m=_floats(data, "length_m"),
            contraction=_floats(data, "contraction"),
            force_static_n=_floats(data, "force_static_n"),
            friction_force_n=_floats(data, "friction_force_n"),
            force_contracting_n=_floats(data, "force_contracting_n"),
            force_extending_n=_floats(data, "force_extending_n"),
        )


@dataclass(frozen=True, eq=False)
class HysteresisSweep:
    """``POST /api/v1/sweeps/hysteresis``: the hysteresis curves at several pressures.

    The contraction grid is shared; each force array has a row per pressure.

    Attributes
    ----------
    pressure_pa : FloatArray
        P of each row [Pa].
    s_scale : FloatArray
        S_scale of eq 34 at each pressure [-].
    min_braid_angle_deg, max_braid_angle_deg : float
        θ_min (eq 8) and θ_max [deg].
    braid_angle_deg, length_m, contraction : FloatArray
        θ [deg], L [m] and contraction [-] at each point.
    force_static_n, friction_force_n, force_contracting_n, force_extending_n : FloatArray
        Eqs 10, 30 and 31 [N], shape (pressures, points).
    """

    pressure_pa: FloatArray
    s_scale: FloatArray
    min_braid_angle_deg: float
    max_braid_angle_deg: float
    braid_angle_deg: FloatArray
    length_m: FloatArray
    contraction: FloatArray
    force_static_n: FloatArray
    friction_force_n: FloatArray
    force_contracting_n: FloatArray
    force_extending_n: FloatArray

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            pressure_pa=_floats(data, "pressure_pa"),
            s_scale=_floats(data, "s_scale"),
            min_braid_angle_deg=_number(data, "min_braid_angle_deg"),
            max_braid_angle_deg=_number(data, "max_braid_angle_deg"),
            braid_angle_deg=_floats(data, "braid_angle_deg"),
            length_m=_floats(data, "length_m"),
            contraction=_floats(data, "contraction"),
            force_static_n=_rows(data, "force_static_n"),
            friction_force_n=_rows(data, "friction_force_n"),
            force_contracting_n=_rows(data, "force_contracting_n"),
            force_extending_n=_rows(data, "force_extending_n"),
        )


@dataclass(frozen=True)
class MaterialProperties:
    """The strand material a design used: the preset's values with the overrides given.

    Attributes
    ----------
    youngs_modulus_pa : float
        E [Pa].
    poisson_ratio : float
        ν [-].
    tensile_strength_pa : float
        σ_u [Pa].
    friction_coefficient : float
        f_s [-].
    """

    youngs_modulus_pa: float
    poisson_ratio: float
    tensile_strength_pa: float
    friction_coefficient: float

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            youngs_modulus_pa=_number(data, "youngs_modulus_pa"),
            poisson_ratio=_number(data, "poisson_ratio"),
            tensile_strength_pa=_number(data, "tensile_strength_pa"),
            friction_coefficient=_number(data, "friction_coefficient"),
        )


@dataclass(frozen=True)
class DesignWarning:
    """A problem with a design: a stable ``code`` and a ``message`` saying why, in words.

    Attributes
    ----------
    code : str
        ``below_failure_count``, ``below_worst_case_failure_count``, ``gap_admits_bladder``,
        ``jams_before_neutral_angle`` or ``strand_count_not_braidable``.
    message : str
        What is wrong and why.
    """

    code: str
    message: str

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(code=_text(data, "code"), message=_text(data, "message"))


@dataclass(frozen=True)
class DesignReport:
    """``POST /api/v1/design``: every quantity of one actuator and the warnings that apply.

    Attributes
    ----------
    theoretical_diameter_m : float
        D_o [m].
    strand_length_m, turns : float or None
        b [m] and n [-]; None when not known.
    min_braid_angle_deg, jamming_angle_deg, max_braid_angle_deg : float
        θ_min (eq 8), 90° − θ_min and θ_max [deg].
    max_contraction : float
        ε_max [-].
    max_length_m, min_length_m, stroke_m : float or None
        L_max (eq 9), L_min and L_max − L_min [m]; None without b.
    peak_static_force_n : float
        F_static at θ_min, eq 10 [N].
    max_gap_width_m : float
        Z at 45°, eq 14 [m].
    max_gap_area_m2 : float
        Eq 15 [m²].
    failure_strand_count : FailureStrandCount
        Eq 20 at 54.7356° and at 45°.
    worst_case_strand_stress_pa : float
        σ at 45° with this N, eq 17 [Pa].
    s_scale, s_scale_computed : float
        S_scale used, and that of eq 34 [-].
    material : MaterialProperties
        The material values used.
    warnings : tuple of DesignWarning
        Empty when nothing is wrong.
    """

    theoretical_diameter_m: float
    strand_length_m: float | None
    turns: float | None
    min_braid_angle_deg: float
    jamming_angle_deg: float
    max_braid_angle_deg: float
    max_contraction: float
    max_length_m: float | None
    min_length_m: float | None
    stroke_m: float | None
    peak_static_force_n: float
    max_gap_width_m: float
    max_gap_area_m2: float
    failure_strand_count: FailureStrandCount
    worst_case_strand_stress_pa: float
    s_scale: float
    s_scale_computed: float
    material: MaterialProperties
    warnings: tuple[DesignWarning, ...]

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            theoretical_diameter_m=_number(data, "theoretical_diameter_m"),
            strand_length_m=_optional_number(data, "strand_length_m"),
            turns=_optional_number(data, "turns"),
            min_braid_angle_deg=_number(data, "min_braid_angle_deg"),
            jamming_angle_deg=_number(data, "jamming_angle_deg"),
            max_braid_angle_deg=_number(data, "max_braid_angle_deg"),
            max_contraction=_number(data, "max_contraction"),
            max_length_m=_optional_number(data, "max_length_m"),
            min_length_m=_optional_number(data, "min_length_m"),
            stroke_m=_optional_number(data, "stroke_m"),
            peak_static_force_n=_number(data, "peak_static_force_n"),
            max_gap_width_m=_number(data, "max_gap_width_m"),
            max_gap_area_m2=_number(data, "max_gap_area_m2"),
            failure_strand_count=FailureStrandCount.from_json(data["failure_strand_count"]),
            worst_case_strand_stress_pa=_number(data, "worst_case_strand_stress_pa"),
            s_scale=_number(data, "s_scale"),
            s_scale_computed=_number(data, "s_scale_computed"),
            material=MaterialProperties.from_json(data["material"]),
            warnings=tuple(DesignWarning.from_json(w) for w in _objects(data, "warnings")),
        )


@dataclass(frozen=True, eq=False)
class StrandCountSweep:
    """``POST /api/v1/sweeps/strand-count``: θ_min, ε_max and gap area against N.

    Attributes
    ----------
    strand_count_limit : int
        Largest N that fits around the braid [-]; the range is cut there.
    strand_count : IntArray
        N, the feasible counts of the range [-].
    min_braid_angle_deg : FloatArray
        θ_min, eq 8 [deg].
    max_contraction : FloatArray
        ε_max [-].
    max_gap_area_m2 : FloatArray
        Eq 15 [m²].
    """

    strand_count_limit: int
    strand_count: IntArray
    min_braid_angle_deg: FloatArray
    max_contraction: FloatArray
    max_gap_area_m2: FloatArray

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            strand_count_limit=_whole(data, "strand_count_limit"),
            strand_count=_wholes(data, "strand_count"),
            min_braid_angle_deg=_floats(data, "min_braid_angle_deg"),
            max_contraction=_floats(data, "max_contraction"),
            max_gap_area_m2=_floats(data, "max_gap_area_m2"),
        )


@dataclass(frozen=True, eq=False)
class PressureSweep:
    """``POST /api/v1/sweeps/pressure``: S_scale and failure strand counts against P.

    Attributes
    ----------
    pressure_pa : FloatArray
        P, evenly spaced [Pa].
    s_scale : FloatArray
        S_scale, eq 34 [-].
    min_strand_count_exact : FloatArray
        N of eq 20 at 54.7356° [-].
    min_strand_count : IntArray
        ceil(N) [-].
    worst_case_min_strand_count_exact : FloatArray
        N of eq 20 at 45° [-].
    worst_case_min_strand_count : IntArray
        ceil(N) at 45° [-].
    """

    pressure_pa: FloatArray
    s_scale: FloatArray
    min_strand_count_exact: FloatArray
    min_strand_count: IntArray
    worst_case_min_strand_count_exact: FloatArray
    worst_case_min_strand_count: IntArray

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            pressure_pa=_floats(data, "pressure_pa"),
            s_scale=_floats(data, "s_scale"),
            min_strand_count_exact=_floats(data, "min_strand_count_exact"),
            min_strand_count=_wholes(data, "min_strand_count"),
            worst_case_min_strand_count_exact=_floats(data, "worst_case_min_strand_count_exact"),
            worst_case_min_strand_count=_wholes(data, "worst_case_min_strand_count"),
        )


@dataclass(frozen=True)
class Material:
    """A strand material preset of ``GET /api/v1/materials``.

    Attributes
    ----------
    id : str
        Stable identifier: the ``material`` argument of ``design``.
    name : str
        Human-readable name.
    youngs_modulus_pa : float
        E [Pa].
    poisson_ratio : float
        ν [-].
    tensile_strength_pa : float
        σ_u [Pa].
    friction_coefficient : float
        f_s [-].
    basis : str
        Whether the values are bulk-polymer or fibre values.
    sources : Mapping of str to str
        The source of each number, keyed by field name (read-only).
    """

    id: str
    name: str
    youngs_modulus_pa: float
    poisson_ratio: float
    tensile_strength_pa: float
    friction_coefficient: float
    basis: str
    sources: Mapping[str, str]

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from one element of the response's ``materials`` list."""
        sources = data["sources"]
        if not isinstance(sources, Mapping) or not all(
            isinstance(value, str) for value in sources.values()
        ):
            raise TypeError("sources should be an object of strings")
        return cls(
            id=_text(data, "id"),
            name=_text(data, "name"),
            youngs_modulus_pa=_number(data, "youngs_modulus_pa"),
            poisson_ratio=_number(data, "poisson_ratio"),
            tensile_strength_pa=_number(data, "tensile_strength_pa"),
            friction_coefficient=_number(data, "friction_coefficient"),
            basis=_text(data, "basis"),
            sources=MappingProxyType(dict(sources)),
        )


def materials_from_json(data: Json) -> tuple[Material, ...]:
    """The presets of a ``GET /api/v1/materials`` response, in the server's order."""
    return tuple(Material.from_json(item) for item in _objects(data, "materials"))


@dataclass(frozen=True)
class BraidSample:
    """The paper's braid sample of §2.1 (Table 1, eq 15).

    Attributes
    ----------
    theoretical_diameter_m : float
        D_o [m].
    strand_diameter_m : float
        D_s [m].
    strand_count : int
        N [-].
    parallel_strands : int
        S [-].
    """

    theoretical_diameter_m: float
    strand_diameter_m: float
    strand_count: int
    parallel_strands: int

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            theoretical_diameter_m=_number(data, "theoretical_diameter_m"),
            strand_diameter_m=_number(data, "strand_diameter_m"),
            strand_count=_whole(data, "strand_count"),
            parallel_strands=_whole(data, "parallel_strands"),
        )


@dataclass(frozen=True)
class PaperTestMuscle:
    """The paper's hysteresis test muscle of §3.3 (its D_o = b/(n·π) is 44 mm).

    Attributes
    ----------
    strand_length_m : float
        b [m].
    turns : float
        n [-].
    strand_diameter_m : float
        D_s [m].
    strand_count : int
        N [-].
    friction_coefficient : float
        f_s [-].
    """

    strand_length_m: float
    turns: float
    strand_diameter_m: float
    strand_count: int
    friction_coefficient: float

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            strand_length_m=_number(data, "strand_length_m"),
            turns=_number(data, "turns"),
            strand_diameter_m=_number(data, "strand_diameter_m"),
            strand_count=_whole(data, "strand_count"),
            friction_coefficient=_number(data, "friction_coefficient"),
        )


@dataclass(frozen=True)
class MinBraidAngleMeasurement:
    """One row of the paper's Table 1 [deg].

    Attributes
    ----------
    strand_count : int
        N [-].
    measured_deg, std_deg : float
        Measured θ_min and its standard deviation [deg].
    calculated_deg : float
        θ_min of eq 8 as the paper prints it [deg].
    """

    strand_count: int
    measured_deg: float
    std_deg: float
    calculated_deg: float

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            strand_count=_whole(data, "strand_count"),
            measured_deg=_number(data, "measured_deg"),
            std_deg=_number(data, "std_deg"),
            calculated_deg=_number(data, "calculated_deg"),
        )


@dataclass(frozen=True)
class SScaleFit:
    """An S_scale fitted to measured hysteresis at one pressure.

    Attributes
    ----------
    pressure_pa : float
        P [Pa].
    s_scale : float
        The fitted S_scale [-].
    source : str
        Who fitted it.
    """

    pressure_pa: float
    s_scale: float
    source: str

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            pressure_pa=_number(data, "pressure_pa"),
            s_scale=_number(data, "s_scale"),
            source=_text(data, "source"),
        )


@dataclass(frozen=True)
class Reference:
    """``GET /api/v1/reference``: the paper's measured data.

    Attributes
    ----------
    braid_sample : BraidSample
        The braid of §2.1.
    test_muscle : PaperTestMuscle
        The hysteresis test muscle of §3.3.
    min_braid_angle_table1 : tuple of MinBraidAngleMeasurement
        Table 1.
    s_scale_fitted : tuple of SScaleFit
        S_scale values fitted to experiments.
    """

    braid_sample: BraidSample
    test_muscle: PaperTestMuscle
    min_braid_angle_table1: tuple[MinBraidAngleMeasurement, ...]
    s_scale_fitted: tuple[SScaleFit, ...]

    @classmethod
    def from_json(cls, data: Json) -> Self:
        """Build from the response's JSON object."""
        return cls(
            braid_sample=BraidSample.from_json(data["braid_sample"]),
            test_muscle=PaperTestMuscle.from_json(data["test_muscle"]),
            min_braid_angle_table1=tuple(
                MinBraidAngleMeasurement.from_json(row)
                for row in _objects(data, "min_braid_angle_table1")
            ),
            s_scale_fitted=tuple(
                SScaleFit.from_json(fit) for fit in _objects(data, "s_scale_fitted")
            ),
        )
