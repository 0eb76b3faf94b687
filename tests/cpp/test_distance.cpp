// SO3::angle and the distances of distance.hpp against the long double
// reference (support/reference.hpp: Mercator series near 0, Horn's
// eigenvector elsewhere), near 0, near pi and at pi, and their invariances.
//
// The distances written once over the groups (DistanceOfEveryGroup, over
// SO2, SE2, SO3, SE3, Sim3 and both scalars): each part against a long
// double reference computed from the group's own accessors (the angle of
// R_a^-1 R_b from its quaternion or its (cos, sin), the Euclidean distance
// of the translations, |log(s_b / s_a)|), symmetric, zero at equality,
// bi-invariant for the rotation groups and invariant under a rigid change
// of the fixed frame for the others (a change of scale scales Sim(3)'s
// translation distance and nothing else).
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/distance.hpp>
#include <chasles/se2.hpp>
#include <chasles/se3.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so2.hpp>
#include <chasles/so3.hpp>

#include "support/all_groups.hpp"
#include "support/reference.hpp"
#include "support/scalar_types.hpp"

namespace {

using chasles::SE3;
using chasles::SO3;
using chasles_ref::ld;

template <typename T>
class Distance : public ::testing::Test {};
using chasles_test::ScalarName;
using chasles_test::ScalarTypes;
TYPED_TEST_SUITE(Distance, ScalarTypes, ScalarName);

/// A unit axis, fixed per index: not a coordinate axis, so that every entry
/// of R carries the angle.
chasles_ref::V3 axis(int i) {
  const chasles_ref::V3 a(ld(0.3) + ld(i) * ld(0.1), ld(-0.7), ld(0.2) * ld(i % 3) + ld(0.5));
  return a / a.norm();
}

/// The angles of the accuracy test: 0, tiny, small, generic, near pi, pi.
/// 1e-160 and 1e-30 are below the cutoff tiny_norm2 on |u_v|^2 in double and in
/// float, 1e-12 and 1e-7 above it.
const ld kAngles[] = {0.0L,
                      1e-160L,
                      1e-30L,
                      1e-12L,
                      1e-7L,
                      1e-4L,
                      0.05L,
                      0.3L,
                      1.0L,
                      2.0L,
                      3.0L,
                      chasles_ref::kPi - 1e-3L,
                      chasles_ref::kPi - 1e-6L,
                      chasles_ref::kPi - 1e-9L,
                      chasles_ref::kPi};

TYPED_TEST(Distance, AngleMatchesTheLongDoubleReferenceNearZeroAndNearPi) {
  using S = TypeParam;
  const ld eps = std::numeric_limits<S>::epsilon();
  int n = 0;
  for (const ld theta : kAngles) {
    for (int i = 0; i < 4; ++i, ++n) {
      // Round the long double rotation to S; the reference is the angle of
      // the rounded matrix, in long double, by formulas chasles does not use.
      const chasles_ref::M3 exact = chasles_ref::exp3(theta * axis(i));
      const Eigen::Matrix<S, 3, 3> M = exact.cast<S>();
      const ld reference = chasles_ref::scaled_norm(chasles_ref::log3(M.template cast<ld>()));
      const S got = SO3<S>::from_matrix_unchecked(M).angle();
      // Relative accuracy near 0 (an absolute bound would accept 0 for 1e-30),
      // a few ulps of pi elsewhere.
      const ld bound = 4 * eps * (reference < 1 ? reference : chasles_ref::kPi);
      EXPECT_LE(std::fabs(ld(got) - reference), bound) << "theta " << double(theta) << " axis " << i;
      EXPECT_GE(got, S(0));
      EXPECT_LE(got, S(3.14159265358979323846));
    }
  }
  EXPECT_EQ(n, 4 * int(sizeof(kAngles) / sizeof(kAngles[0])));
}

TYPED_TEST(Distance, AcosOfTheTraceWouldFailTheSameBound) {
  // The test above can fail: acos((tr R - 1) / 2) loses half the digits at
  // 1e-4 and near pi, and is off by far more than its bound there.
  using S = TypeParam;
  const ld eps = std::numeric_limits<S>::epsilon();
  const ld theta = sizeof(S) == 4 ? 1e-2L : 1e-6L;
  const Eigen::Matrix<S, 3, 3> M = chasles_ref::exp3(theta * axis(1)).cast<S>();
  const ld reference = chasles_ref::scaled_norm(chasles_ref::log3(M.template cast<ld>()));
  using std::acos;
  const S c = (M.trace() - S(1)) / S(2);
  const S naive = acos(c < S(1) ? c : S(1));
  EXPECT_GT(std::fabs(ld(naive) - reference), 4 * eps * reference);
  EXPECT_LE(std::fabs(ld(SO3<S>::from_matrix_unchecked(M).angle()) - reference), 4 * eps * reference);
}

TYPED_TEST(Distance, AngleIsExactlyZeroAtTheIdentityAndPiAtAHalfTurn) {
  using S = TypeParam;
  EXPECT_EQ(SO3<S>::identity().angle(), S(0));
  Eigen::Matrix<S, 3, 3> half_turn = Eigen::Matrix<S, 3, 3>::Identity();
  half_turn(1, 1) = half_turn(2, 2) = S(-1);  // pi about x, exactly
  EXPECT_EQ(SO3<S>::from_matrix_unchecked(half_turn).angle(), S(3.14159265358979323846));
}

TYPED_TEST(Distance, AngleOfAMatrixOffSO3IsTheAngleOfItsNearestRotationToFirstOrder) {
  using S = TypeParam;
  const S d = sizeof(S) == 4 ? S(1e-3) : S(1e-6);
  const SO3<S> R = SO3<S>::exp(Eigen::Matrix<S, 3, 1>(S(0.4), S(-1.1), S(0.7)));
  const Eigen::Matrix<S, 3, 3> E = (Eigen::Matrix<S, 3, 3>() << 1, -2, 0.5, 0.3, 1, -1, 2, 0.1, -0.4).finished();
  const Eigen::Matrix<S, 3, 3> M = R.matrix() + d * E;
  const S projected = SO3<S>::from_matrix_projected(M).angle();
  const S off = SO3<S>::from_matrix_unchecked(M).angle();
  EXPECT_LE(std::fabs(off - projected), S(10) * d * d + S(16) * std::numeric_limits<S>::epsilon());
}

TYPED_TEST(Distance, RotationDistanceIsTheAngleOfTheRelativeRotationAndBiInvariant) {
  using S = TypeParam;
  using V3 = Eigen::Matrix<S, 3, 1>;
  const S tol = S(64) * std::numeric_limits<S>::epsilon();
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<S> u(S(-2), S(2));
  for (int k = 0; k < 200; ++k) {
    const SO3<S> a = SO3<S>::exp(V3(u(rng), u(rng), u(rng)));
    const SO3<S> b = SO3<S>::exp(V3(u(rng), u(rng), u(rng)));
    const SO3<S> g = SO3<S>::exp(V3(u(rng), u(rng), u(rng)));
    const S d = chasles::distance(a, b);
    // The reference: the long double angle of the relative rotation.
    const chasles_ref::M3 rel = a.matrix().template cast<ld>().transpose() * b.matrix().template cast<ld>();
    EXPECT_NEAR(double(d), double(chasles_ref::scaled_norm(chasles_ref::log3(rel))), double(tol));
    EXPECT_NEAR(d, chasles::distance(b, a), tol);
    EXPECT_NEAR(d, chasles::distance(g * a, g * b), tol);
    EXPECT_NEAR(d, chasles::distance(a * g, b * g), tol);
  }
  EXPECT_EQ(chasles::distance(SO3<S>::identity(), SO3<S>::identity()), S(0));
}

TYPED_TEST(Distance, PoseDistanceIsTheRotationAngleAndTheDistanceOfTheOrigins) {
  using S = TypeParam;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using V6 = Eigen::Matrix<S, 6, 1>;
  const S tol = S(64) * std::numeric_limits<S>::epsilon();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<S> u(S(-2), S(2));
  for (int k = 0; k < 200; ++k) {
    V6 x, y, z;
    for (int i = 0; i < 6; ++i) {
      x[i] = u(rng);
      y[i] = u(rng);
      z[i] = u(rng);
    }
    const SE3<S> a = SE3<S>::exp(x), b = SE3<S>::exp(y), g = SE3<S>::exp(z);
    const chasles::SE3Distance<S> d = chasles::distance(a, b);
    EXPECT_EQ(d.angle, chasles::distance(a.rotation(), b.rotation()));
    const V3 diff = b.translation() - a.translation();
    EXPECT_NEAR(d.translation, std::sqrt(diff[0] * diff[0] + diff[1] * diff[1] + diff[2] * diff[2]), tol);
    // |p_b - p_a| is the length of the translation of a^-1 b ...
    EXPECT_NEAR(d.translation, (a.inverse() * b).translation().norm(), S(4) * tol);
    // ... and both parts are invariant under a change of the fixed frame.
    const chasles::SE3Distance<S> dg = chasles::distance(g * a, g * b);
    EXPECT_NEAR(dg.angle, d.angle, tol);
    EXPECT_NEAR(dg.translation, d.translation, S(8) * tol);
  }
}

TEST(DistanceAutodiff, AngleHasTheRightDerivativeAndAFiniteOneAtTheIdentity) {
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  using V3 = Eigen::Matrix<AD, 3, 1>;
  const Eigen::Vector3d n = Eigen::Vector3d(0.2, -0.6, 0.3).normalized();
  for (const double t : {0.7, 2.5}) {
    const AD s(t, 1, 0);  // d/ds angle(exp(s n)) = 1 for 0 < s < pi
    const AD a = SO3<AD>::exp(V3(s * n[0], s * n[1], s * n[2])).angle();
    EXPECT_NEAR(a.value(), t, 1e-14);
    EXPECT_NEAR(a.derivatives()[0], 1.0, 1e-12);
  }
  const AD zero(0.0, 1, 0);
  const AD a0 = SO3<AD>::exp(V3(zero * n[0], zero * n[1], zero * n[2])).angle();
  EXPECT_EQ(a0.value(), 0.0);
  EXPECT_TRUE(std::isfinite(a0.derivatives()[0]));
}

// ---- every group ------------------------------------------------------------

template <typename G>
class DistanceOfEveryGroup : public ::testing::Test {};
TYPED_TEST_SUITE(DistanceOfEveryGroup, chasles_test::AllGroups, chasles_test::AllGroupsName);

/// The angle of R_a^-1 R_b in long double: |atan2| of the complex quotient (SO2), 2 atan2(|q_v|, |q_w|) (SO3).
template <typename S>
ld reference_angle(const chasles::SO2<S>& a, const chasles::SO2<S>& b) {
  const ld ca = a.complex()[0], sa = a.complex()[1], cb = b.complex()[0], sb = b.complex()[1];
  return std::fabs(std::atan2(ca * sb - sa * cb, ca * cb + sa * sb));
}
template <typename S>
ld reference_angle(const SO3<S>& a, const SO3<S>& b) {
  const Eigen::Matrix<ld, 3, 3> M = a.matrix().template cast<ld>().transpose() * b.matrix().template cast<ld>();
  const Eigen::Quaternion<ld> q(M);
  return 2 * std::atan2(q.vec().norm(), std::fabs(q.w()));
}

/// The reference distances, part by part, from the group's accessors.
template <typename G>
std::vector<ld> reference_distance(const G& a, const G& b) {
  using S = typename G::Scalar;
  if constexpr (std::is_same<G, chasles::SO2<S>>::value || std::is_same<G, SO3<S>>::value) {
    return {reference_angle(a, b)};
  } else {
    std::vector<ld> d{reference_angle(a.rotation(), b.rotation()),
                      (b.translation().template cast<ld>() - a.translation().template cast<ld>()).norm()};
    if constexpr (std::is_same<G, chasles::Sim3<S>>::value)
      d.push_back(std::fabs(std::log(ld(b.scale())) - std::log(ld(a.scale()))));
    if constexpr (std::is_same<G, chasles::SE23<S>>::value)
      d.push_back((b.velocity().template cast<ld>() - a.velocity().template cast<ld>()).norm());
    return d;
  }
}

/// The library's distance as a vector, whatever its type.
template <typename S>
std::vector<ld> as_vector(const S& d) {
  return {ld(d)};
}
template <typename S>
std::vector<ld> as_vector(const chasles::SE3Distance<S>& d) {
  return {ld(d.angle), ld(d.translation)};
}
template <typename S, int N>
std::vector<ld> as_vector(const Eigen::Matrix<S, N, 1>& d) {
  std::vector<ld> out;
  for (int i = 0; i < N; ++i) out.push_back(ld(d[i]));
  return out;
}

template <typename G>
std::vector<ld> library_distance(const G& a, const G& b) {
  return as_vector(chasles::distance(a, b));
}

TYPED_TEST(DistanceOfEveryGroup, EachPartMatchesTheLongDoubleReference) {
  using G = TypeParam;
  using S = typename G::Scalar;
  const ld eps = std::numeric_limits<S>::epsilon();
  std::mt19937_64 gen(41);
  for (int trial = 0; trial < 200; ++trial) {
    const double spread = trial % 3 == 0 ? 1e-3 : (trial % 3 == 1 ? 0.5 : 1.5);
    const G a = G::exp(chasles_test::normal_tangent<G>(gen, 1.5));
    const G b = a * G::exp(chasles_test::normal_tangent<G>(gen, spread));
    const std::vector<ld> d = library_distance(a, b), ref = reference_distance(a, b);
    ASSERT_EQ(d.size(), ref.size());
    for (std::size_t k = 0; k < d.size(); ++k)
      EXPECT_NEAR(double(d[k]), double(ref[k]), double(32 * eps * std::max(ld(1), ref[k]))) << trial << " part " << k;
    const std::vector<ld> back = library_distance(b, a);  // symmetric, to rounding
    for (std::size_t k = 0; k < d.size(); ++k)
      EXPECT_NEAR(double(back[k]), double(d[k]), double(8 * eps * std::max(ld(1), d[k]))) << trial << " part " << k;
    for (const ld x : library_distance(a, a)) EXPECT_LE(x, 8 * eps);
  }
}

TYPED_TEST(DistanceOfEveryGroup, IsInvariantUnderAChangeOfTheFixedFrame) {
  using G = TypeParam;
  using S = typename G::Scalar;
  constexpr bool rotation_group = std::is_same<G, chasles::SO2<S>>::value || std::is_same<G, SO3<S>>::value;
  const ld eps = std::numeric_limits<S>::epsilon();
  std::mt19937_64 gen(42);
  for (int trial = 0; trial < 100; ++trial) {
    const G a = G::exp(chasles_test::normal_tangent<G>(gen, 1.0)),
            b = G::exp(chasles_test::normal_tangent<G>(gen, 1.0));
    typename G::Tangent x = chasles_test::normal_tangent<G>(gen, 1.0);
    if constexpr (std::is_same<G, chasles::Sim3<S>>::value) x[6] = S(0);  // a rigid g
    const G g = G::exp(x);
    const std::vector<ld> d = library_distance(a, b), left = library_distance(G(g * a), G(g * b));
    const ld scale = 1 + std::max(ld(g.matrix().template cast<ld>().cwiseAbs().maxCoeff()),
                                  ld(a.matrix().template cast<ld>().cwiseAbs().maxCoeff()));
    for (std::size_t k = 0; k < d.size(); ++k)
      EXPECT_NEAR(double(left[k]), double(d[k]), double(64 * eps * scale)) << k;
    if constexpr (rotation_group) {  // bi-invariant
      EXPECT_NEAR(double(library_distance(G(a * g), G(b * g))[0]), double(d[0]), double(64 * eps));
    }
    if constexpr (std::is_same<G, chasles::Sim3<S>>::value) {
      // A change of scale c: the angle and |log(s_b / s_a)| are kept, the translation distance scales by c.
      const S c = S(2.5);
      const G scaling(SO3<S>(), Eigen::Matrix<S, 3, 1>::Zero(), c);
      const std::vector<ld> scaled = library_distance(G(scaling * a), G(scaling * b));
      EXPECT_NEAR(double(scaled[0]), double(d[0]), double(64 * eps));
      EXPECT_NEAR(double(scaled[1]), double(ld(c) * d[1]), double(64 * eps * (1 + d[1])));
      EXPECT_NEAR(double(scaled[2]), double(d[2]), double(64 * eps));
    }
  }
}

TEST(DistanceOfSO2, TinyAnglesAreNotLost) {
  // |theta| rather than sqrt(theta^2), which underflows to 0 below 1e-154 in double.
  const chasles::SO2<double> a = chasles::SO2<double>::exp(1e-200), b = chasles::SO2<double>::exp(-2e-200);
  EXPECT_NEAR(chasles::distance(a, b), 3e-200, 1e-215);
}

}  // namespace
