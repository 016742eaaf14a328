r"""Braid strength: strand stress and the fewest strands that survive a pressure (eqs 16-20).

Each turn of a strand is a hoop carrying the pressure load (paper §2.3). Removing strands
raises the stress on the rest until the braid bursts.

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
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD, braid_angle

#: Braid angle of the largest strand stress, 45° [rad]: :math:`\cos\theta\sin\theta` peaks
#: there, and every actuator passes through it on its stroke.
WORST_CASE_BRAID_ANGLE_RAD: float = float(np.pi / 4)

# Slack before rounding a strand count up, so that 97.0000000001 (float noise on an exact
# 97) does not become 98: relative, but at most 1e-6 so that 1e15 stays 1e15.
_CEIL_SLACK = 1e-9


def strand_cross_section_area(strand_diameter_m: npt.ArrayLike) -> Floats:
    r"""Cross-sectional area of one round strand.

    .. math:: A_{strand} = \frac{\pi D_s^2}{4}

    Parameters
    ----------
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`A_{strand}` [m²].

    References
    ----------
    Davis & Caldwell 2006, eq 17. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(strand_cross_section_area(0.25e-3)) * 1e6, 5)
    0.04909
    """
    d_s = check.positive("strand_diameter_m", strand_diameter_m)
    return check.scalar_or_array(np.pi * d_s**2 / 4.0)


def strand_stress(
    pressure_pa: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    braid_angle_rad: npt.ArrayLike,
) -> Floats:
    r"""Tensile stress in each strand from the pressure's hoop load.

    .. math:: \sigma = \frac{P D L}{2 n N A_{strand}}
        = \frac{P \pi D_o^2 \cos\theta \sin\theta}{2 N A_{strand}} \qquad (17)

    using :math:`D = D_o\sin\theta` (eq 18), :math:`L = b\cos\theta` (eq 19) and
    :math:`b = n\pi D_o` (eq 1).

    Parameters
    ----------
    pressure_pa : array_like
        :math:`P`, gauge pressure [Pa].
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].
    strand_count : array_like
        :math:`N`, total number of strands [-].
    braid_angle_rad : array_like
        :math:`\theta`, braid angle [rad].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`\sigma` [Pa].

    Notes
    -----
    Largest at :math:`\theta = 45°`.

    References
    ----------
    Davis & Caldwell 2006, eqs 16-19. :doi:`10.1177/0278364906063227`

    Examples
    --------
    With 97 strands at 500 kPa and 54.7° the nylon braid is just below 75 MPa:

    >>> theta_n = np.arccos(1 / np.sqrt(3))
    >>> round(float(strand_stress(500e3, 0.031, 0.25e-3, 97, theta_n)) / 1e6, 1)
    74.7
    """
    n = check.at_least("strand_count", strand_count, 2, "a braid needs strands in both helices")
    load = _stress_times_strand_count(
        pressure_pa, theoretical_diameter_m, strand_diameter_m, braid_angle_rad
    )
    return check.scalar_or_array(load / n)


def _stress_times_strand_count(
    pressure_pa: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    braid_angle_rad: npt.ArrayLike,
) -> FloatArray:
    r""":math:`\sigma N = P \pi D_o^2 \cos\theta \sin\theta / (2 A_{strand})` [Pa], eq 17."""
    p = check.positive("pressure_pa", pressure_pa)
    d_o = check.positive("theoretical_diameter_m", theoretical_diameter_m)
    area = np.asarray(strand_cross_section_area(strand_diameter_m))
    theta = braid_angle(braid_angle_rad)
    return p * np.pi * d_o**2 * np.cos(theta) * np.sin(theta) / (2.0 * area)


def failure_strand_count(
    pressure_pa: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    tensile_strength_pa: npt.ArrayLike,
    braid_angle_rad: npt.ArrayLike = NEUTRAL_BRAID_ANGLE_RAD,
    safety_factor: npt.ArrayLike = 1.0,
) -> Floats:
    r"""Number of strands at which the strand stress reaches the allowed stress.

    .. math:: N = \frac{P D_o^2 \pi \cos\theta \sin\theta}{2 \sigma A_{strand}},
        \qquad \sigma = \sigma_u / k \qquad (20)

    A braid with fewer strands than this fails. The result is a real number; see
    :func:`min_strand_count` for the whole number of strands to build with.

    Parameters
    ----------
    pressure_pa : array_like
        :math:`P`, gauge pressure [Pa].
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].
    tensile_strength_pa : array_like
        :math:`\sigma_u`, tensile strength of the strand material [Pa].
    braid_angle_rad : array_like, optional
        :math:`\theta` [rad]. Default the neutral angle 54.74°, the fully contracted state
        the paper uses; :data:`WORST_CASE_BRAID_ANGLE_RAD` (45°) gives the largest count.
    safety_factor : array_like, optional
        :math:`k` [-], at least 1, dividing :math:`\sigma_u`. Default 1.

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`N` [-], proportional to :math:`P`.

    References
    ----------
    Davis & Caldwell 2006, eq 20 and §2.3. :doi:`10.1177/0278364906063227`

    Examples
    --------
    The paper's nylon braid at 500 kPa (σ_u = 75 MPa): 96.6 strands, so 97; 102.5 at 45°:

    >>> round(float(failure_strand_count(500e3, 0.031, 0.25e-3, 75e6)), 2)
    96.64
    >>> round(float(failure_strand_count(500e3, 0.031, 0.25e-3, 75e6, np.pi / 4)), 2)
    102.51
    """
    sigma_u = check.positive("tensile_strength_pa", tensile_strength_pa)
    k = check.at_least("safety_factor", safety_factor, 1.0, "it divides the tensile strength")
    load = _stress_times_strand_count(
        pressure_pa, theoretical_diameter_m, strand_diameter_m, braid_angle_rad
    )
    return check.scalar_or_array(load * k / sigma_u)


def min_strand_count(exact_strand_count: npt.ArrayLike) -> Floats:
    r"""Smallest whole number of strands that does not fail: the ceiling of eq 20.

    Parameters
    ----------
    exact_strand_count : array_like
        Real strand count from :func:`failure_strand_count` [-].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`\lceil N \rceil` [-], a whole number.

    References
    ----------
    Davis & Caldwell 2006, eq 20 ("the minimum number of braid strands ... is 97").
    :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> min_strand_count(np.array([96.644, 102.507, 97.0 + 1e-12]))
    array([ 97., 103.,  97.])
    """
    exact = check.as_floats("exact_strand_count", exact_strand_count)
    return check.scalar_or_array(np.ceil(exact - np.minimum(exact * _CEIL_SLACK, 1e-6)))
