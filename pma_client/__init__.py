"""Typed Python client of the PMA calculator's HTTP API, blocking and asynchronous.

:class:`PMAClient` (over :class:`httpx.Client`) and :class:`AsyncPMAClient` (over
:class:`httpx.AsyncClient`) have one method per endpoint. The keyword arguments are the
API's JSON fields, SI units in their names; optional ones left as None are not sent, so
the service applies its defaults. Results are frozen dataclasses; curves and sweeps are
read-only numpy arrays. A refused input raises :class:`PMAValidationError` naming the
field; any other error status :class:`PMAError`.

Examples
--------
The paper's braid (Davis & Caldwell 2006, Table 1), against ``pma-calculator serve``:

>>> from pma_client import PMAClient
>>> with PMAClient("http://127.0.0.1:8000") as pma:  # doctest: +SKIP
...     braid = pma.min_braid_angle(
...         strand_diameter_m=0.25e-3, strand_count=240, theoretical_diameter_m=0.031
...     )
>>> round(braid.min_braid_angle_deg, 1)  # doctest: +SKIP
19.0

The same with :class:`AsyncPMAClient`, inside a coroutine:

>>> import asyncio
>>> from pma_client import AsyncPMAClient
>>> async def main() -> float:
...     async with AsyncPMAClient() as pma:
...         result = await pma.s_scale(
...             strand_diameter_m=0.25e-3,
...             pressure_pa=200e3,
...             youngs_modulus_pa=3e9,
...             poisson_ratio=0.4,
...         )
...     return result.s_scale
>>> round(asyncio.run(main()), 1)  # doctest: +SKIP
18.1
"""

from __future__ import annotations

from pma_client._client import DEFAULT_BASE_URL, DEFAULT_TIMEOUT, AsyncPMAClient, PMAClient
from pma_client._errors import PMAError, PMAValidationError
from pma_client._models import (
    BraidSample,
    DesignReport,
    DesignWarning,
    FailureStrandCount,
    FloatArray,
    GapArea,
    Health,
    Hysteresis,
    HysteresisSweep,
    IntArray,
    Material,
    MaterialProperties,
    MinBraidAngle,
    MinBraidAngleMeasurement,
    OpenSimActuator,
    PaperTestMuscle,
    PressureSweep,
    Reference,
    SScale,
    SScaleFit,
    StrandCountSweep,
)

__all__ = [
    "DEFAULT_BASE_URL",
    "DEFAULT_TIMEOUT",
    "AsyncPMAClient",
    "BraidSample",
    "DesignReport",
    "DesignWarning",
    "FailureStrandCount",
    "FloatArray",
    "GapArea",
    "Health",
    "Hysteresis",
    "HysteresisSweep",
    "IntArray",
    "Material",
    "MaterialProperties",
    "MinBraidAngle",
    "MinBraidAngleMeasurement",
    "OpenSimActuator",
    "PMAClient",
    "PMAError",
    "PMAValidationError",
    "PaperTestMuscle",
    "PressureSweep",
    "Reference",
    "SScale",
    "SScaleFit",
    "StrandCountSweep",
]
