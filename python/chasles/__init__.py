"""chasles: Lie groups of rigid-body motion, SO(3) and SE(3) (and the plane's
SO(2) and SE(2), the similarities Sim(3) and the extended poses SE_2(3)),
with twists, wrenches and screws, over the C++ headers of the same name.

Two layers over the same C++ kernels:

- objects for one element: ``SO3``, ``SE3``, ``SO2``, ``SE2``, ``Sim3``, ``SE23``, ``Twist``, ``Wrench``,
  ``Screw`` and ``SpatialInertia`` (a rigid body's inertia), with ``@``
  for composition and action (``g @ h``, ``g @ p``);
- array functions for batches: ``so3_exp``, ``se3_log``, ``se3_compose``,
  ... (and the methods of ``Chain``).

The array functions are numpy generalized ufuncs over the C++ kernels, each
with a core signature, ``so3_exp`` ``(3)->(3,3)``, ``se3_compose``
``(4,4),(4,4)->(4,4)``, ``se3_act`` ``(4,4),(3)->(3)``, so numpy's own rules
apply, as for ``np.matmul``: the batch axes broadcast, numpy picks the
float32 or the float64 loop by safe casting, ``out=`` and ``axes=`` work,
and the GIL is released (``set_num_threads(n)`` splits a large batch across
threads, with bit-identical results). docs/python.md states these rules in
full. A dask array passed directly is a ValueError (dask infers the result
dtype by calling the function on arrays of size 1, which a fixed core size
refuses): ``dask.array.apply_gufunc(f, f.signature, x, output_dtypes=...)``
maps an array function over the chunks, lazily.

``so3_from_quat`` and ``so3_as_quat`` take ``scalar_first``, which a ufunc
cannot: they are Python functions that pick one of two ufuncs and pass the
other keywords on. So are ``so3_from_euler`` / ``so3_as_euler`` (an Euler
sequence such as ``"xyz"`` or ``"ZYX"``, ``degrees=``) and ``so3_from_rpy`` /
``so3_as_rpy`` (URDF's roll, pitch, yaw).

Conventions (the same in C++, in README.md and in every docstring):

- twists xi = (v, w), linear part first (Murray, Li and Sastry); the Modern
  Robotics order (w, v) only through ``Twist.to_modern_robotics`` /
  ``Twist.from_modern_robotics``;
- wrenches F = (f, tau), force first, so power is the dot product V . F;
- g_ab maps frame b to frame a; twists change frame by
  Ad_g = [[R, [p]R], [0, R]], wrenches by Ad_g^-T;
- quaternions are (x, y, z, w), scalar last, as in scipy
  (``scalar_first=True`` for (w, x, y, z)); angles are in radians.

Example:
    >>> import numpy as np
    >>> import chasles
    >>> g = chasles.SE3.from_screw([0.0, 2.0, 0.0], [0.0, 0.0, 1.0], 0.0, np.pi / 2)
    >>> np.round(g @ [0.0, 2.0, 5.0], 12) + 0.0
    array([0., 2., 5.])

``chasles.plot`` draws frames, trajectories and screws with matplotlib (an
optional dependency: ``pip install chasles[plot]``; ``import chasles`` does
not import it). ``python -m chasles`` runs a demo: the worked screw-motion
example of the documentation and the screw of a random rigid motion, printed,
checked and drawn into a PNG.
"""

