// chasles: Lie groups of rigid-body motion. The umbrella header.
//
// Conventions (the same words in README.md and in the Python docstrings):
// - twists xi = (v, w), linear part first (Murray, Li and Sastry);
// - wrenches F = (f, tau), force first, so power is the dot product V . F;
// - g_ab maps frame b to frame a; twists change frame by Ad_g = [[R, [p]R], [0, R]],
//   wrenches by Ad_g^-T;
// - quaternions are Eigen::Quaternion; angles are in radians.
#pragma once

#include "chasles/align.hpp"
#include "chasles/bspline.hpp"
#include "chasles/constants.hpp"
#include "chasles/distance.hpp"
#include "chasles/dynamics.hpp"
#include "chasles/dynamics_derivatives.hpp"
#include "chasles/euler.hpp"
#include "chasles/gaussian.hpp"
#include "chasles/inverse_kinematics.hpp"
#include "chasles/io.hpp"
#include "chasles/jacobians.hpp"
#include "chasles/kinematics.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/mean.hpp"
#include "chasles/random.hpp"
#include "chasles/screw.hpp"
#include "chasles/se2.hpp"
#include "chasles/se23.hpp"
#include "chasles/se3.hpp"
#include "chasles/sim3.hpp"
#include "chasles/so2.hpp"
#include "chasles/so3.hpp"
#include "chasles/spatial_inertia.hpp"
#include "chasles/spline.hpp"
#include "chasles/time_scaling.hpp"
#include "chasles/twist.hpp"
#include "chasles/wrench.hpp"
