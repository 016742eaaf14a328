r"""Braid limits: minimum braid angle, jamming, lengths and contractile range (eqs 8-9).

The braid dilates until neighbouring strands press against each other. With :math:`N`
strands of diameter :math:`D_s` on a braid of theoretical diameter :math:`D_o` that
happens at the minimum braid angle :math:`\theta_{min}` (eq 8); by symmetry the braid also
jams at :math:`90° - \theta_{min}`.

References
----------
.. [1] S. Davis and D. G. Caldwell, "Braid Effects on Contractile Range and Friction
   Modeling in Pneumatic Muscle Actuators", Int. J. Robotics Research 25(4), 359-369,
   2006. :doi:`10.1177/0278364906063227`
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import numpy.typing as npt

from pma_core import _validation as check
from pma_core._validation import FloatArray, Floats
from pma_core.geometry import NEUTRAL_BRAID_ANGLE_RAD, theoretical_diameter


def strand_fill_ratio(
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
) -> Floats:
    r"""Fraction of the 90° circumference the strands fill side by side.

    .. math:: \phi = \frac{D_s N}{\pi D_o}

    This is :math:`\sin 2\theta_{min}` (eq 8). At :math:`\phi \ge 1` no braid exists.

    Parameters
    ----------
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].
    strand_count : array_like
        :math:`N`, total number of strands in the braid [-], at least 2.
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`\phi` [-].

    Raises
    ------
    ValueError
        If a parameter is not positive or the strands cannot fit (:math:`\phi \ge 1`).

    References
    ----------
    Davis & Caldwell 2006, eq 8. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(strand_fill_ratio(0.25e-3, 240, 0.031)), 3)
    0.616
    >>> strand_fill_ratio(0.25e-3, 240, 0.010)
    Traceback (most recent call last):
    ...
    ValueError: strand_count: 240 strands of 0.25 mm cannot fit around a 10 mm braid: ...
    """
    d_s = check.positive("strand_diameter_m", strand_diameter_m)
    n = check.at_least("strand_count", strand_count, 2, "a braid needs strands in both helices")
    d_o = check.positive("theoretical_diameter_m", theoretical_diameter_m)
    ratio = d_s * n / (np.pi * d_o)
    _require_fit(ratio, d_s, n, d_o)
    return check.scalar_or_array(ratio)


def _require_fit(ratio: FloatArray, d_s: FloatArray, n: FloatArray, d_o: FloatArray) -> None:
    jammed = ratio >= 1.0
    if not check.any_true(jammed):
        return
    i = np.unravel_index(int(np.argmax(jammed)), jammed.shape)
    n_i, d_s_i, d_o_i = np.broadcast_arrays(n, d_s, d_o)
    count, d_s_mm, d_o_mm = n_i[i], d_s_i[i] * 1e3, d_o_i[i] * 1e3
    raise ValueError(
        f"strand_count: {count:g} strands of {d_s_mm:g} mm cannot fit around a {d_o_mm:g} mm"
        f" braid: side by side they need {count * d_s_mm:.3g} mm of circumference and a"
        f" {d_o_mm:g} mm braid has {np.pi * d_o_mm:.3g} mm (N·D_s must be less than π·D_o)"
    )


def max_strand_count(
    strand_diameter_m: npt.ArrayLike, theoretical_diameter_m: npt.ArrayLike
) -> Floats:
    r"""Largest number of strands that fit around the braid side by side.

    .. math:: N_{max} = \max\{N \in \mathbb{Z} : D_s N < \pi D_o\}

    the limit of eq 8, where :math:`\theta_{min}` reaches 45° and the braid cannot move.

    Parameters
    ----------
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`N_{max}` [-], a whole number.

    References
    ----------
    Davis & Caldwell 2006, eq 8. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> int(max_strand_count(0.25e-3, 0.031))
    389
    """
    d_s = check.positive("strand_diameter_m", strand_diameter_m)
    d_o = check.positive("theoretical_diameter_m", theoretical_diameter_m)
    return check.scalar_or_array(np.ceil(np.pi * d_o / d_s) - 1.0)


def min_braid_angle(
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
) -> Floats:
    r"""Minimum braid angle at full dilation, where neighbouring strands touch.

    .. math:: \theta_{min} = \frac{1}{2}\sin^{-1}\left(\frac{D_s N}{\pi D_o}\right) \qquad (8)

    Parameters
    ----------
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].
    strand_count : array_like
        :math:`N`, total number of strands in the braid [-].
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`\theta_{min}` [rad].

    Notes
    -----
    Independent of the number of parallel strands :math:`S` and of the actuator length.
    Assumes the bladder is small enough not to stop the braid dilating (paper §2). Defined
    for :math:`D_s N < \pi D_o`; beyond, the strands do not fit and a ValueError is raised.

    References
    ----------
    Davis & Caldwell 2006, eq 8 and Table 1. :doi:`10.1177/0278364906063227`

    Examples
    --------
    Table 1 of the paper (D_o = 31 mm, D_s = 0.25 mm), N = 240, 160, 120:

    >>> np.degrees(min_braid_angle(0.25e-3, np.array([240, 160, 120]), 0.031)).round(1)
    array([19. , 12.1,  9. ])
    """
    ratio = strand_fill_ratio(strand_diameter_m, strand_count, theoretical_diameter_m)
    return check.scalar_or_array(0.5 * np.arcsin(ratio))


def jamming_angle(
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
) -> Floats:
    r"""Braid angle at which the braid locks on contraction, :math:`90° - \theta_{min}`.

    .. math:: \theta_{jam} = \frac{\pi}{2} - \theta_{min}

    By the symmetry of eq 8 (:math:`\sin 2\theta` takes the same value at both angles) the
    strands touch again at this angle.

    Parameters
    ----------
    strand_diameter_m, strand_count, theoretical_diameter_m : array_like
        :math:`D_s` [m], :math:`N` [-], :math:`D_o` [m] as in :func:`min_braid_angle`.

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`\theta_{jam}` [rad].

    References
    ----------
    Davis & Caldwell 2006, eq 8. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(np.degrees(jamming_angle(0.25e-3, 240, 0.031))), 1)
    71.0
    """
    theta_min = min_braid_angle(strand_diameter_m, strand_count, theoretical_diameter_m)
    return check.scalar_or_array(np.pi / 2 - np.asarray(theta_min))


def max_braid_angle(
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
) -> Floats:
    r"""Largest reachable braid angle: the neutral angle unless the braid jams first.

    .. math:: \theta_{max} = \min\left(\theta_n,\ \frac{\pi}{2} - \theta_{min}\right),
        \qquad \theta_n = \cos^{-1}(1/\sqrt{3}) = 54.7356°

    Parameters
    ----------
    strand_diameter_m, strand_count, theoretical_diameter_m : array_like
        :math:`D_s` [m], :math:`N` [-], :math:`D_o` [m] as in :func:`min_braid_angle`.

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`\theta_{max}` [rad].

    Notes
    -----
    The braid jams before the neutral angle when :math:`\theta_{min} > 35.26°`, i.e. when the
    strands fill more than :math:`\sin 70.53° = 94.3\,\%` of the circumference.

    References
    ----------
    Davis & Caldwell 2006, §2 and eq 8; Schulte 1962 for :math:`\theta_n`.
    :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(np.degrees(max_braid_angle(0.25e-3, 240, 0.031))), 4)
    54.7356
    """
    theta_jam = jamming_angle(strand_diameter_m, strand_count, theoretical_diameter_m)
    return check.scalar_or_array(np.minimum(NEUTRAL_BRAID_ANGLE_RAD, theta_jam))


def max_contraction(
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
) -> Floats:
    r"""Maximum contraction, as a fraction of the fully dilated length.

    .. math:: \varepsilon_{max} = 1 - \frac{\cos\theta_{max}}{\cos\theta_{min}}

    from :math:`L_{max} = b\cos\theta_{min}` (eq 9) and :math:`L_{min} = b\cos\theta_{max}`.

    Parameters
    ----------
    strand_diameter_m, strand_count, theoretical_diameter_m : array_like
        :math:`D_s` [m], :math:`N` [-], :math:`D_o` [m] as in :func:`min_braid_angle`.

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`\varepsilon_{max}` [-].

    Notes
    -----
    The paper's "about 7 % more contractile range" for N = 240 → 120 is the relative change
    of this quantity: 0.3893 → 0.4155, +6.7 %.

    References
    ----------
    Davis & Caldwell 2006, eq 9 and §2.1. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> eps = max_contraction(0.25e-3, np.array([240, 120]), 0.031)
    >>> eps.round(4), round(float(eps[1] / eps[0] - 1), 3)
    (array([0.3893, 0.4155]), 0.067)
    """
    theta_min = np.asarray(min_braid_angle(strand_diameter_m, strand_count, theoretical_diameter_m))
    theta_max = np.minimum(NEUTRAL_BRAID_ANGLE_RAD, np.pi / 2 - theta_min)
    return check.scalar_or_array(1.0 - np.cos(theta_max) / np.cos(theta_min))


def max_length(
    strand_length_m: npt.ArrayLike,
    turns: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
) -> Floats:
    r"""Maximum (fully dilated) actuator length.

    .. math:: L_{max} = b\cos\theta_{min}
        = b\cos\left[\frac{1}{2}\sin^{-1}\left(\frac{D_s N}{\pi D_o}\right)\right] \qquad (9)

    Parameters
    ----------
    strand_length_m : array_like
        :math:`b`, length of one braid strand [m].
    turns : array_like
        :math:`n`, turns of one strand around the actuator [-]; :math:`D_o = b/(n\pi)`.
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].
    strand_count : array_like
        :math:`N`, total number of strands [-].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`L_{max}` [m].

    References
    ----------
    Davis & Caldwell 2006, eq 9. :doi:`10.1177/0278364906063227`

    Examples
    --------
    The paper's test muscle (b = 0.65 m, n = 4.7, D_s = 0.25 mm, N = 240):

    >>> round(float(max_length(0.65, 4.7, 0.25e-3, 240)), 4)
    0.6337
    """
    d_o = theoretical_diameter(strand_length_m, turns)
    theta_min = min_braid_angle(strand_diameter_m, strand_count, d_o)
    return check.scalar_or_array(np.asarray(strand_length_m) * np.cos(theta_min))


def min_length(
    strand_length_m: npt.ArrayLike,
    turns: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
) -> Floats:
    r"""Minimum (fully contracted) actuator length.

    .. math:: L_{min} = b\cos\theta_{max} \qquad (19)

    with :math:`\theta_{max}` from :func:`max_braid_angle`.

    Parameters
    ----------
    strand_length_m, turns, strand_diameter_m, strand_count : array_like
        :math:`b` [m], :math:`n` [-], :math:`D_s` [m], :math:`N` [-] as in :func:`max_length`.

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`L_{min}` [m].

    References
    ----------
    Davis & Caldwell 2006, eq 19 and §2. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(min_length(0.65, 4.7, 0.25e-3, 240)), 4)
    0.3753
    """
    d_o = theoretical_diameter(strand_length_m, turns)
    theta_max = max_braid_angle(strand_diameter_m, strand_count, d_o)
    return check.scalar_or_array(np.asarray(strand_length_m) * np.cos(theta_max))


def stroke(
    strand_length_m: npt.ArrayLike,
    turns: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
) -> Floats:
    r"""Stroke: the difference between the maximum and minimum actuator lengths.

    .. math:: \Delta L = b\,(\cos\theta_{min} - \cos\theta_{max})

    Parameters
    ----------
    strand_length_m, turns, strand_diameter_m, strand_count : array_like
        :math:`b` [m], :math:`n` [-], :math:`D_s` [m], :math:`N` [-] as in :func:`max_length`.

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`\Delta L` [m].

    References
    ----------
    Davis & Caldwell 2006, eqs 9 and 19. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(stroke(0.65, 4.7, 0.25e-3, 240)) * 1e3, 1)
    258.4
    """
    args = (strand_length_m, turns, strand_diameter_m, strand_count)
    return check.scalar_or_array(np.asarray(max_length(*args)) - np.asarray(min_length(*args)))


@dataclass(frozen=True)
class BraidLimits:
    """The angle range and contractile range of one braid (eqs 8-9), SI units and radians.

    Lengths are None when the strand length is not given.
    """

    min_braid_angle_rad: Floats
    jamming_angle_rad: Floats
    max_braid_angle_rad: Floats
    max_contraction: Floats
    max_length_m: Floats | None = None
    min_length_m: Floats | None = None
    stroke_m: Floats | None = None


def braid_limits(
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
    strand_length_m: npt.ArrayLike | None = None,
) -> BraidLimits:
    r"""Every limit of one braid at once: :math:`\theta_{min}` computed and checked once.

    .. math:: \theta_{min} = \frac{1}{2}\sin^{-1}\frac{D_s N}{\pi D_o} \quad (8), \qquad
        \theta_{max} = \min(\theta_n, 90° - \theta_{min}), \qquad
        L = b\cos\theta \quad (9, 19)

    Parameters
    ----------
    strand_diameter_m, strand_count, theoretical_diameter_m : array_like
        :math:`D_s` [m], :math:`N` [-], :math:`D_o` [m] as in :func:`min_braid_angle`.
    strand_length_m : array_like, optional
        :math:`b` [m]; gives the lengths and the stroke.

    Returns
    -------
    BraidLimits

    References
    ----------
    Davis & Caldwell 2006, eqs 8, 9 and 19. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> limits = braid_limits(0.25e-3, 120, 0.031)
    >>> theta_min = round(float(np.degrees(limits.min_braid_angle_rad)), 1)
    >>> theta_min, round(float(limits.max_contraction), 4)
    (9.0, 0.4155)
    """
    theta_min = np.asarray(min_braid_angle(strand_diameter_m, strand_count, theoretical_diameter_m))
    theta_jam = np.pi / 2 - theta_min
    theta_max = np.minimum(NEUTRAL_BRAID_ANGLE_RAD, theta_jam)
    cos_min, cos_max = np.cos(theta_min), np.cos(theta_max)
    limits = BraidLimits(
        min_braid_angle_rad=check.scalar_or_array(theta_min),
        jamming_angle_rad=check.scalar_or_array(theta_jam),
        max_braid_angle_rad=check.scalar_or_array(theta_max),
        max_contraction=check.scalar_or_array(1.0 - cos_max / cos_min),
    )
    if strand_length_m is None:
        return limits
    b = check.positive("strand_length_m", strand_length_m)
    return replace(
        limits,
        max_length_m=check.scalar_or_array(b * cos_min),
        min_length_m=check.scalar_or_array(b * cos_max),
        stroke_m=check.scalar_or_array(b * (cos_min - cos_max)),
    )


def check_reachable_angle(
    braid_angle_rad: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    strand_count: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
) -> FloatArray:
    r"""Return the braid angle after checking it lies in :math:`[\theta_{min}, 90° - \theta_{min}]`.

    Outside that range the strands would overlap: the braid cannot take that angle.

    Examples
    --------
    >>> check_reachable_angle(np.radians(10.0), 0.25e-3, 240, 0.031)
    Traceback (most recent call last):
    ...
    ValueError: braid_angle_deg: 10° is outside the reachable range 19.02° to 70.98° ...
    """
    theta = check.as_floats("braid_angle_rad", braid_angle_rad)
    theta_min = np.asarray(min_braid_angle(strand_diameter_m, strand_count, theoretical_diameter_m))
    # A relative tolerance so that θ_min itself, round-tripped through degrees, is reachable.
    slack = 1e-9 * np.maximum(theta_min, 1.0)
    bad = (theta < theta_min - slack) | (theta > np.pi / 2 - theta_min + slack)
    if check.any_true(bad):
        i = np.unravel_index(int(np.argmax(bad)), bad.shape)
        theta_b, low_b = np.broadcast_arrays(theta, theta_min)
        low = np.degrees(low_b[i])
        raise ValueError(
            f"braid_angle_deg: {np.degrees(theta_b[i]):.4g}° is outside the reachable range"
            f" {low:.2f}° to {90 - low:.2f}° of this braid: below the minimum braid angle"
            " (eq 8) and above 90° minus it the strands would overlap"
        )
    return theta
