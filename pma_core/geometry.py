"""Braid kinematics: diameter, length, braid angle and contraction (eqs 1, 18, 19).

A braided muscle is a cylinder wound by strands of length :math:`b` that turn :math:`n`
times around it. At braid angle :math:`\\theta` (between a strand and the axis) the
cylinder has diameter :math:`D_o\\sin\\theta` and length :math:`b\\cos\\theta`.

References
----------
.. [1] S. Davis and D. G. Caldwell, "Braid Effects on Contractile Range and Friction
   Modeling in Pneumatic Muscle Actuators", Int. J. Robotics Research 25(4), 359-369,
   2006. :doi:`10.1177/0278364906063227`
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from pma_core import _validation as check
from pma_core._validation import FloatArray, Floats

#: Neutral braid angle :math:`\\arccos(1/\\sqrt{3})` = 54.7356° [rad], where the static
#: force vanishes: the fully contracted state (Schulte 1962).
NEUTRAL_BRAID_ANGLE_RAD: float = float(np.arccos(1.0 / np.sqrt(3.0)))


def theoretical_diameter(strand_length_m: npt.ArrayLike, turns: npt.ArrayLike) -> Floats:
    """Braid diameter at a 90° braid angle, :math:`D_o`.

    .. math:: D_o = \\frac{b}{n \\pi} \\qquad (1)

    Parameters
    ----------
    strand_length_m : array_like
        :math:`b`, length of one braid strand [m].
    turns : array_like
        :math:`n`, turns one strand makes around the actuator [-].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`D_o` [m].

    Notes
    -----
    Valid for any b > 0, n > 0.

    References
    ----------
    Davis & Caldwell 2006, eq 1. :doi:`10.1177/0278364906063227`

    Examples
    --------
    The paper's hysteresis test muscle, b = 0.65 m and n = 4.7:

    >>> round(float(theoretical_diameter(0.65, 4.7)) * 1e3, 2)
    44.02
    """
    b = check.positive("strand_length_m", strand_length_m)
    n = check.positive("turns", turns)
    return check.scalar_or_array(b / (n * np.pi))


def turns(strand_length_m: npt.ArrayLike, theoretical_diameter_m: npt.ArrayLike) -> Floats:
    """Turns of one strand around the actuator, eq 1 solved for :math:`n`.

    .. math:: n = \\frac{b}{\\pi D_o} \\qquad (1)

    Parameters
    ----------
    strand_length_m : array_like
        :math:`b`, length of one braid strand [m].
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`n` [-].

    References
    ----------
    Davis & Caldwell 2006, eq 1. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(turns(0.65, 0.65 / (4.7 * 3.141592653589793))), 6)
    4.7
    """
    b = check.positive("strand_length_m", strand_length_m)
    d_o = check.positive("theoretical_diameter_m", theoretical_diameter_m)
    return check.scalar_or_array(b / (np.pi * d_o))


def strand_length(turns: npt.ArrayLike, theoretical_diameter_m: npt.ArrayLike) -> Floats:
    """Length of one braid strand, eq 1 solved for :math:`b`.

    .. math:: b = n \\pi D_o \\qquad (1)

    Parameters
    ----------
    turns : array_like
        :math:`n`, turns of one strand around the actuator [-].
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`b` [m].

    References
    ----------
    Davis & Caldwell 2006, eq 1. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(strand_length(4.7, 0.65 / (4.7 * 3.141592653589793))), 6)
    0.65
    """
    n = check.positive("turns", turns)
    d_o = check.positive("theoretical_diameter_m", theoretical_diameter_m)
    return check.scalar_or_array(n * np.pi * d_o)


def actuator_diameter(
    theoretical_diameter_m: npt.ArrayLike, braid_angle_rad: npt.ArrayLike
) -> Floats:
    """Actuator diameter at braid angle :math:`\\theta`.

    .. math:: D = D_o \\sin\\theta = \\frac{b \\sin\\theta}{n \\pi} \\qquad (18)

    Parameters
    ----------
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].
    braid_angle_rad : array_like
        :math:`\\theta`, braid angle [rad], in (0, π/2).

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`D` [m].

    References
    ----------
    Davis & Caldwell 2006, eq 18 (after Chou & Hannaford 1996).
    :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(actuator_diameter(0.031, np.radians(30.0))) * 1e3, 2)
    15.5
    """
    d_o = check.positive("theoretical_diameter_m", theoretical_diameter_m)
    theta = braid_angle(braid_angle_rad)
    return check.scalar_or_array(d_o * np.sin(theta))


def actuator_length(strand_length_m: npt.ArrayLike, braid_angle_rad: npt.ArrayLike) -> Floats:
    """Actuator length at braid angle :math:`\\theta`.

    .. math:: L = b \\cos\\theta \\qquad (19)

    Parameters
    ----------
    strand_length_m : array_like
        :math:`b`, length of one braid strand [m].
    braid_angle_rad : array_like
        :math:`\\theta`, braid angle [rad], in (0, π/2).

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`L` [m].

    References
    ----------
    Davis & Caldwell 2006, eq 19 (after Chou & Hannaford 1996).
    :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(actuator_length(0.65, np.radians(60.0))), 3)
    0.325
    """
    b = check.positive("strand_length_m", strand_length_m)
    theta = braid_angle(braid_angle_rad)
    return check.scalar_or_array(b * np.cos(theta))


def braid_angle_at_contraction(
    contraction: npt.ArrayLike, min_braid_angle_rad: npt.ArrayLike
) -> Floats:
    """Braid angle at a contraction :math:`\\varepsilon` from the fully dilated length.

    .. math:: \\theta = \\arccos\\left[(1 - \\varepsilon)\\cos\\theta_{min}\\right]

    from :math:`L = b\\cos\\theta` (eq 19) and :math:`\\varepsilon = 1 - L/L_{max}`.

    Parameters
    ----------
    contraction : array_like
        :math:`\\varepsilon`, contraction [-], in [0, 1).
    min_braid_angle_rad : array_like
        :math:`\\theta_{min}`, braid angle at full dilation [rad].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`\\theta` [rad].

    References
    ----------
    Davis & Caldwell 2006, eqs 9 and 19. :doi:`10.1177/0278364906063227`

    Examples
    --------
    At the paper's maximum contraction of 38.9 % (N = 240) the braid reaches 54.7°:

    >>> theta_min = np.radians(19.0153512699)
    >>> round(float(np.degrees(braid_angle_at_contraction(0.3893260549, theta_min))), 2)
    54.74
    """
    eps = check.within("contraction", contraction, 0.0, 1.0, "a fraction of the dilated length")
    theta_min = braid_angle(min_braid_angle_rad, "min_braid_angle_rad")
    return check.scalar_or_array(np.arccos(cos_braid_angle_kernel(eps, theta_min)))


def cos_braid_angle_kernel(
    contraction: FloatArray, min_braid_angle_rad: FloatArray | float
) -> FloatArray:
    r""":math:`\cos\theta = (1 - \varepsilon)\cos\theta_{min}`, unchecked: for validated inputs."""
    cos_theta = np.subtract(1.0, contraction)
    cos_theta *= np.cos(min_braid_angle_rad)
    return cos_theta


def braid_angle(value: npt.ArrayLike, name: str = "braid_angle_rad") -> npt.NDArray[np.float64]:
    """Return a braid angle as floats after checking it lies strictly in (0, π/2) [rad].

    Examples
    --------
    >>> braid_angle(0.0)
    Traceback (most recent call last):
    ...
    ValueError: braid_angle_rad must lie strictly between 0 and 90° ... got 0 rad
    """
    theta = check.as_floats(name, value)
    bad = (theta <= 0) | (theta >= np.pi / 2)
    if check.any_true(bad):
        raise ValueError(
            f"{name} must lie strictly between 0 and 90° (a braid angle between strand and"
            f" axis), got {theta[bad].flat[0]:g} rad"
        )
    return theta
