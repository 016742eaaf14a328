"""Exports to other tools: the design as OpenSim ``McKibbenActuator`` parameters."""

from __future__ import annotations

from xml.sax.saxutils import escape

from fastapi import APIRouter

from app.errors import core_errors
from app.responses import JSONResponse
from app.routing import JSONBodyRoute
from app.schemas import OpenSimIn, OpenSimOut
from pma_core import braid

router = APIRouter(
    prefix="/api/v1/export",
    tags=["export"],
    default_response_class=JSONResponse,
    route_class=JSONBodyRoute,
)


@router.post("/opensim", response_model=OpenSimOut)
async def opensim(body: OpenSimIn) -> JSONResponse:
    """The design as OpenSim ``McKibbenActuator`` properties and XML.

    OpenSim's force law F = P(3L² − b²)/(4πn²), with L the braided length, is the static
    force of eq 10 with thread_length = b and number_of_turns = n. OpenSim knows no braid
    limits: keep the actuator between ``min_length_m`` and ``max_length_m`` (plus cords).
    """
    with core_errors(OpenSimIn.model_fields):
        geo = body.geometry(need_length=True)
        assert geo.strand_length_m is not None
        assert geo.turns is not None
        args = (geo.strand_length_m, geo.turns, body.strand_diameter_m, body.strand_count)
        max_length, min_length = float(braid.max_length(*args)), float(braid.min_length(*args))
    xml = (
        f'<McKibbenActuator name="{escape(body.name)}">\n'
        f"    <thread_length>{geo.strand_length_m!r}</thread_length>\n"
        f"    <number_of_turns>{geo.turns!r}</number_of_turns>\n"
        f"    <cord_length>{body.cord_length_m!r}</cord_length>\n"
        "</McKibbenActuator>\n"
    )
    return JSONResponse(
        {
            "thread_length": geo.strand_length_m,
            "number_of_turns": geo.turns,
            "cord_length": body.cord_length_m,
            "max_length_m": max_length,
            "min_length_m": min_length,
            "xml": xml,
        }
    )
