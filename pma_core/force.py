r"""Static actuator force, the basic model of Schulte (1962) (eq 10).

References
----------
.. [1] S. Davis and D. G. Caldwell, "Braid Effects on Contractile Range and Friction
   Modeling in Pneumatic Muscle Actuators", Int. J. Robotics Research 25(4), 359-369,
   2006. :doi:`10.1177/0278364906063227`
.. [2] R. A. Schulte, "The characteristics of the McKibben artificial muscle", The
   Application of External Power in Prosthetics and Orthotics, NAS-NRC Publ. 874, 1962.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from pma_core import _validation as check
from pma_core._validation import FloatArray, Floats
from pma_core.geometry import braid_angle


def static_force(
    pressure_pa: npt.ArrayLike,
    theoretical_diameter_m: npt.ArrayLike,
    braid_angle_rad: npt.ArrayLike,
) -> Floats:
    r"""Contractile force of an ideal braided muscle at braid angle :math:`\theta`.

    .. math:: F_{static} = \frac{\pi D_o^2 P}{4}\left(3\cos^2\theta - 1\right) \qquad (10)

    Parameters
    ----------
    pressure_pa : array_like
        :math:`P`, gauge pressure [Pa], at least 0.
    theoretical_diameter_m : array_like
        :math:`D_o`, braid diameter at 90° [m].
    braid_angle_rad : array_like
        :math:`\theta`, braid angle [rad].

    Returns
    -------
    numpy.float64 or numpy.ndarray
        :math:`F_{static}` [N], positive when pulling; 0 at the neutral angle 54.74°.

    Notes
    -----
    Thin-walled, frictionless, inextensible braid (Schulte 1962). Largest at the smallest
    braid angle, :math:`\theta_{min}`; Schulte's model is typically within 10-20 %.

    References
    ----------
    Davis & Caldwell 2006, eq 10; Schulte 1962. :doi:`10.1177/0278364906063227`

    Examples
    --------
    The paper's eq 10: the force at 10° is 16 % above the force at 20°:

    >>> f = static_force(200e3, 0.031, np.radians([10.0, 20.0]))
    >>> round(float(f[0] / f[1]), 2)
    1.16
    """
    p = check.at_least("pressure_pa", pressure_pa, 0.0, "a gauge pressure that inflates")
    d_o = check.positive("theoretical_diameter_m", theoretical_diameter_m)
    theta = braid_angle(braid_angle_rad)
    return check.scalar_or_array(static_force_kernel(p, d_o, np.cos(theta)))


def static_force_kernel(
    pressure_pa: FloatArray | float,
    theoretical_diameter_m: FloatArray | float,
    cos_theta: FloatArray,
) -> FloatArray:
    r"""Eq 10 from :math:`\cos\theta`, unchecked: for callers that validated their inputs."""
    scale = np.pi * np.square(theoretical_diameter_m) * pressure_pa / 4.0
    force = np.square(cos_theta)
    force *= 3.0
    force -= 1.0
    force *= scale
    return force
