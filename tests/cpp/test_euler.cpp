// Euler angles (euler.hpp), for float and double, all 24 sequences, against
// an independent reference: the product of the elementary rotation matrices
// Rx, Ry, Rz written out in long double (the library builds from_euler from
// quaternions and reads as_euler with atan2 pairs).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "chasles/euler.hpp"

namespace {

using chasles::EulerSequence;
using ld = long double;
using M3L = Eigen::Matrix<ld, 3, 3>;
constexpr ld kPi = 3.141592653589793238462643383279502884L;
constexpr const char* kNames[24] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz",
                                    "XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"};

/// The elementary rotation by t about axis 0, 1 or 2 (x, y, z), long double.
M3L elementary(int axis, ld t) {
  const ld c = std::cos(t), s = std::sin(t);
  M3L R = M3L::Identity();
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // R e_a = c e_a + s e_b for (axis, a, b) cyclic
  R(a, a) = c;
  R(b, a) = s;
  R(a, b) = -s;
  R(b, b) = c;
  return R;
}

int axis_of(char c) { return (c | 0x20) - 'x'; }
bool is_extrinsic(const char* name) { return name[0] >= 'a'; }

/// The reference: extrinsic "abc" is R_c(t3) R_b(t2) R_a(t1), intrinsic "ABC" is R_A(t1) R_B(t2) R_C(t3).
template <typename V>
M3L reference(const char* name, const V& t) {
  const M3L A = elementary(axis_of(name[0]), ld(t[0]));
  const M3L B = elementary(axis_of(name[1]), ld(t[1]));
  const M3L C = elementary(axis_of(name[2]), ld(t[2]));
  return is_extrinsic(name) ? M3L(C * B * A) : M3L(A * B * C);
}

/// Calls f(std::integral_constant<int, n>) for n = 0..23: each sequence as a
/// compile-time value, as a user writes it.
template <typename F, int... N>
void for_sequences_impl(F&& f, std::integer_sequence<int, N...>) {
  (f(std::integral_constant<int, N>()), ...);
}
template <typename F>
void for_each_sequence(F&& f) {
  for_sequences_impl(f, std::make_integer_sequence<int, 24>());
}

template <typename T>
class Euler : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Euler, Scalars);

template <typename T>
constexpr ld eps() {
  return ld(std::numeric_limits<T>::epsilon());
}

template <typename T>
ld max_diff(const Eigen::Matrix<T, 3, 3>& a, const M3L& b) {
  ld worst = 0;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(ld(a(i, j)) - b(i, j)));
  return worst;
}

/// A uniformly random rotation (Shoemake's uniform quaternion), in long double, rounded to T.
template <typename T>
chasles::SO3<T> random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  Eigen::Quaternion<ld> q(ld(n(rng)), ld(n(rng)), ld(n(rng)), ld(n(rng)));
  q.normalize();
  return chasles::SO3<T>::from_matrix_unchecked(q.toRotationMatrix().template cast<T>());
}

TYPED_TEST(Euler, FromEulerIsTheProductOfElementaryRotations) {
  using T = TypeParam;
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> u(-7.0, 7.0);  // outside the output ranges too
  for_each_sequence([&](auto n) {
    constexpr auto seq = static_cast<EulerSequence>(decltype(n)::value);
    const char* name = kNames[decltype(n)::value];
    ld worst = 0;
    for (int k = 0; k < 200; ++k) {
      const Eigen::Matrix<T, 3, 1> t(T(u(rng)), T(u(rng)), T(u(rng)));
      worst = std::max(worst, max_diff(chasles::from_euler<seq>(t).matrix(), reference(name, t)));
    }
    EXPECT_LE(worst, 8 * eps<T>()) << name;
  });
}

TYPED_TEST(Euler, RebuildsEveryRotation) {
  // from_euler(as_euler(R)) = R to a few ulps (1e-15 in double), measured
  // with the long double reference product of the returned angles.
  using T = TypeParam;
  std::mt19937_64 rng(7);
  for_each_sequence([&](auto n) {
    constexpr auto seq = static_cast<EulerSequence>(decltype(n)::value);
    const char* name = kNames[decltype(n)::value];
    ld worst = 0;
    for (int k = 0; k < 500; ++k) {
      const chasles::SO3<T> R = random_rotation<T>(rng);
      const auto e = chasles::as_euler<seq>(R);
      EXPECT_FALSE(e.gimbal_lock) << name;
      worst = std::max(worst, max_diff(R.matrix(), reference(name, e.angles)));
    }
    EXPECT_LE(worst, 5 * eps<T>()) << name;
  });
}

