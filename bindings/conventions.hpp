// chasles._core: the conventions paragraph every class docstring carries,
// in the words of include/chasles/chasles.hpp and README.md.
#pragma once

namespace chasles_py {

/// Appended to each class docstring (Google style "Conventions:" section).
inline constexpr const char* kConventions = R"doc(
Conventions (the same in C++, in README.md and in every docstring):
    - twists xi = (v, w), linear part first (Murray, Li and Sastry); the
      Modern Robotics order (w, v) only through Twist.to_modern_robotics /
      Twist.from_modern_robotics;
    - wrenches F = (f, tau), force first, so power is the dot product V . F;
    - g_ab maps frame b to frame a: q_a = g_ab q_b, g_ac = g_ab @ g_bc;
      twists change frame by Ad_g = [[R, [p]R], [0, R]], wrenches by Ad_g^-T;
    - hat(w) = [w] with [w] p = w x p; [xi] = [[ [w], v ], [0, 0]];
    - quaternions are (x, y, z, w), scalar last, as in scipy; pass
      scalar_first=True for (w, x, y, z); angles are in radians.

Numbers may be given as lists, tuples or arrays of any real dtype (bool,
integers and floats are converted to float64), in any memory layout; a wrong
shape is a ValueError naming the expected and the given shape, a value that
is not real (complex, object, str, None) a TypeError. Constructors refuse NaN
and infinities (ValueError); functions that return the numbers given,
rearranged (hat, SO3.vee, SE3.vee, actions on points), carry a NaN through,
and the defects are inf for a matrix that is not finite.

Values are float64 and immutable. ``==`` is the exact equality of the stored
numbers, compared as floats (-0.0 == 0.0; a NaN is unequal to everything,
itself included), ``!=`` its negation, and objects are unhashable; compare
within a tolerance with ``is_approx(other, tol)``. Objects pickle and copy
bit-exactly, and ``np.asarray(x)`` gives their matrix or vector.
)doc";

}  // namespace chasles_py
