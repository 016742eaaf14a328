r"""Strand-on-strand friction: contact area, Hertz scaling and friction force (eqs 21-34).

The braid's crossing strands rub as the muscle moves. The flat-strand contact area
(eq 29) overestimates the real one; the paper replaces the fitted scale factor
:math:`S_{scale}` with the ratio of the flat contact radius to the Hertz contact radius of
two equal spheres pressed together (eqs 32-34).

References
----------
.. [1] S. Davis and D. G. Caldwell, "Braid Effects on Contractile Range and Friction
   Modeling in Pneumatic Muscle Actuators", Int. J. Robotics Research 25(4), 359-369,
   2006. :doi:`10.1177/0278364906063227`
.. [2] T. A. Stolarski, Tribology in Machine Design, Elsevier, 1999 (Hertz contact).
.. [3] B. Tondu and P. Lopez, "Modeling and control of McKibben artificial muscle robot
   actuators", IEEE Control Systems Magazine 20(2), 2000. :doi:`10.1109/37.833638`
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from pma_core import _validation as check
from pma_core._validation import FloatArray, Floats
from pma_core.geometry import braid_angle

#: Hertz coefficient of two equal spheres as the paper prints it (eq 33); the exact
#: value is :math:`(3/8)^{1/3} = 0.7211`.
HERTZ_COEFFICIENT: float = 0.721


def contact_area(
    strand_length_m: npt.ArrayLike,
    turns: npt.ArrayLike,
    min_braid_angle_rad: npt.ArrayLike,
    braid_angle_rad: npt.ArrayLike,
) -> Floats:
    r"""Total strand-on-strand contact area of the braid, assuming flat strands.

    .. math:: S_{contact} = \frac{b^2 \sin^2\theta_{min} \cos^2\theta_{min}}
        {n \sin\theta \cos\theta} \qquad (29)

    Parameters
    ----------
    strand_length_m : array_like
        :math:`b`, length of one braid strand [m].
    turns : array_like
        :math:`n`, turns of one strand around the actuator [-].
    min_braid_angle_rad : array_like
        :math:`\theta_{min}`, minimum braid angle [rad] (eq 8).
    braid_angle_rad : array_like
        :math:`\theta`, braid angle [rad].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`S_{contact}` [m²].

    Notes
    -----
    Assumes the braid surface is all crossover points at full dilation (eq 26), so the
    contact area equals the muscle's surface area there: :math:`\pi D L` at
    :math:`\theta_{min}`.

    References
    ----------
    Davis & Caldwell 2006, eqs 22-29. :doi:`10.1177/0278364906063227`

    Examples
    --------
    At :math:`\theta_{min}` it is the surface of the dilated paper test muscle:

    >>> theta_min = np.radians(19.0)
    >>> round(float(contact_area(0.65, 4.7, theta_min, theta_min)) * 1e4, 1)
    276.7
    """
    b = check.positive("strand_length_m", strand_length_m)
    n = check.positive("turns", turns)
    theta_min = braid_angle(min_braid_angle_rad, "min_braid_angle_rad")
    theta = braid_angle(braid_angle_rad)
    return check.scalar_or_array(
        contact_area_kernel(b, n, theta_min, np.sin(theta) * np.cos(theta))
    )


def contact_area_kernel(
    strand_length_m: FloatArray | float,
    turns: FloatArray | float,
    min_braid_angle_rad: FloatArray | float,
    sin_cos_theta: FloatArray,
) -> FloatArray:
    r"""Eq 29 from :math:`\sin\theta\cos\theta`, unchecked: for validated inputs."""
    dilated = np.square(strand_length_m * np.sin(min_braid_angle_rad) * np.cos(min_braid_angle_rad))
    return np.divide(dilated / turns, sin_cos_theta)


def compressive_force(pressure_pa: npt.ArrayLike, strand_diameter_m: npt.ArrayLike) -> Floats:
    r"""Force pressing two crossing strands together.

    .. math:: F_{comp} = P D_s^2 \qquad (33)

    Parameters
    ----------
    pressure_pa : array_like
        :math:`P`, gauge pressure [Pa].
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`F_{comp}` [N].

    References
    ----------
    Davis & Caldwell 2006, eq 33. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(compressive_force(200e3, 0.25e-3)), 4)
    0.0125
    """
    p = check.positive("pressure_pa", pressure_pa)
    d_s = check.positive("strand_diameter_m", strand_diameter_m)
    return check.scalar_or_array(p * d_s**2)


def flat_contact_radius(strand_diameter_m: npt.ArrayLike) -> Floats:
    r"""Contact radius of two flat strands, the numerator of eq 32.

    .. math:: a_c^{flat} = \frac{D_s}{2} \qquad (32)

    Parameters
    ----------
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`a_c^{flat}` [m].

    References
    ----------
    Davis & Caldwell 2006, eq 32. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> float(flat_contact_radius(0.25e-3))
    0.000125
    """
    return check.scalar_or_array(check.positive("strand_diameter_m", strand_diameter_m) / 2.0)


def hertz_contact_radius(
    pressure_pa: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    youngs_modulus_pa: npt.ArrayLike,
    poisson_ratio: npt.ArrayLike,
) -> Floats:
    r"""Hertz contact radius of two equal spheres of the strand's diameter.

    .. math:: a_c^{sphere} = 0.721\,(F_{comp} K_d C_e)^{1/3},\quad
        C_e = \frac{2(1-\nu^2)}{E},\quad K_d = \frac{D_s}{2},\quad F_{comp} = P D_s^2
        \qquad (33)

    Parameters
    ----------
    pressure_pa : array_like
        :math:`P`, gauge pressure [Pa], greater than 0.
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].
    youngs_modulus_pa : array_like
        :math:`E`, Young's modulus of the strand material [Pa].
    poisson_ratio : array_like
        :math:`\nu`, Poisson ratio of the strand material [-], in [0, 0.5).

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`a_c^{sphere}` [m].

    References
    ----------
    Davis & Caldwell 2006, eq 33; Stolarski 1999. :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(hertz_contact_radius(200e3, 0.25e-3, 3e9, 0.4)) * 1e6, 2)
    6.9
    """
    f_comp = np.asarray(compressive_force(pressure_pa, strand_diameter_m))
    e = check.positive("youngs_modulus_pa", youngs_modulus_pa)
    nu = check.within("poisson_ratio", poisson_ratio, 0.0, 0.5, "an isotropic solid")
    c_e = 2.0 * (1.0 - nu**2) / e
    k_d = np.asarray(strand_diameter_m) / 2.0
    return check.scalar_or_array(HERTZ_COEFFICIENT * np.cbrt(f_comp * k_d * c_e))


def s_scale(
    pressure_pa: npt.ArrayLike,
    strand_diameter_m: npt.ArrayLike,
    youngs_modulus_pa: npt.ArrayLike,
    poisson_ratio: npt.ArrayLike,
) -> Floats:
    r"""Contact-area scale factor: flat contact radius over Hertz contact radius.

    .. math:: S_{scale} = \frac{a_c^{flat}}{a_c^{sphere}}
        = \frac{D_s}{1.442\left(F_{comp} \frac{D_s}{2} C_e\right)^{1/3}} \qquad (32, 34)

    Parameters
    ----------
    pressure_pa : array_like
        :math:`P`, gauge pressure [Pa], greater than 0 (at 0 the strands do not press
        together and the factor is unbounded).
    strand_diameter_m : array_like
        :math:`D_s`, diameter of one strand [m].
    youngs_modulus_pa : array_like
        :math:`E`, Young's modulus of the strand material [Pa].
    poisson_ratio : array_like
        :math:`\nu`, Poisson ratio [-], in [0, 0.5).

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`S_{scale}` [-], falling as :math:`P^{-1/3}`.

    Notes
    -----
    The crossing-cylinder contact is approximated by two equal spheres (paper §3.4). The
    paper prints 18.1 (200 kPa), 15.8 (300 kPa) and 14.3 (400 kPa, where the formula gives
    14.39: the paper truncates).

    References
    ----------
    Davis & Caldwell 2006, eqs 32-34. :doi:`10.1177/0278364906063227`

    Examples
    --------
    Nylon (E = 3 GPa, ν = 0.4), D_s = 0.25 mm, at 200, 300 and 400 kPa:

    >>> s_scale(np.array([200e3, 300e3, 400e3]), 0.25e-3, 3e9, 0.4).round(2)
    array([18.13, 15.83, 14.39])
    """
    a_sphere = np.asarray(
        hertz_contact_radius(pressure_pa, strand_diameter_m, youngs_modulus_pa, poisson_ratio)
    )
    a_flat = np.asarray(flat_contact_radius(strand_diameter_m))
    return check.scalar_or_array(a_flat / a_sphere)


def friction_force(
    friction_coefficient: npt.ArrayLike,
    contact_area_m2: npt.ArrayLike,
    s_scale: npt.ArrayLike,
    pressure_pa: npt.ArrayLike,
) -> Floats:
    r"""Friction force between the braid strands.

    .. math:: F_{friction} = f_s \frac{S_{contact}}{S_{scale}} P \qquad (30)

    Parameters
    ----------
    friction_coefficient : array_like
        :math:`f_s`, strand-on-strand friction coefficient [-], at least 0.
    contact_area_m2 : array_like
        :math:`S_{contact}`, flat-strand contact area [m²] (eq 29).
    s_scale : array_like
        :math:`S_{scale}` [-] (eq 34, or a measured value), greater than 0.
    pressure_pa : array_like
        :math:`P`, gauge pressure [Pa].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`F_{friction}` [N].

    References
    ----------
    Davis & Caldwell 2006, eq 30; Tondu & Lopez 2000 (eq 21).
    :doi:`10.1177/0278364906063227`

    Examples
    --------
    >>> round(float(friction_force(0.2, 0.0269, 18.1, 200e3)), 1)
    59.4
    """
    f_s = check.at_least("friction_coefficient", friction_coefficient, 0.0, "a coefficient")
    area = check.at_least("contact_area_m2", contact_area_m2, 0.0, "an area")
    scale = check.positive("s_scale", s_scale)
    p = check.at_least("pressure_pa", pressure_pa, 0.0, "a gauge pressure that inflates")
    return check.scalar_or_array(friction_force_kernel(f_s, np.array(area), scale, p))


def friction_force_kernel(
    friction_coefficient: FloatArray | float,
    contact_area_m2: FloatArray,
    s_scale: FloatArray | float,
    pressure_pa: FloatArray | float,
) -> FloatArray:
    r"""Eq 30, unchecked and in place: ``contact_area_m2`` becomes the friction force."""
    contact_area_m2 *= friction_coefficient * pressure_pa / s_scale
    return contact_area_m2