from chasles import _threads
from chasles._align import se3_align, sim3_align, so3_align
from chasles._arrays import (
    so3_as_euler,
    so3_as_quat,
    so3_as_rpy,
    so3_from_euler,
    so3_from_quat,
    so3_from_rpy,
)
from chasles._bspline import SE2BSpline, SE3BSpline, SE23BSpline, Sim3BSpline, SO2BSpline, SO3BSpline
from chasles._chain import Chain
from chasles._core import (
    SE2,
    SE3,
    SE23,
    SO2,
    SO3,
    Screw,
    Sim3,
    SpatialInertia,
    Twist,
    Wrench,
    __version__,
    act_jacobians,
    between,
    between_jacobians,
    compose_jacobians,
    get_num_threads,
    interpolate,
    interpolate_jacobian_t,
    inverse_jacobian,
    lminus,
    lminus_jacobians,
    log_jacobian,
    lplus,
    lplus_jacobians,
    rminus,
    rminus_jacobians,
    rplus,
    rplus_jacobians,
    se2_act,
    se2_compose,
    se2_distance,
    se2_exp,
    se2_hat,
    se2_interpolate,
    se2_inverse,
    se2_log,
    se2_normalize,
    se2_vee,
    se3_act,
    se3_act_jacobian,
    se3_act_twist,
    se3_act_wrench,
    se3_adjoint,
    se3_compose,
    se3_distance,
    se3_exp,
    se3_hat,
    se3_interpolate,
    se3_inverse,
    se3_log,
    se3_normalize,
    se3_vee,
    se23_act,
    se23_compose,
    se23_distance,
    se23_exp,
    se23_hat,
    se23_interpolate,
    se23_inverse,
    se23_log,
    se23_normalize,
    se23_vee,
    sim3_act,
    sim3_compose,
    sim3_distance,
    sim3_exp,
    sim3_hat,
    sim3_interpolate,
    sim3_inverse,
    sim3_log,
    sim3_normalize,
    sim3_vee,
    so2_act,
    so2_compose,
    so2_distance,
    so2_exp,
    so2_hat,
    so2_interpolate,
    so2_inverse,
    so2_log,
    so2_normalize,
    so2_vee,
    so3_act,
    so3_act_jacobian,
    so3_angle,
    so3_compose,
    so3_distance,
    so3_exp,
    so3_from_uniforms,
    so3_hat,
    so3_interpolate,
    so3_inverse,
    so3_log,
    so3_normalize,
    so3_vee,
)
from chasles._mean import se2_mean, se3_mean, se23_mean, sim3_mean, so2_mean, so3_mean
from chasles._random import (
    se2_gaussian,
    se2_random,
    se3_gaussian,
    se3_random,
    se23_gaussian,
    se23_random,
    sim3_gaussian,
    sim3_random,
    so2_gaussian,
    so2_random,
    so3_gaussian,
    so3_random,
)
from chasles._spline import SE2Spline, SE3Spline, SE23Spline, Sim3Spline, SO2Spline, SO3Spline
from chasles._threads import set_num_threads

__all__ = [
    "SE2",
    "SE3",
    "SE23",
    "SO2",
    "SO3",
    "Chain",
    "SE2BSpline",
    "SE2Spline",
    "SE3BSpline",
    "SE3Spline",
    "SE23BSpline",
    "SE23Spline",
    "SO2BSpline",
    "SO2Spline",
    "SO3BSpline",
    "SO3Spline",
    "Screw",
    "Sim3",
    "Sim3BSpline",
    "Sim3Spline",
    "SpatialInertia",
    "Twist",
    "Wrench",
    "__version__",
    "act_jacobians",
    "between",
    "between_jacobians",
    "compose_jacobians",
    "get_num_threads",
    "interpolate",
    "interpolate_jacobian_t",
    "inverse_jacobian",
    "lminus",
    "lminus_jacobians",
    "log_jacobian",
    "lplus",
    "lplus_jacobians",
    "rminus",
    "rminus_jacobians",
    "rplus",
    "rplus_jacobians",
    "se2_act",
    "se2_compose",
    "se2_distance",
    "se2_exp",
    "se2_gaussian",
    "se2_hat",
    "se2_interpolate",
    "se2_inverse",
    "se2_log",
    "se2_mean",
    "se2_normalize",
    "se2_random",
    "se2_vee",
    "se3_act",
    "se3_act_jacobian",
    "se3_act_twist",
    "se3_act_wrench",
    "se3_adjoint",
    "se3_align",
    "se3_compose",
    "se3_distance",
    "se3_exp",
    "se3_gaussian",
    "se3_hat",
    "se3_interpolate",
    "se3_inverse",
    "se3_log",
    "se3_mean",
    "se3_normalize",
    "se3_random",
    "se3_vee",
    "se23_act",
    "se23_compose",
    "se23_distance",
    "se23_exp",
    "se23_gaussian",
    "se23_hat",
    "se23_interpolate",
    "se23_inverse",
    "se23_log",
    "se23_mean",
    "se23_normalize",
    "se23_random",
    "se23_vee",
    "set_num_threads",
    "sim3_act",
    "sim3_align",
    "sim3_compose",
    "sim3_distance",
    "sim3_exp",
    "sim3_gaussian",
    "sim3_hat",
    "sim3_interpolate",
    "sim3_inverse",
    "sim3_log",
    "sim3_mean",
    "sim3_normalize",
    "sim3_random",
    "sim3_vee",
    "so2_act",
    "so2_compose",
    "so2_distance",
    "so2_exp",
    "so2_gaussian",
    "so2_hat",
    "so2_interpolate",
    "so2_inverse",
    "so2_log",
    "so2_mean",
    "so2_normalize",
    "so2_random",
    "so2_vee",
    "so3_act",
    "so3_act_jacobian",
    "so3_align",
    "so3_angle",
    "so3_as_euler",
    "so3_as_quat",
    "so3_as_rpy",
    "so3_compose",
    "so3_distance",
    "so3_exp",
    "so3_from_euler",
    "so3_from_quat",
    "so3_from_rpy",
    "so3_from_uniforms",
    "so3_gaussian",
    "so3_hat",
    "so3_interpolate",
    "so3_inverse",
    "so3_log",
    "so3_mean",
    "so3_normalize",
    "so3_random",
    "so3_vee",
]

_threads._read_environment()
