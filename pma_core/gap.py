r"""Braid gaps: node spacing, clear gap width and gap area (eqs 11-15).

Between crossing strands the braid leaves rhombic gaps. Fewer strands open them up, and a
large enough gap lets the inner bladder push through and rupture (paper §2.2).

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
from pma_core._validation import Floats
from pma_core.braid import check_reachable_angle

#: Braid angle of the largest gap, 45° [rad] (eq 15).
MAX_GAP_BRAID_ANGLE_RAD: float = float(np.pi / 4)


def node_spacing(
    theoretical_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    parallel_strands: npt.ArrayLike,
    braid_angle_rad: npt.ArrayLike,
) -> Floats:
    r"""Circumferential distance between strand crossover points (nodes).

    .. math:: G = \frac{2 S \pi D_o \sin\theta}{N} \qquad (12)

    Parameters
    ----------
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].
    strand_count : array_like
        :math:`N`, total number of strands [-].
    parallel_strands : array_like
        :math:`S`, parallel strands following each path [-], at least 1.
    braid_angle_rad : array_like
        :math:`\theta`, braid angle [rad].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`G` [m].

    References
    ----------
    Davis & Caldwell 2006, eqs 11-12. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(node_spacing(0.031, 240, 3, np.pi / 4)) * 1e3, 3)
    1.722
    """
    d_o = check.positive("theoretical_diameter_m", theoretical_diameter_m)
    n = check.at_least("strand_count", strand_count, 2, "a braid needs strands in both helices")
    s = check.at_least("parallel_strands", parallel_strands, 1, "each path has a strand")
    theta = check.as_floats("braid_angle_rad", braid_angle_rad)
    return check.scalar_or_array(2.0 * s * np.pi * d_o * np.sin(theta) / n)


def gap_width(
    theoretical_diameter_m: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    parallel_strands: npt.ArrayLike,
    braid_angle_rad: npt.ArrayLike,
) -> Floats:
    r"""Clear circumferential width of the gap between neighbouring strand bands.

    .. math:: Z = \frac{2 S \pi D_o \sin\theta}{N} - \frac{D_s S}{\cos\theta} \qquad (14)

    clipped at 0 where the strands touch.

    Parameters
    ----------
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].
    strand_count : array_like
        :math:`N`, total number of strands [-].
    parallel_strands : array_like
        :math:`S`, parallel strands following each path [-].
    braid_angle_rad : array_like
        :math:`\theta`, braid angle [rad], in :math:`[\theta_{min}, 90° - \theta_{min}]`.

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`Z` [m]; 0 at :math:`\theta_{min}` and :math:`90° - \theta_{min}`.

    References
    ----------
    Davis & Caldwell 2006, eqs 13-14. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(gap_width(0.031, 0.25e-3, 240, 3, np.pi / 4)) * 1e3, 3)
    0.661
    """
    theta = check_reachable_angle(
        braid_angle_rad, strand_diameter_m, strand_count, theoretical_diameter_m
    )
    g = node_spacing(theoretical_diameter_m, strand_count, parallel_strands, theta)
    band = np.asarray(parallel_strands) * np.asarray(strand_diameter_m) / np.cos(theta)
    return check.scalar_or_array(np.maximum(np.asarray(g) - band, 0.0))


def gap_area(
    theoretical_diameter_m: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    parallel_strands: npt.ArrayLike,
    braid_angle_rad: npt.ArrayLike,
) -> Floats:
    r"""Area of one rhombic braid gap at braid angle :math:`\theta`.

    .. math:: A_{gap} = \frac{Z^2}{2\tan\theta}

    The rhombus has circumferential diagonal :math:`Z` (eq 14) and sides along the strands;
    at 45° this is the paper's :math:`Z^2/2` (eq 15), its maximum over :math:`\theta`.

    Parameters
    ----------
    theoretical_diameter_m, strand_diameter_m, strand_count, parallel_strands,
    braid_angle_rad : array_like
        :math:`D_o` [m], :math:`D_s` [m], :math:`N` [-], :math:`S` [-], :math:`\theta` [rad]
        as in :func:`gap_width`.

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`A_{gap}` [m²].

    References
    ----------
    Davis & Caldwell 2006, eqs 13-15. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(gap_area(0.031, 0.25e-3, 240, 3, np.radians(30.0))) * 1e6, 3)
    0.107
    """
    z = gap_width(
        theoretical_diameter_m, strand_diameter_m, strand_count, parallel_strands, braid_angle_rad
    )
    theta = np.asarray(braid_angle_rad, dtype=np.float64)
    return check.scalar_or_array(np.asarray(z) ** 2 / (2.0 * np.tan(theta)))


def max_gap_area(
    theoretical_diameter_m: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    parallel_strands: npt.ArrayLike,
) -> Floats:
    r"""Largest braid gap area, reached at a braid angle of 45°.

    .. math:: A_{max} = \frac{1}{2}\left(\frac{2 S \pi D_o \sin 45°}{N}
        - \frac{D_s S}{\cos 45°}\right)^2 \qquad (15)

    Parameters
    ----------
    theoretical_diameter_m, strand_diameter_m, strand_count, parallel_strands : array_like
        :math:`D_o` [m], :math:`D_s` [m], :math:`N` [-], :math:`S` [-] as in :func:`gap_width`.

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`A_{max}` [m²].

    Notes
    -----
    45° is reachable whenever the braid exists (:math:`\theta_{min} < 45°`).

    References
    ----------
    Davis & Caldwell 2006, eq 15 and §2.2. :doi:`10.1177/0278364906063227`

    Examples
    --------
    The paper's braid (D_o = 31 mm, D_s = 0.25 mm, S = 3), N = 240 and 120:

    >>> (max_gap_area(0.031, 0.25e-3, np.array([240, 120]), 3) * 1e6).round(2)
    array([0.22, 2.84])
    """
    return gap_area(
        theoretical_diameter_m,
        strand_diameter_m,
        strand_count,
        parallel_strands,
        MAX_GAP_BRAID_ANGLE_RAD,
    )
