// The groups written on lie_group.hpp's generic layer (SO2, SE2, SE23), as
// one typed suite over {group} x {float, double}, against oracles independent of
// the code under test:
// - exp against the matrix exponential of the hat matrix, summed in long
//   double (Taylor series after scaling, then squaring);
// - log against exp: log(exp(x)) = x inside the principal range, and
//   exp(log(g)) = g everywhere (angle pi included);
// - every Jacobian (of exp and its inverse, of log, inverse, compose, rplus,
//   rminus, lplus, lminus, between, the action) against central finite
//   differences of its defining identity, taken on the long double group
//   (step 1e-6: truncation 1e-12, rounding 1e-13);
// - the group laws on the long double matrices, and the algebra's bracket
//   against the commutator of the hat matrices.
// Tolerances are k * eps of the scalar under test times the data's scale
// (support/group_traits.hpp's `near`): kOp = 8 for one operation,
// kExp = 16 for exp, log and their round trips, kFd = 1e-9 / eps
// (absolute 1e-9 in double) for a Jacobian against finite differences.
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/chasles.hpp>

#include "support/exp_taylor.hpp"
#include "support/group_traits.hpp"
#include "support/jacobian_checks.hpp"

namespace {

using namespace chasles_test;
using chasles::SE2;
using chasles::SE23;
using chasles::SO2;

constexpr LD kOp = 8;
constexpr LD kExp = 16;

/// What the suite needs of a group beyond the generic interface: its
/// samples, its point size, the rotation angle of a tangent, a point in the
/// matrix's coordinates, and the rotation by pi.
template <typename G>
struct Samples;

template <typename S>
struct Samples<SO2<S>> {
  static constexpr int kPoint = 2;
  static Eigen::Matrix<LD, 2, 1> homogeneous(const Eigen::Matrix<LD, 2, 1>& p) { return p; }
  static Eigen::Matrix<S, 2, 2> rotation_by_pi() { return -Eigen::Matrix<S, 2, 2>::Identity(); }
  using Tangent = Eigen::Matrix<S, 1, 1>;
  static LD angle(const Tangent& x) { return std::fabs(static_cast<LD>(x[0])); }
  static LD scale(const Tangent&) { return 1; }
  static std::vector<Tangent> tangents() {
    std::vector<Tangent> out;
    const LD pi = kPi;
    const LD special[] = {0, 1e-30L, 1e-12L, 1e-8L, 1e-4L, 0.1L, 1, pi / 2, pi - 1e-4L, pi - 1e-6L, pi, 4, 10};
    for (LD a : special) {
      out.push_back(Tangent(S(a)));
      out.push_back(Tangent(S(-a)));
    }
    // Both sides of the series' cutoff, one ulp apart (constants.hpp).
    const S cut = std::sqrt(chasles::Thresholds<S>::taylor_theta2);
    out.push_back(Tangent(std::nextafter(cut, S(0))));
    out.push_back(Tangent(std::nextafter(cut, S(1))));
    std::mt19937_64 rng(kSeed);
    std::uniform_real_distribution<double> u(-double(kPi), double(kPi));
    for (int i = 0; i < 32; ++i) out.push_back(Tangent(S(u(rng))));
    return out;
  }
};

template <typename S>
struct Samples<SE2<S>> {
  static constexpr int kPoint = 2;
  static Eigen::Matrix<LD, 3, 1> homogeneous(const Eigen::Matrix<LD, 2, 1>& p) { return {p[0], p[1], 1}; }
  static Eigen::Matrix<S, 2, 2> rotation_by_pi() { return -Eigen::Matrix<S, 2, 2>::Identity(); }
  using Tangent = Eigen::Matrix<S, 3, 1>;
  static LD angle(const Tangent& x) { return std::fabs(static_cast<LD>(x[2])); }
  static LD scale(const Tangent& x) { return std::max(LD(1), max_abs(x)); }
  static std::vector<Tangent> tangents() {
    std::vector<Tangent> out;
    std::mt19937_64 rng(kSeed + 1);
    std::normal_distribution<double> n(0.0, 1.0);
    const S sizes[] = {S(0), S(1e-6), S(1), S(100)};
    int k = 0;
    for (const auto& w : Samples<SO2<S>>::tangents()) {
      Eigen::Vector2d v(n(rng), n(rng));
      v = v.normalized() * double(sizes[k++ % 4]);
      out.push_back(Tangent(S(v[0]), S(v[1]), w[0]));
    }
    out.push_back(Tangent(S(3), S(-4), S(0)));
    return out;
  }
};

template <typename S>
struct Samples<SE23<S>> {
  static constexpr int kPoint = 3;
  using Tangent = Eigen::Matrix<S, 9, 1>;
  static Eigen::Matrix<LD, 5, 1> homogeneous(const Eigen::Matrix<LD, 3, 1>& p) {
    Eigen::Matrix<LD, 5, 1> h;
    h << p, 1, 0;
    return h;
  }
  static Eigen::Matrix<S, 3, 3> rotation_by_pi() { return Eigen::Matrix<S, 3, 1>(1, -1, -1).asDiagonal(); }
  static LD angle(const Tangent& x) { return to_ld(Eigen::Matrix<S, 3, 1>(x.template tail<3>())).norm(); }
  static LD scale(const Tangent& x) { return std::max(LD(1), max_abs(x)); }
  /// SO2's angles (the hard ones and the cutoff's sides) about random axes
  /// and about the x axis, with position and velocity parts of four sizes.
  static std::vector<Tangent> tangents() {
    std::vector<Tangent> out;
    std::mt19937_64 rng(kSeed + 2);
    std::normal_distribution<double> n(0.0, 1.0);
    const S sizes[] = {S(0), S(1e-6), S(1), S(100)};
    int k = 0;
    for (const auto& a : Samples<SO2<S>>::tangents()) {
      Eigen::Vector3d axis(n(rng), n(rng), n(rng));
      if (k % 3 == 0) axis = Eigen::Vector3d::UnitX();
      Tangent x;
      for (int i = 0; i < 6; ++i) x[i] = S(n(rng) * double(sizes[(k + i / 3) % 4]) / std::sqrt(3.0));
      x.template tail<3>() = (axis.normalized() * double(a[0])).template cast<S>();
      ++k;
      out.push_back(x);
    }
    // Both sides of the series' cutoff, one ulp apart, about the x axis.
    const S cut = std::sqrt(chasles::Thresholds<S>::taylor_theta2);
    for (S a : {std::nextafter(cut, S(0)), std::nextafter(cut, S(1))}) {
      Tangent x;
      x << S(0.3), S(-0.2), S(0.1), S(1), S(2), S(-3), a, S(0), S(0);
      out.push_back(x);
    }
    return out;
  }
};

template <typename G>
class Groups : public ::testing::Test {
 public:
  using S = typename G::Scalar;
  using P = Samples<G>;
  using Tangent = typename G::Tangent;
  using GL = decltype(std::declval<G>().template cast<LD>());  // the same group over long double
  using TL = typename GL::Tangent;
  static constexpr int D = G::DoF;
  std::vector<Tangent> xs = P::tangents();
};

struct Name {
  template <typename G>
  static std::string GetName(int) {
    using S = typename G::Scalar;
    const std::string n = std::is_same<G, SO2<S>>::value ? "SO2" : std::is_same<G, SE2<S>>::value ? "SE2" : "SE23";
    return n + (std::is_same<S, float>::value ? "f" : "d");
  }
};

using Types = ::testing::Types<SO2<float>, SO2<double>, SE2<float>, SE2<double>, SE23<float>, SE23<double>>;
TYPED_TEST_SUITE(Groups, Types, Name);

TYPED_TEST(Groups, ExpIsTheMatrixExponentialOfHat) {
  using S = typename TestFixture::S;
  for (const auto& x : this->xs) {
    const auto X = to_ld(TypeParam::hat(x));
    EXPECT_TRUE(near<S>(TypeParam::exp(x).matrix(), chasles_ref::exp_taylor(X), kExp, TestFixture::P::scale(x)))
        << x.transpose();
  }
}

TYPED_TEST(Groups, LogInvertsExp) {
  using S = typename TestFixture::S;
  for (const auto& x : this->xs) {
    const TypeParam g = TypeParam::exp(x);
    // exp(log(g)) = g for every g, the angle pi included (either branch).
    EXPECT_TRUE(near<S>(TypeParam::exp(g.log()).matrix(), g.matrix(), kExp, TestFixture::P::scale(x))) << x.transpose();
    // log(exp(x)) = x in the principal range, away from pi by more than the
    // rounding of the angle (either branch is right there).
    if (TestFixture::P::angle(x) < LD(kPi) - 16 * eps<S>() * 4) {
      EXPECT_TRUE(near<S>(g.log(), x, kExp, TestFixture::P::scale(x))) << x.transpose();
    }
  }
  // At pi exactly (the rotation matrix [[-1, 0], [0, -1]]) the angle is pi, never NaN.
  const auto M = TypeParam::exp(this->xs[0]).matrix();
  auto Mpi = M;
  constexpr int kP = TestFixture::P::kPoint;
  Mpi.template topLeftCorner<kP, kP>() = TestFixture::P::rotation_by_pi();
  const auto w = TypeParam::from_matrix_unchecked(Mpi).log();
  EXPECT_EQ(TestFixture::P::angle(w), LD(S(kPi)));
}

TYPED_TEST(Groups, GroupLawsOnTheMatrices) {
  using S = typename TestFixture::S;
  const auto& xs = this->xs;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const TypeParam a = TypeParam::exp(xs[i]), b = TypeParam::exp(xs[(7 * i + 3) % xs.size()]);
    const LD scale = TestFixture::P::scale(xs[i]) + TestFixture::P::scale(xs[(7 * i + 3) % xs.size()]);
    EXPECT_TRUE(near<S>((a * b).matrix(), to_ld(a.matrix()) * to_ld(b.matrix()), kOp, scale));
    EXPECT_TRUE(near<S>(a.inverse().matrix(), to_ld(a.matrix()).inverse(), kOp, scale));
    EXPECT_TRUE(near<S>((a * a.inverse()).matrix(), decltype(to_ld(a.matrix()))::Identity(), kOp, scale));
    // Ad: a exp(y) a^-1 = exp(Ad_a y), on the matrices.
    const auto& y = xs[(11 * i + 2) % xs.size()];
    if (TestFixture::P::scale(y) < 10) {
      const auto lhs =
          (to_ld(a.matrix()) * chasles_ref::exp_taylor(to_ld(TypeParam::hat(y))) * to_ld(a.matrix()).inverse()).eval();
      EXPECT_TRUE(
          near<S>(TypeParam::exp(typename TypeParam::Tangent(a.adjoint() * y)).matrix(), lhs, 4 * kExp, scale * scale));
    }
    // ad(x) y = vee([hat x, hat y]); vee(hat(x)) = x.
    const auto X = to_ld(TypeParam::hat(xs[i])), Y = to_ld(TypeParam::hat(y));
    const auto C = (X * Y - Y * X).eval();
    EXPECT_TRUE(near<S>(TypeParam::ad(xs[i]) * y, TypeParam::vee(C.template cast<S>()), kOp, scale * scale));
    EXPECT_TRUE((TypeParam::vee(TypeParam::hat(xs[i])).array() == xs[i].array()).all());
    // The action: the matrix on the homogeneous point (or the point).
    constexpr int kP = TestFixture::P::kPoint;
    const Eigen::Matrix<S, kP, 1> p = Eigen::Matrix<S, kP, 1>::LinSpaced(S(0.3), S(-1.7));
    const auto q = (to_ld(a.matrix()) * TestFixture::P::homogeneous(to_ld(p))).eval();
    EXPECT_TRUE(near<S>(a.act(p), q.template head<kP>(), kOp, scale));
  }
}

