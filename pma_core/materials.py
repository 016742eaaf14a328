"""Braid strand materials: elastic constants, strength and friction, with their sources.

The paper uses bulk nylon values (Brydson 1999). Fibres drawn from the same polymers are
several times stronger and stiffer along their axis, so a preset states its basis. Values
are typical, not guaranteed: a user with a datasheet for their own braid should use it.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Material:
    """A braid strand material preset.

    Attributes
    ----------
    id : str
        Stable identifier used by the API.
    name : str
        Human-readable name.
    youngs_modulus_pa : float
        :math:`E` [Pa].
    poisson_ratio : float
        :math:`\\nu` [-].
    tensile_strength_pa : float
        :math:`\\sigma_u` [Pa].
    friction_coefficient : float
        :math:`f_s`, same material strand on strand [-].
    basis : str
        Whether the values are bulk-polymer or fibre values.
    sources : dict of str to str
        The source of each number, keyed by attribute name.
    """

    id: str
    name: str
    youngs_modulus_pa: float
    poisson_ratio: float
    tensile_strength_pa: float
    friction_coefficient: float
    basis: str
    sources: dict[str, str]


_BRYDSON = (
    "Brydson, J. (1999) Plastics Materials, 7th ed., Elsevier (as used by Davis & Caldwell 2006)"
)
_MPE = "Modern Plastics Encyclopedia '99, McGraw-Hill: PET 2.7-4.0 GPa, 47-70 MPa"
_MORTON_HEARLE = (
    "Morton, W. E. & Hearle, J. W. S. (2008) Physical Properties of Textile Fibres, 4th ed.,"
    " Woodhead, Table 13.2"
)
_TEIJIN = (
    "Teijin Aramid, Tensile Properties of Industrial Fibers, Table 3 (Technora technical data)"
)

NYLON = Material(
    id="nylon",
    name="Nylon 6,6 (paper's braid)",
    youngs_modulus_pa=3.0e9,
    poisson_ratio=0.4,
    tensile_strength_pa=75e6,
    friction_coefficient=0.2,
    basis="bulk polymer, as in Davis & Caldwell 2006",
    sources={
        "youngs_modulus_pa": _BRYDSON,
        "poisson_ratio": _BRYDSON,
        "tensile_strength_pa": _BRYDSON,
        "friction_coefficient": (
            "Plastics Design Library Staff (1995) Fatigue and Tribological Properties of"
            " Plastics and Elastomers, William Andrew: 0.15-0.25 nylon on nylon; 0.2 as in the"
            " paper's test"
        ),
    },
)

PET_BULK = Material(
    id="pet",
    name="Polyester (PET), bulk values",
    youngs_modulus_pa=2.9e9,
    poisson_ratio=0.39,
    tensile_strength_pa=60e6,
    friction_coefficient=0.2,
    basis="bulk polymer, like for like with the paper's nylon",
    sources={
        "youngs_modulus_pa": _MPE,
        "poisson_ratio": "Granta/CES EduPack PET record: 0.38-0.40 (estimated)",
        "tensile_strength_pa": _MPE + " (mid-range)",
        "friction_coefficient": (
            "PET on PET 0.12-0.45 across sources (film, ASTM D1894; fibre tables); 0.2"
            " chosen to match the paper's polymer braid: low confidence, measure if it matters"
        ),
    },
)

PET_FIBRE = Material(
    id="pet-fibre",
    name="Polyester (PET) monofilament, fibre values",
    youngs_modulus_pa=13e9,
    poisson_ratio=0.39,
    tensile_strength_pa=650e6,
    friction_coefficient=0.2,
    basis="fibre (medium tenacity), axial",
    sources={
        "youngs_modulus_pa": _MORTON_HEARLE + ": 10.6 N/tex = 14.6 GPa; " + _TEIJIN + ": 12.7 GPa",
        "poisson_ratio": "bulk PET value (Granta/CES): no fibre value published",
        "tensile_strength_pa": _MORTON_HEARLE + ": 0.47 N/tex medium tenacity = 0.65 GPa",
        "friction_coefficient": "as for bulk PET: low confidence",
    },
)

ARAMID = Material(
    id="aramid",
    name="Aramid (Kevlar 29 / Twaron), fibre values",
    youngs_modulus_pa=73e9,
    poisson_ratio=0.36,
    tensile_strength_pa=2.9e9,
    friction_coefficient=0.22,
    basis="fibre, axial (transverse modulus is only about 1.3 GPa)",
    sources={
        "youngs_modulus_pa": _TEIJIN + ": PPTA regular 7470 kg/mm² = 73 GPa",
        "poisson_ratio": (
            "unconfirmed: 0.34 for Kevlar 49/epoxy (Zweben 1989); fibre values vary widely"
        ),
        "tensile_strength_pa": _TEIJIN + ": 300 kg/mm² = 2.9 GPa",
        "friction_coefficient": (
            "Brown, I. A. & Burgoyne, C. J. (1999) Wear 236:315-327, Kevlar 49 on Kevlar 49,"
            " 0.22 at high contact pressure"
        ),
    },
)

#: Presets by id, in the order the page offers them.
MATERIALS: dict[str, Material] = {m.id: m for m in (NYLON, PET_BULK, PET_FIBRE, ARAMID)}
