// chasles._core: the private gufuncs behind chasles.time_scaling and
// chasles.joint_trajectory (python/chasles/_trajectory.py): the time
// scalings of include/chasles/time_scaling.hpp (cubic, quintic and
// trapezoidal; Modern Robotics ch. 9.2) and the straight-line joint
// trajectory they time. The Python functions check the arguments (the
// kind, times that are not NaN, durations finite and > 0, ratios in (1, 2],
// finite joint vectors of one length, shapes that broadcast) and make them
// float64; each kernel calls the header on one element:
//
//   _time_scaling      (),(),(),()->(),(),()              kind, duration, ratio, t -> s, s_dot, s_ddot
//   _joint_trajectory  (n),(n),(),(),(),()->(n),(n),(n)   q_start, q_end, kind, duration, ratio, t -> q, qd, qdd
//
// `kind` is an int, the index of chasles::TimeScalingKind (0 cubic, 1
// quintic, 2 trapezoidal), picked once per run of equal kinds
// (ufunc::cases; another int gives NaN); the ratio (the peak velocity over
// the average one) is read by the trapezoid only. n <= 32, the bound of a
// Chain's joints (NaN results beyond; the Python function refuses more).
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include <chasles/time_scaling.hpp>

#include "bindings.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

using ufunc::Core;
using ufunc::def_ufunc;
using ufunc::Typed;
using Kind = Typed<Core<>, int>;

/// The joints of a joint vector: at most a Chain's kMaxJoints.
using Joints = Core<ufunc::upto<kMaxJoints>>;

/// The time scaling of kind C (an index of chasles::TimeScalingKind) at t.
template <int C>
chasles::TimeScaling<double> scaling_of(std::integral_constant<int, C>, double duration, double ratio,
                                        double t) noexcept {
  return chasles::time_scaling(static_cast<chasles::TimeScalingKind>(C), duration, t, ratio);
}

/// The end of the docstrings: the operands, for the public function `name`.
std::string operands_of(const std::string& name) {
  return R"(

Operands: kind, an int (0 cubic, 1 quintic, 2 trapezoidal; NaN results for
another); duration, float64 (finite and > 0, else NaN results); ratio,
float64 (the trapezoid's peak velocity over the average one, in (1, 2],
else NaN results; read by the trapezoid only); t, float64 (the time; at rest
outside [0, duration], NaN results for NaN). A private numpy generalized
ufunc behind chasles.)" +
         name + R"( (python/chasles/_trajectory.py), which checks the
arguments: numpy's rules for broadcasting, out= and axes= apply.)";
}

}  // namespace

void bind_trajectory(py::module_& m) {
  def_ufunc<std::tuple<Core<>, Core<>, Core<>>(Kind, Core<>, Core<>, Core<>), ufunc::Float64>(
      m, "_time_scaling", "kind, duration, ratio, t",
      "The path parameter s(t) in [0, 1] of a rest-to-rest motion of the duration, and its time derivatives "
      "s_dot and s_ddot (chasles::time_scaling)." +
          operands_of("time_scaling"),
      ufunc::cases<3, 0>([](auto kind, int, double duration, double ratio, double t) noexcept {
        const chasles::TimeScaling<double> s = scaling_of(kind, duration, ratio, t);
        return std::make_tuple(s.s, s.s_dot, s.s_ddot);
      }));
  def_ufunc<std::tuple<Joints, Joints, Joints>(Joints, Joints, Kind, Core<>, Core<>, Core<>), ufunc::Float64>(
      m, "_joint_trajectory", "q_start, q_end, kind, duration, ratio, t",
      "The straight-line joint trajectory from q_start to q_end timed by a time scaling: q = q_start + s d, "
      "qd = s_dot d, qdd = s_ddot d, d = q_end - q_start (chasles::joint_trajectory), for joint vectors "
      "q_start, q_end of n <= 32 joints (NaN results beyond)." +
          operands_of("joint_trajectory"),
      ufunc::cases<3, 2>(
          [](auto kind, const auto& q_start, const auto& q_end, int, double duration, double ratio, double t) noexcept {
            auto point = chasles::joint_trajectory(q_start, q_end, scaling_of(kind, duration, ratio, t));
            return std::make_tuple(std::move(point.q), std::move(point.qd), std::move(point.qdd));
          }));
}

}  // namespace chasles_py