TYPED_TEST(Groups, JacobiansOfExpAgainstDifferences) {
  using S = typename TestFixture::S;
  using GL = typename TestFixture::GL;
  using TL = typename TestFixture::TL;
  constexpr int D = TestFixture::D;
  for (const auto& x : this->xs) {
    if (TestFixture::P::angle(x) > 3 || TestFixture::P::scale(x) > 10) continue;  // J^-1 grows near 2 pi
    const TL xl = x.template cast<LD>();
    const GL g = GL::exp(xl);
    const auto Jr = central_differences<D>(D, [&](const TL& d) { return TL(rminus(GL::exp(TL(xl + d)), g)); });
    const auto Jl = central_differences<D>(D, [&](const TL& d) { return TL(lminus(GL::exp(TL(xl + d)), g)); });
    EXPECT_TRUE(near<S>(TypeParam::right_jacobian(x), Jr, fd_tolerance<S>())) << x.transpose();
    EXPECT_TRUE(near<S>(TypeParam::left_jacobian(x), Jl, fd_tolerance<S>())) << x.transpose();
    const auto I = Eigen::Matrix<LD, D, D>::Identity();
    EXPECT_TRUE(near<S>(to_ld(TypeParam::right_jacobian(x)) * to_ld(TypeParam::right_jacobian_inverse(x)), I, kExp));
    EXPECT_TRUE(near<S>(to_ld(TypeParam::left_jacobian(x)) * to_ld(TypeParam::left_jacobian_inverse(x)), I, kExp));
  }
}