TYPED_TEST(Euler, RunTimeSequenceIsTheCompileTimeOne) {
  // from_euler(seq, t) and as_euler(seq, R): the same bits as the template instance of seq.
  using T = TypeParam;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  for_each_sequence([&](auto n) {
    constexpr auto seq = static_cast<EulerSequence>(decltype(n)::value);
    const char* name = kNames[decltype(n)::value];
    for (int k = 0; k < 20; ++k) {
      const Eigen::Matrix<T, 3, 1> t(T(u(rng)), T(u(rng)), T(u(rng)));
      EXPECT_EQ(chasles::from_euler(seq, t).matrix(), chasles::from_euler<seq>(t).matrix()) << name;
      const chasles::SO3<T> R = random_rotation<T>(rng);
      const auto a = chasles::as_euler(seq, R), b = chasles::as_euler<seq>(R);
      EXPECT_EQ(a.angles, b.angles) << name;
      EXPECT_EQ(a.gimbal_lock, b.gimbal_lock) << name;
    }
  });
}

/// The lock of a sequence: middle angle pi/2 (Tait-Bryan) or 0 and pi (proper).
bool proper(const char* name) { return (name[0] | 0x20) == (name[2] | 0x20); }

TYPED_TEST(Euler, AnglesRoundTripWithScipysRanges) {
  // Angles inside the output ranges come back, to a few ulps times the
  // conditioning 1 / |cos t2| (Tait-Bryan) or 1 / |sin t2| (proper).
  using T = TypeParam;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> outer(-3.1, 3.1), tb(-1.5, 1.5), pr(0.05, 3.09);
  for_each_sequence([&](auto n) {
    constexpr auto seq = static_cast<EulerSequence>(decltype(n)::value);
    const char* name = kNames[decltype(n)::value];
    for (int k = 0; k < 300; ++k) {
      const Eigen::Matrix<T, 3, 1> t(T(outer(rng)), T(proper(name) ? pr(rng) : tb(rng)), T(outer(rng)));
      // the matrix of the angles, rounded from the long double reference
      const auto R = chasles::SO3<T>::from_matrix_unchecked(reference(name, t).template cast<T>());
      const auto e = chasles::as_euler<seq>(R);
      const ld cond = 1 / (proper(name) ? std::abs(std::sin(ld(t[1]))) : std::abs(std::cos(ld(t[1]))));
      for (int i = 0; i < 3; ++i) EXPECT_LE(std::abs(ld(e.angles[i]) - ld(t[i])), 8 * eps<T>() * cond) << name << i;
    }
  });
}

TYPED_TEST(Euler, AtAndNearTheLock) {
  // At the lock (a matrix built from a middle angle of fl(pi/2), 0 or
  // fl(pi)) the lock is reported and the third angle is zero, as scipy; near
  // it (1e-16 to 1e-3 away, both sides) no lock, and R is rebuilt to a few
  // ulps however ill-determined the outer angles are.
  using T = TypeParam;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> outer(-3.1, 3.1);
  const std::array<ld, 9> offsets = {0, 1e-16L, 1e-12L, 1e-9L, 1e-7L, 3e-7L, 1e-5L, 1e-3L, 2 * eps<T>()};
  for_each_sequence([&](auto n) {
    constexpr auto seq = static_cast<EulerSequence>(decltype(n)::value);
    const char* name = kNames[decltype(n)::value];
    const std::array<ld, 2> locks = proper(name) ? std::array<ld, 2>{0, kPi} : std::array<ld, 2>{kPi / 2, -kPi / 2};
    for (const ld lock : locks)
      for (const ld off : offsets)
        for (const ld sign : {ld(1), ld(-1)})
          for (int k = 0; k < 20; ++k) {
            const ld middle = lock + sign * off;
            const Eigen::Matrix<T, 3, 1> t(T(outer(rng)), T(middle), T(outer(rng)));
            // from the library's own from_euler, as a user would build it
            const chasles::SO3<T> R = chasles::from_euler<seq>(t);
            const auto e = chasles::as_euler<seq>(R);
            EXPECT_LE(max_diff(R.matrix(), reference(name, e.angles)), 5 * eps<T>())
                << name << " middle " << double(middle) << " -> " << e.angles.transpose();
            if (off == 0) {
              EXPECT_TRUE(e.gimbal_lock) << name << " " << double(middle);
              EXPECT_EQ(e.angles[2], T(0)) << name;
            } else if (off >= 16 * eps<T>()) {  // clear of the lock pair's rounding
              EXPECT_FALSE(e.gimbal_lock) << name << " " << double(middle);
            }
          }
  });
}

