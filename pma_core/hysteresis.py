r"""Force-contraction hysteresis from strand friction (eq 31).

The muscle pulls less while contracting and resists more while being stretched: friction
between the braid strands opposes the motion either way (Chou & Hannaford 1996; Tondu &
Lopez 2000), with the friction force of eq 30.

References
----------
.. [1] S. Davis and D. G. Caldwell, "Braid Effects on Contractile Range and Friction
   Modeling in Pneumatic Muscle Actuators", Int. J. Robotics Research 25(4), 359-369,
   2006. :doi:`10.1177/0278364906063227`
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from pma_core import _validation as check
from pma_core._validation import FloatArray, Floats
from pma_core.braid import max_braid_angle, min_braid_angle
from pma_core.force import static_force_kernel
from pma_core.friction import contact_area_kernel, friction_force_kernel
from pma_core.friction import s_scale as hertz_s_scale
from pma_core.geometry import cos_braid_angle_kernel, theoretical_diameter


def friction_branches(
    force_static_n: npt.ArrayLike, friction_force_n: npt.ArrayLike
) -> tuple[Floats, Floats]:
    r"""Contracting and extending forces either side of the static force.

    .. math:: F_{SF} = F_{static} \mp F_{friction} \qquad (31)

    minus while the muscle contracts, plus while it dilates (is stretched). A braided
    muscle only pulls, so the contracting branch is clipped at 0.

    Parameters
    ----------
    force_static_n : array_like
        :math:`F_{static}` [N] (eq 10).
    friction_force_n : array_like
        :math:`F_{friction}` [N] (eq 30), at least 0.

    Returns
    -------
    contracting, extending : numpy.float64 or numpy.ndarray
        :math:`F_{SF}` on each branch [N].

    References
    ----------
    Davis & Caldwell 2006, eq 31; Tondu & Lopez 2000. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> friction_branches(np.array([100.0, 10.0]), 20.0)
    (array([80.,  0.]), array([120.,  30.]))
    """
    static = check.as_floats("force_static_n", force_static_n)
    friction = check.at_least("friction_force_n", friction_force_n, 0.0, "it opposes motion")
    contracting, extending = _branches(static, friction)
    return check.scalar_or_array(contracting), check.scalar_or_array(extending)


def _branches(static: FloatArray, friction: FloatArray) -> tuple[FloatArray, FloatArray]:
    # asarray: for 0-d input numpy returns a scalar, and ``out=`` needs an array.
    contracting = np.asarray(np.subtract(static, friction))
    np.maximum(contracting, 0.0, out=contracting)
    return contracting, np.add(static, friction)


@dataclass(frozen=True)
class HysteresisCurves:
    """Static force and both friction branches along the stroke (eqs 10, 29-31).

    Arrays run from full dilation (contraction 0) to full contraction, evenly spaced in
    contraction. Forces in newtons, lengths in metres, angles in radians.
    """

    s_scale: float
    min_braid_angle_rad: float
    max_braid_angle_rad: float
    braid_angle_rad: FloatArray
    length_m: FloatArray
    contraction: FloatArray
    force_static_n: FloatArray
    friction_force_n: FloatArray
    force_contracting_n: FloatArray
    force_extending_n: FloatArray


def hysteresis_curves(
    strand_length_m: float,
    turns: float,
    strand_diameter_m: float,
    strand_count: float,
    pressure_pa: float,
    friction_coefficient: float,
    youngs_modulus_pa: float,
    poisson_ratio: float,
    s_scale: float | None = None,
    points: int = 201,
) -> HysteresisCurves:
    r"""Force against contraction with friction hysteresis, for one actuator design.

    For contraction :math:`\varepsilon` from 0 to :math:`\varepsilon_{max}`:
    :math:`\cos\theta = (1-\varepsilon)\cos\theta_{min}`, :math:`L = b\cos\theta` (eq 19),
    :math:`F_{static}` (eq 10), :math:`S_{contact}` (eq 29), :math:`F_{friction}` (eq 30)
    and the branches :math:`F_{static} \mp F_{friction}` (eq 31).

    Parameters
    ----------
    strand_length_m : float
        :math:`b`, length of one braid strand [m].
    turns : float
        :math:`n`, turns of one strand around the actuator [-].
    strand_diameter_m : float
        :math:`D_s`, diameter of one strand [m].
    strand_count : float
        :math:`N`, total number of strands [-].
    pressure_pa : float
        :math:`P`, gauge pressure [Pa], greater than 0.
    friction_coefficient : float
        :math:`f_s`, strand-on-strand friction coefficient [-].
    youngs_modulus_pa, poisson_ratio : float
        :math:`E` [Pa] and :math:`\nu` [-] of the strand material, for eq 34.
    s_scale : float, optional
        Measured :math:`S_{scale}` [-]; default: eq 34.
    points : int, optional
        Number of points along the stroke, at least 2. Default 201.

    Returns
    -------
    HysteresisCurves

    Notes
    -----
    Basic Schulte static model (eq 10), not the paper's stretch-corrected model of
    Davis et al. 2003, so forces are upper estimates (Schulte: within 10-20 %).

    References
    ----------
    Davis & Caldwell 2006, eqs 10, 29-31 and §3.3. :doi:`10.1177/0278364906063227`

    Examples
    --------
    The paper's test muscle at 200 kPa; S_scale from eq 34 is the paper's 18.1:

    >>> c = hysteresis_curves(0.65, 4.7, 0.25e-3, 240, 200e3, 0.2, 3e9, 0.4, points=5)
    >>> round(c.s_scale, 1), c.contraction.round(3)
    (18.1, array([0.   , 0.102, 0.204, 0.306, 0.408]))
    >>> c.force_static_n.round(0), c.force_contracting_n.round(0)
    (array([564., 396., 246., 114.,   0.]), array([521., 374., 227.,  95.,   0.]))
    """
    if points < 2:
        raise ValueError(f"points must be at least 2 (a curve has two ends), got {points}")
    d_o = float(theoretical_diameter(strand_length_m, turns))
    theta_min = float(min_braid_angle(strand_diameter_m, strand_count, d_o))
    theta_max = float(max_braid_angle(strand_diameter_m, strand_count, d_o))
    scale = _scale(s_scale, pressure_pa, strand_diameter_m, youngs_modulus_pa, poisson_ratio)
    f_s = float(check.at_least("friction_coefficient", friction_coefficient, 0.0, "a coefficient"))

    eps_max = 1.0 - np.cos(theta_max) / np.cos(theta_min)
    contraction = np.linspace(0.0, eps_max, points)
    # In place where it is safe: at 10^6 points each temporary is 8 MB to allocate and fill.
    cos_theta = cos_braid_angle_kernel(contraction, theta_min)
    static = static_force_kernel(pressure_pa, d_o, cos_theta)
    sin_cos = np.square(cos_theta)
    np.subtract(1.0, sin_cos, out=sin_cos)
    np.sqrt(sin_cos, out=sin_cos)
    sin_cos *= cos_theta
    area = contact_area_kernel(strand_length_m, turns, theta_min, sin_cos)
    friction = friction_force_kernel(f_s, area, scale, pressure_pa)
    contracting, extending = _branches(static, friction)
    length = np.multiply(cos_theta, strand_length_m)
    return HysteresisCurves(
        s_scale=scale,
        min_braid_angle_rad=theta_min,
        max_braid_angle_rad=theta_max,
        braid_angle_rad=np.arccos(cos_theta, out=cos_theta),
        length_m=length,
        contraction=contraction,
        force_static_n=static,
        friction_force_n=friction,
        force_contracting_n=contracting,
        force_extending_n=extending,
    )


def _scale(measured: float | None, pressure_pa: float, d_s: float, e: float, nu: float) -> float:
    computed = float(hertz_s_scale(pressure_pa, d_s, e, nu))
    if measured is None:
        return computed
    return float(check.positive("s_scale", measured))