TYPED_TEST(Groups, JacobiansOfTheOperationsAgainstDifferences) {
  constexpr int D = TestFixture::D;
  const auto& xs = this->xs;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const auto &x = xs[i], &y = xs[(5 * i + 1) % xs.size()];
    if (TestFixture::P::angle(x) > 2.5 || TestFixture::P::angle(y) > 2.5 || TestFixture::P::scale(x) > 10 ||
        TestFixture::P::scale(y) > 10)
      continue;
    const std::string at = "at x = " + std::to_string(double(x[D - 1])) + ", y = " + std::to_string(double(y[D - 1]));
    expect_operation_jacobians<TypeParam, TestFixture::P::kPoint>(TypeParam::exp(x), TypeParam::exp(y), y, at);
  }
}

TYPED_TEST(Groups, ConstructionFromMatrices) {
  using S = typename TestFixture::S;
  using M = decltype(TypeParam().matrix());
  for (const auto& x : this->xs) {
    const TypeParam g = TypeParam::exp(x);
    const M m = g.matrix();
    // A group element's own matrix passes the check and comes back exactly.
    ASSERT_TRUE(TypeParam::from_matrix(m).has_value());
    EXPECT_TRUE((TypeParam::from_matrix(m)->matrix().array() == m.array()).all());
    // Noise of 1e-3 on the rotation block: refused, and projected back to within it.
    M noisy = m;
    constexpr int kP = TestFixture::P::kPoint;
    noisy.template topLeftCorner<kP, kP>() += Eigen::Matrix<S, kP, kP>::Constant(S(1e-3));
    EXPECT_FALSE(TypeParam::from_matrix(noisy).has_value());
    EXPECT_TRUE(TypeParam::from_matrix_projected(noisy).is_approx(g, S(3e-3)));
    EXPECT_TRUE(TypeParam::from_matrix_projected(noisy).normalized().is_approx(
        TypeParam::from_matrix_projected(noisy), S(8) * std::numeric_limits<S>::epsilon()));
    // A reflection is no rotation.
    M reflected = m;
    reflected.row(0) = -reflected.row(0);
    EXPECT_FALSE(TypeParam::from_matrix(reflected).has_value());
  }
  M bad = TypeParam().matrix();
  bad(0, 0) = S(NAN);
  EXPECT_FALSE(TypeParam::from_matrix(bad).has_value());
  EXPECT_TRUE(TypeParam::from_matrix_projected(bad).is_approx(TypeParam(), 0));
}