TYPED_TEST(Euler, LockThresholdBothSides) {
  // Matrices whose lock pair has a norm of 0.7 eps and 1.4 eps, rounded from
  // the long double reference: the first is the lock, the second is not,
  // and both rebuild R.
  using T = TypeParam;
  for_each_sequence([&](auto n) {
    constexpr auto seq = static_cast<EulerSequence>(decltype(n)::value);
    const char* name = kNames[decltype(n)::value];
    for (const ld d : {ld(0.7), ld(1.4)}) {
      // Tait-Bryan: |cos t2| = d eps; proper: |sin t2| = d eps
      const ld middle = proper(name) ? d * eps<T>() : kPi / 2 - d * eps<T>();
      const Eigen::Matrix<ld, 3, 1> t(0.4L, middle, -1.1L);
      const auto R = chasles::SO3<T>::from_matrix_unchecked(reference(name, t).template cast<T>());
      const auto e = chasles::as_euler<seq>(R);
      EXPECT_EQ(e.gimbal_lock, d < 1) << name << " d = " << double(d);
      EXPECT_LE(max_diff(R.matrix(), reference(name, e.angles)), 5 * eps<T>()) << name;
    }
  });
}

TYPED_TEST(Euler, RpyIsUrdfsFixedXYZ) {
  using T = TypeParam;
  const T roll(0.3), pitch(-1.2), yaw(2.5);
  const M3L ref = elementary(2, ld(yaw)) * elementary(1, ld(pitch)) * elementary(0, ld(roll));
  const chasles::SO3<T> R = chasles::from_rpy(roll, pitch, yaw);
  EXPECT_LE(max_diff(R.matrix(), ref), 4 * eps<T>());
  const auto e = chasles::as_rpy(R);
  EXPECT_FALSE(e.gimbal_lock);
  EXPECT_NEAR(double(e.angles[0]), double(roll), 20 * double(eps<T>()));
  EXPECT_NEAR(double(e.angles[1]), double(pitch), 20 * double(eps<T>()));
  EXPECT_NEAR(double(e.angles[2]), double(yaw), 20 * double(eps<T>()));
}

TEST(EulerAutodiff, DerivativeOfTheRoundTripIsTheIdentity) {
  // Away from the lock, as_euler(from_euler(t)) = t, so its Jacobian is I;
  // and d from_euler / dt_i = [a_i] R for the axis a_i in the right frame:
  // checked against central differences.
  using AD = Eigen::AutoDiffScalar<Eigen::Vector3d>;
  for_each_sequence([&](auto n) {
    constexpr auto seq = static_cast<EulerSequence>(decltype(n)::value);
    const char* name = kNames[decltype(n)::value];
    const Eigen::Vector3d t0(0.7, proper(name) ? 1.1 : -0.4, -2.3);
    Eigen::Matrix<AD, 3, 1> t;
    for (int i = 0; i < 3; ++i) t[i] = AD(t0[i], 3, i);
    const auto R = chasles::from_euler<seq>(t);
    const auto e = chasles::as_euler<seq>(R);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(e.angles[i].value(), t0[i], 1e-14) << name;
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(e.angles[i].derivatives()[j], i == j ? 1.0 : 0.0, 1e-13) << name;
    }
    const double h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d tp = t0, tm = t0;
      tp[j] += h;
      tm[j] -= h;
      const Eigen::Matrix3d fd =
          (chasles::from_euler<seq>(tp).matrix() - chasles::from_euler<seq>(tm).matrix()) / (2 * h);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(R.matrix()(r, c).derivatives()[j], fd(r, c), 1e-9) << name;
    }
  });
}

}  // namespace

namespace {

TEST(EulerThreshold, LockIsEpsSquared) {
  // constants.hpp: the lock pair's squared norm is compared with eps^2 (a power of two, exact).
  EXPECT_EQ(chasles::Thresholds<float>::euler_lock2,
            std::numeric_limits<float>::epsilon() * std::numeric_limits<float>::epsilon());
  EXPECT_EQ(chasles::Thresholds<double>::euler_lock2,
            std::numeric_limits<double>::epsilon() * std::numeric_limits<double>::epsilon());
  EXPECT_EQ(chasles::Thresholds<long double>::euler_lock2,
            std::numeric_limits<long double>::epsilon() * std::numeric_limits<long double>::epsilon());
}

}  // namespace