TYPED_TEST(Groups, AutodiffDerivativesAtTheIdentityAreExact) {
  // d exp(x) / dx_i at x = 0 is hat(e_i) exactly: the series branch, no 0/0.
  using S = typename TestFixture::S;
  constexpr int D = TestFixture::D;
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<S, D, 1>>;
  using GA = decltype(std::declval<TypeParam>().template cast<AD>());
  typename GA::Tangent x;
  for (int i = 0; i < D; ++i) x[i] = AD(S(0), D, i);
  const auto E = GA::exp(x).matrix();
  const auto w = GA::exp(x).log();
  for (int i = 0; i < D; ++i) {
    typename TypeParam::Tangent e = TypeParam::Tangent::Zero();
    e[i] = S(1);
    const auto H = TypeParam::hat(e);
    for (int r = 0; r < H.rows(); ++r)
      for (int c = 0; c < H.cols(); ++c) EXPECT_EQ(E(r, c).derivatives()[i], H(r, c)) << r << "," << c;
    for (int j = 0; j < D; ++j) EXPECT_EQ(w[j].derivatives()[i], S(i == j ? 1 : 0));
  }
}

TEST(SO2, StoresTheUnitComplexNumber) {
  const SO2<double> r = SO2<double>::exp(0.3);
  EXPECT_EQ(r.complex()[0], std::cos(0.3));
  EXPECT_EQ(r.complex()[1], std::sin(0.3));
  EXPECT_EQ(SO2<double>::from_complex(3e-300, 4e-300).complex()[0], 0.6);
  EXPECT_EQ(SO2<double>::from_complex(0, 0).complex()[0], 1.0);
  EXPECT_NEAR(SO2<double>::from_complex(3e300, -4e300).angle(), std::atan2(-4.0, 3.0), 2.3e-16);
}

}  // namespace
