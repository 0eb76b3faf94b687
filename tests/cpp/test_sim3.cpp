// Sim(3) (sim3.hpp), as a typed suite over {float, double}, against oracles
// independent of the code under test, as test_groups.cpp does for SO2/SE2:
// - exp against the matrix exponential of the hat matrix, summed in long
//   double (Taylor series after scaling, then squaring), on a grid of
//   theta x sigma x |v| that covers 0, tiny, both sides of every cutoff
//   (one ulp apart), pi, large |sigma|, and random samples;
// - log against exp: log(exp(x)) = x inside the principal range, and
//   exp(log(g)) = g everywhere (angle pi included);
// - every Jacobian (of exp and its inverse, of log, inverse, compose, rplus,
//   rminus, lplus, lminus, between) against central finite differences of
//   its defining identity on the long double group (step 1e-6);
// - the Jacobians of exp also against the top-right block of the
//   exponential of [[ad_xi, I], [0, 0]] in long double, to rounding;
// - the group laws on the long double matrices, and ad against the
//   commutator of the hat matrices;
// - autodiff: the derivative of exp at 0 is the hat generators, exactly.
// Tolerances are k * eps of the scalar under test times the data's scale
// (support/group_traits.hpp's `near`): kOp = 8 for one operation,
// kExp = 16 for exp, log and their round trips (the scale of the
// translation is max(1, A |v|), A = (e^sigma - 1)/sigma the size of W; of
// the block s R, max(1, s)), and 1e-9 / eps (absolute 1e-9 in double,
// relative beyond unit scale) for a Jacobian against finite differences.
// The worst errors, in eps, are printed at the end of each test.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/LU>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/chasles.hpp>

#include "support/exp_taylor.hpp"
#include "support/group_traits.hpp"
#include "support/jacobian_checks.hpp"

namespace {

using namespace chasles_test;
using chasles::Sim3;

constexpr LD kOp = 8;
constexpr LD kExp = 16;

/// The largest S whose square (rounded in S) is below cut, and the next one.
template <typename S>
std::pair<S, S> cutoff_sides(S cut, S factor = S(1)) {
  S x = std::sqrt(cut / factor);
  while (factor * (x * x) >= cut) x = std::nextafter(x, S(0));
  while (factor * (std::nextafter(x, S(1)) * std::nextafter(x, S(1))) < cut) x = std::nextafter(x, S(1));
  return {x, std::nextafter(x, S(1))};
}

/// Worst error seen, in eps, and where.
struct Worst {
  explicit Worst(const char* w) : what(w) {}
  const char* what;
  LD err = 0;
  std::string at;
  void see(LD e, const std::string& where) {
    if (e > err) err = e, at = where;
  }
  ~Worst() { std::printf("  worst %s: %.3g eps at %s\n", what, double(err), at.c_str()); }
};

template <typename Derived>
std::string str(const Eigen::MatrixBase<Derived>& x) {
  std::string s;
  char buf[64];
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s%.9g", i ? " " : "", double(x(i)));
    s += buf;
  }
  return "(" + s + ")";
}

template <typename G>
class Sim3Test : public ::testing::Test {
 public:
  using S = typename G::Scalar;
  using Tangent = typename G::Tangent;
  using GL = Sim3<LD>;
  using TL = typename GL::Tangent;
  static constexpr int D = 7;

  static Tangent make(const Eigen::Matrix<S, 3, 1>& v, const Eigen::Matrix<S, 3, 1>& w, S sigma) {
    Tangent x;
    x << v, w, sigma;
    return x;
  }

  /// The grid: theta x sigma x |v|, axes random (the cutoff samples on a
  /// coordinate axis, so that theta^2 is on the side intended), and random
  /// samples.
  static std::vector<Tangent> tangents() {
    std::vector<Tangent> out;
    const S cut = chasles::Thresholds<S>::taylor_theta2;
    const auto c1 = cutoff_sides<S>(cut);
    const S pi = S(kPi);
    const std::vector<S> thetas = {S(0),      S(1e-30), S(1e-12), S(1e-8),   S(1e-4),        c1.first,
                                   c1.second, S(0.1),   S(1),     S(pi / 2), S(kPi - 1e-6L), pi};
    const std::vector<S> sigmas = {S(0),      S(1e-30), S(1e-12), S(-1e-8), S(1e-4), c1.first, c1.second,
                                   -c1.first, S(0.1),   S(1),     S(-1),    S(5),    S(-5)};
    const S sizes[] = {S(0), S(1), S(100)};
    std::mt19937_64 rng(kSeed + 7);
    std::normal_distribution<double> n(0.0, 1.0);
    auto unit = [&]() {
      Eigen::Vector3d u(n(rng), n(rng), n(rng));
      return Eigen::Matrix<S, 3, 1>(u.normalized().cast<S>());
    };
    for (std::size_t i = 0; i < thetas.size(); ++i)
      for (S sigma : sigmas)
        for (S size : sizes) {
          const bool on_axis = i == 5 || i == 6;
          const Eigen::Matrix<S, 3, 1> axis = on_axis ? Eigen::Matrix<S, 3, 1>(S(1), S(0), S(0)) : unit();
          out.push_back(make(Eigen::Matrix<S, 3, 1>(unit() * size), Eigen::Matrix<S, 3, 1>(axis * thetas[i]), sigma));
        }
    // Both sides of the two-variable cutoff sigma^2 + theta^2 (sigma = theta),
    // and of sigma's alone with theta just above and below its own.
    const auto c2 = cutoff_sides<S>(cut, S(2));
    for (S x : {c2.first, c2.second})
      for (S size : sizes)
        for (S sg : {x, S(-x)})
          out.push_back(make(Eigen::Matrix<S, 3, 1>(unit() * size), Eigen::Matrix<S, 3, 1>(x, S(0), S(0)), sg));
    // The regimes named in the issue.
    for (S size : sizes) {
      out.push_back(make(Eigen::Matrix<S, 3, 1>(unit() * size), Eigen::Matrix<S, 3, 1>(unit() * S(1e-3)), S(1e-3)));
      out.push_back(make(Eigen::Matrix<S, 3, 1>(unit() * size), Eigen::Matrix<S, 3, 1>(unit() * S(1e-4)), S(5)));
      out.push_back(make(Eigen::Matrix<S, 3, 1>(unit() * size), Eigen::Matrix<S, 3, 1>(unit() * S(3e-3)), S(2e-3)));
    }
    std::uniform_real_distribution<double> u(0.0, double(kPi)), us(-3.0, 3.0);
    for (int i = 0; i < 48; ++i) {
      const Eigen::Matrix<S, 3, 1> v = unit() * S(std::exp(us(rng)));
      out.push_back(make(v, Eigen::Matrix<S, 3, 1>(unit() * S(u(rng))), S(us(rng))));
    }
    return out;
  }

  std::vector<Tangent> xs = tangents();

  static LD angle(const Tangent& x) { return to_ld(x.template segment<3>(3)).norm(); }
  static LD size(const Tangent& x) { return max_abs(x); }
  static LD phi(LD sigma) { return sigma == 0 ? LD(1) : std::expm1(sigma) / sigma; }
  /// The scale of exp(x)'s translation: max(1, A |v|_max).
  static LD t_scale(const Tangent& x) {
    return std::max(LD(1), phi(static_cast<LD>(x[6])) * max_abs(x.template head<3>()));
  }

  /// max |a - b| / (eps * max(1, |a|, |b|, extra)).
  template <typename A, typename B>
  static LD err_eps(const A& a, const B& b, LD extra = 1) {
    const LD scale = std::max({LD(1), max_abs(a), max_abs(b), extra});
    return max_abs_diff(a, b) / (eps<S>() * scale);
  }
};

struct Name {
  template <typename G>
  static std::string GetName(int) {
    return std::is_same<typename G::Scalar, float>::value ? "Sim3f" : "Sim3d";
  }
};

using Types = ::testing::Types<Sim3<float>, Sim3<double>>;
TYPED_TEST_SUITE(Sim3Test, Types, Name);

TYPED_TEST(Sim3Test, ExpIsTheMatrixExponentialOfHat) {
  using S = typename TestFixture::S;
  Worst block("exp s R"), trans("exp t");
  for (const auto& x : this->xs) {
    const Eigen::Matrix<LD, 4, 4> E = chasles_ref::exp_taylor<4>(to_ld(TypeParam::hat(x)));
    const Eigen::Matrix<S, 4, 4> M = TypeParam::exp(x).matrix();
    const LD sb = std::max(LD(1), std::exp(static_cast<LD>(x[6])));
    const LD st = TestFixture::t_scale(x);
    const Eigen::Matrix<S, 3, 3> B = M.template topLeftCorner<3, 3>();
    const Eigen::Matrix<LD, 3, 3> Bl = E.template topLeftCorner<3, 3>();
    const Eigen::Matrix<S, 3, 1> T = M.template topRightCorner<3, 1>();
    const Eigen::Matrix<LD, 3, 1> Tl = E.template topRightCorner<3, 1>();
    EXPECT_TRUE(near<S>(B, Bl, kExp, sb)) << str(x);
    EXPECT_TRUE(near<S>(T, Tl, kExp, st)) << str(x);
    EXPECT_TRUE(near<S>(M.template bottomRows<1>(), E.template bottomRows<1>(), 0)) << str(x);
    block.see(TestFixture::err_eps(B, Bl, sb), str(x));
    trans.see(TestFixture::err_eps(T, Tl, st), str(x));
  }
}

TYPED_TEST(Sim3Test, LogInvertsExp) {
  using S = typename TestFixture::S;
  Worst roundtrip("log(exp(x)) - x"), back("exp(log(g)) - g");
  for (const auto& x : this->xs) {
    const TypeParam g = TypeParam::exp(x);
    // exp(log(g)) = g for every g, the angle pi included (either branch).
    const TypeParam h = TypeParam::exp(g.log());
    const LD sb = std::max(LD(1), static_cast<LD>(g.scale()));
    const LD st = TestFixture::t_scale(x);
    EXPECT_TRUE(
        near<S>(h.matrix().template topLeftCorner<3, 3>(), to_ld(g.matrix().template topLeftCorner<3, 3>()), kExp, sb))
        << str(x);
    EXPECT_TRUE(near<S>(h.translation(), to_ld(g.translation()), kExp, st)) << str(x);
    back.see(std::max(TestFixture::err_eps(h.matrix().template topLeftCorner<3, 3>(),
                                           g.matrix().template topLeftCorner<3, 3>(), sb),
                      TestFixture::err_eps(h.translation(), g.translation(), st)),
             str(x));
    // log(exp(x)) = x in the principal range, away from pi by more than the
    // rounding of the angle (either branch is right there).
    if (TestFixture::angle(x) < LD(kPi) - LD(1e-3)) {
      const auto y = g.log();
      const LD sc = std::max(LD(1), TestFixture::size(x));
      EXPECT_TRUE(near<S>(y, to_ld(x), kExp, sc)) << str(x) << " -> " << str(y);
      roundtrip.see(TestFixture::err_eps(y, to_ld(x), sc), str(x));
    }
  }
}

TYPED_TEST(Sim3Test, GroupLawsOnTheMatrices) {
  using S = typename TestFixture::S;
  using M4 = Eigen::Matrix<LD, 4, 4>;
  const auto& xs = this->xs;
  Worst worst("group laws");
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const auto &x = xs[i], &xb = xs[(7 * i + 3) % xs.size()];
    const TypeParam a = TypeParam::exp(x), b = TypeParam::exp(xb);
    const M4 A = to_ld(a.matrix()), Bm = to_ld(b.matrix());
    const LD scale = std::max(LD(1), max_abs(A)) * std::max(LD(1), max_abs(Bm));
    EXPECT_TRUE(near<S>((a * b).matrix(), A * Bm, kOp, scale));
    TypeParam m = a;
    m *= b;
    EXPECT_TRUE(near<S>(m.matrix(), A * Bm, kOp, scale));
    const LD inv_scale = max_abs(M4(A.inverse()));
    EXPECT_TRUE(near<S>(a.inverse().matrix(), A.inverse(), kOp, inv_scale)) << str(x);
    EXPECT_TRUE(near<S>((a * a.inverse()).matrix(), M4::Identity(), kOp, std::max(LD(1), max_abs(A)) * inv_scale));
    worst.see(TestFixture::err_eps((a * b).matrix(), A * Bm, scale), "compose " + str(x));
    // The action: the matrix on the homogeneous point.
    const Eigen::Matrix<S, 3, 1> p(S(0.3), S(-1.7), S(2.2));
    const Eigen::Matrix<LD, 4, 1> q = A * Eigen::Matrix<LD, 4, 1>(LD(p[0]), LD(p[1]), LD(p[2]), 1);
    EXPECT_TRUE(near<S>(a.act(p), q.template head<3>(), kOp, 3 * std::max(LD(1), max_abs(A))));
    EXPECT_TRUE(near<S>(a * p, q.template head<3>(), kOp, 3 * std::max(LD(1), max_abs(A))));
    // Ad: a exp(y) a^-1 = exp(Ad_a y), on the matrices (y of moderate size).
    const auto& y = xs[(11 * i + 2) % xs.size()];
    if (TestFixture::size(y) < 10 && max_abs(A) < 200) {
      const M4 lhs = A * chasles_ref::exp_taylor<4>(to_ld(TypeParam::hat(y))) * A.inverse();
      const typename TypeParam::Tangent ady = a.adjoint() * y;
      EXPECT_TRUE(near<S>(TypeParam::exp(ady).matrix(), lhs, 4 * kExp, max_abs(lhs) * max_abs(A) * inv_scale))
          << str(x) << " " << str(y);
      // The same on the algebra, exactly: hat(Ad_a y) = A hat(y) A^-1.
      EXPECT_TRUE(near<S>(TypeParam::hat(ady), A * to_ld(TypeParam::hat(y)) * A.inverse(), kOp,
                          max_abs(A) * inv_scale * std::max(LD(1), TestFixture::size(y))));
    }
    // ad(x) y = vee([hat x, hat y]); vee(hat(x)) = x.
    const auto X = to_ld(TypeParam::hat(x)), Y = to_ld(TypeParam::hat(y));
    const Eigen::Matrix<LD, 4, 4> C = X * Y - Y * X;
    const LD sxy = std::max(LD(1), TestFixture::size(x)) * std::max(LD(1), TestFixture::size(y));
    EXPECT_TRUE(near<S>(TypeParam::ad(x) * y, TypeParam::vee(C.template cast<S>()), kOp, sxy));
    EXPECT_TRUE((TypeParam::vee(TypeParam::hat(x)).array() == x.array()).all());
  }
}

TYPED_TEST(Sim3Test, JacobiansOfExpAgainstDifferences) {
  using S = typename TestFixture::S;
  using GL = typename TestFixture::GL;
  using TL = typename TestFixture::TL;
  constexpr int D = TestFixture::D;
  Worst wr("J_r vs differences (in units of the fd tolerance)"), wl("J_l vs differences (fd tolerance)"),
      wi("J J^-1 - I");
  for (const auto& x : this->xs) {
    const TL xl = x.template cast<LD>();
    const GL g = GL::exp(xl);
    const auto Jr = central_differences<D>(D, [&](const TL& d) { return TL(rminus(GL::exp(TL(xl + d)), g)); });
    const auto Jl = central_differences<D>(D, [&](const TL& d) { return TL(lminus(GL::exp(TL(xl + d)), g)); });
    const auto JR = TypeParam::right_jacobian(x), JL = TypeParam::left_jacobian(x);
    EXPECT_TRUE(near<S>(JR, Jr, fd_tolerance<S>())) << str(x);
    EXPECT_TRUE(near<S>(JL, Jl, fd_tolerance<S>())) << str(x);
    wr.see(TestFixture::err_eps(JR, Jr) / fd_tolerance<S>(), str(x));
    wl.see(TestFixture::err_eps(JL, Jl) / fd_tolerance<S>(), str(x));
    const auto I = Eigen::Matrix<LD, D, D>::Identity();
    const auto JRi = TypeParam::right_jacobian_inverse(x), JLi = TypeParam::left_jacobian_inverse(x);
    const LD sr = max_abs(JR) * max_abs(JRi), sl = max_abs(JL) * max_abs(JLi);
    EXPECT_TRUE(near<S>(to_ld(JR) * to_ld(JRi), I, kExp, sr)) << str(x);
    EXPECT_TRUE(near<S>(to_ld(JL) * to_ld(JLi), I, kExp, sl)) << str(x);
    EXPECT_TRUE(near<S>(to_ld(JRi) * to_ld(JR), I, kExp, sr)) << str(x);
    wi.see(std::max(TestFixture::err_eps(to_ld(JR) * to_ld(JRi), I, sr),
                    TestFixture::err_eps(to_ld(JL) * to_ld(JLi), I, sl)),
           str(x));
  }
  // At 0: the identity, exactly.
  const auto Z = TypeParam::Tangent::Zero().eval();
  EXPECT_TRUE((TypeParam::left_jacobian(Z).array() == Eigen::Matrix<S, D, D>::Identity().array()).all());
  EXPECT_TRUE((TypeParam::right_jacobian_inverse(Z).array() == Eigen::Matrix<S, D, D>::Identity().array()).all());
}

// J_l(xi) = phi(ad_xi) is the top-right block of the exponential of the
// 14x14 [[ad_xi, I], [0, 0]] (the integral of exp(u ad_xi) over [0, 1]),
// summed in long double from the same input: an oracle for the value to
// rounding, where the differences above check only the convention. Within
// kExp eps of the largest entry over the whole grid, |v| = 100 and
// |sigma| = 5 included (the coupling blocks are computed for v scaled to
// unit size, sim3.hpp).
TYPED_TEST(Sim3Test, JacobianOfExpIsTheBlockExponential) {
  using S = typename TestFixture::S;
  using TL = typename TestFixture::TL;
  constexpr int D = TestFixture::D;
  Worst wl("J_l vs the block exponential"), wr("J_r vs the block exponential");
  auto phi_ad = [](const TL& x) {
    Eigen::Matrix<LD, 2 * D, 2 * D> B = Eigen::Matrix<LD, 2 * D, 2 * D>::Zero();
    B.template topLeftCorner<D, D>() = Sim3<LD>::ad(x);
    B.template topRightCorner<D, D>().setIdentity();
    return Eigen::Matrix<LD, D, D>(chasles_ref::exp_taylor<2 * D>(B).template topRightCorner<D, D>());
  };
  for (const auto& x : this->xs) {
    const TL xl = x.template cast<LD>();
    const auto JL = TypeParam::left_jacobian(x), JR = TypeParam::right_jacobian(x);
    const Eigen::Matrix<LD, D, D> L = phi_ad(xl), R = phi_ad(TL(-xl));
    EXPECT_TRUE(near<S>(JL, L, kExp)) << str(x);
    EXPECT_TRUE(near<S>(JR, R, kExp)) << str(x);
    wl.see(TestFixture::err_eps(JL, L), str(x));
    wr.see(TestFixture::err_eps(JR, R), str(x));
  }
}

TYPED_TEST(Sim3Test, JacobiansOfTheOperationsAgainstDifferences) {
  const auto& xs = this->xs;
  for (std::size_t i = 0; i < xs.size(); i += 3) {
    const auto &x = xs[i], &y = xs[(5 * i + 1) % xs.size()];
    if (TestFixture::angle(x) > 2.5 || TestFixture::angle(y) > 2.5) continue;  // log's branch cut at pi
    expect_operation_jacobians<TypeParam, 3>(TypeParam::exp(x), TypeParam::exp(y), y,
                                             "at x = " + str(x) + ", y = " + str(y));
  }
}

TYPED_TEST(Sim3Test, ConstructionFromMatrices) {
  using S = typename TestFixture::S;
  using M = Eigen::Matrix<S, 4, 4>;
  for (const auto& x : this->xs) {
    const TypeParam g = TypeParam::exp(x);
    const M m = g.matrix();
    const LD tol = 8 * eps<S>();
    // A group element's own matrix passes the check and comes back to rounding.
    ASSERT_TRUE(TypeParam::from_matrix(m).has_value()) << str(x);
    EXPECT_TRUE(TypeParam::from_matrix(m)->is_approx(g, S(tol))) << str(x);
    EXPECT_TRUE(near_scalar<S>(TypeParam::from_matrix_unchecked(m).scale(), g.scale(), 4, g.scale())) << str(x);
    EXPECT_TRUE(TypeParam::from_matrix_projected(m).is_approx(g, S(tol))) << str(x);
    // Noise of 1e-3 s on the block: refused, and projected back to within it.
    M noisy = m;
    noisy.template topLeftCorner<3, 3>() += M::Constant(S(1e-3) * g.scale()).template topLeftCorner<3, 3>();
    EXPECT_FALSE(TypeParam::from_matrix(noisy).has_value());
    EXPECT_TRUE(TypeParam::from_matrix_projected(noisy).rotation().is_approx(g.rotation(), S(3e-3))) << str(x);
    EXPECT_NEAR(double(TypeParam::from_matrix_projected(noisy).scale() / g.scale()), 1.0, 3e-3);
    EXPECT_TRUE(TypeParam::from_matrix_projected(noisy).normalized().is_approx(
        TypeParam::from_matrix_projected(noisy), S(8) * std::numeric_limits<S>::epsilon()));
    // A reflection is no similarity; nor is a bottom row other than (0, 0, 0, 1).
    M reflected = m;
    reflected.row(0).template head<3>() = -reflected.row(0).template head<3>();
    EXPECT_FALSE(TypeParam::from_matrix(reflected).has_value());
    M bottom = m;
    bottom(3, 0) = S(1e-2);
    EXPECT_FALSE(TypeParam::from_matrix(bottom).has_value());
  }
  M bad = TypeParam().matrix();
  bad(0, 0) = S(NAN);
  EXPECT_FALSE(TypeParam::from_matrix(bad).has_value());
  EXPECT_FALSE(TypeParam::from_matrix(M::Zero()).has_value());
  EXPECT_TRUE(TypeParam::from_matrix_projected(bad).is_approx(TypeParam(), 0));
}

TYPED_TEST(Sim3Test, AutodiffDerivativesAtTheIdentityAreExact) {
  // d exp(x) / dx_i at x = 0 is hat(e_i) exactly: the series branch, no 0/0.
  using S = typename TestFixture::S;
  constexpr int D = TestFixture::D;
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<S, D, 1>>;
  using GA = Sim3<AD>;
  typename GA::Tangent x;
  for (int i = 0; i < D; ++i) x[i] = AD(S(0), D, i);
  const auto E = GA::exp(x).matrix();
  const auto w = GA::exp(x).log();
  for (int i = 0; i < D; ++i) {
    typename TypeParam::Tangent e = TypeParam::Tangent::Zero();
    e[i] = S(1);
    const auto H = TypeParam::hat(e);
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(E(r, c).derivatives()[i], H(r, c)) << r << "," << c;
    for (int j = 0; j < D; ++j) EXPECT_EQ(w[j].derivatives()[i], S(i == j ? 1 : 0));
  }
  // Away from 0 (the closed forms, expm1 through tanh): d exp(y) / dy_i =
  // exp(y) hat(J_r(y) e_i), with J_r computed in S.
  typename GA::Tangent y;
  typename TypeParam::Tangent yv;
  yv << S(0.3), S(-0.2), S(0.5), S(0.4), S(0.1), S(-0.7), S(0.8);
  for (int i = 0; i < D; ++i) y[i] = AD(yv[i], D, i);
  const auto Ey = GA::exp(y).matrix();
  const Eigen::Matrix<LD, 4, 4> G = to_ld(TypeParam::exp(yv).matrix());
  const auto Jr = TypeParam::right_jacobian(yv);
  for (int i = 0; i < D; ++i) {
    const typename TypeParam::Tangent col = Jr.col(i);
    const Eigen::Matrix<LD, 4, 4> ref = G * to_ld(TypeParam::hat(col));
    Eigen::Matrix<LD, 4, 4> got;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) got(r, c) = static_cast<LD>(Ey(r, c).derivatives()[i]);
    EXPECT_TRUE(near<S>(got, ref, kExp)) << i;
  }
}

TEST(Sim3, CoefficientsAcrossTheCutoffs) {
  // A, B, C on both sides of each cutoff, one ulp apart, against long double
  // values of the closed forms (far from 0, where they are accurate): the
  // series and the weighted forms agree to rounding.
  using S = double;
  const S cut = chasles::Thresholds<S>::taylor_theta2;
  auto reference = [](LD s, LD t) {
    // The double series to high order, in long double (|s| and t are small here).
    LD a = 0, b = 0, c = 0, fact = 1;
    for (int m = 0; m < 30; ++m) {
      if (m > 0) fact *= m;
      LD ib = 0, ic = 0, tj = 1, f1 = 1, f2 = 2;  // (2j+1)!, (2j+2)!
      for (int j = 0; j < 10; ++j) {
        if (j > 0) {
          tj *= -t;
          f1 *= (2 * j) * (2 * j + 1);
          f2 *= (2 * j + 1) * (2 * j + 2);
        }
        ib += tj / (f1 * (2 * j + m + 2));
        ic += tj / (f2 * (2 * j + m + 3));
      }
      const LD sm = std::pow(s, LD(m)) / fact;
      a += sm / (m + 1);
      b += sm * ib;
      c += sm * ic;
    }
    return Eigen::Matrix<LD, 3, 1>(a, b, c);
  };
  const auto c1 = cutoff_sides<S>(cut), c2 = cutoff_sides<S>(cut, 2);
  const std::vector<std::pair<S, S>> points = {{0, c1.first * c1.first},
                                               {0, c1.second * c1.second},
                                               {c1.first, 0},
                                               {c1.second, 0},
                                               {-c1.first, 0},
                                               {-c1.second, 0},
                                               {c2.first, c2.first * c2.first},
                                               {c2.second, c2.second * c2.second},
                                               {-c2.second, c2.second * c2.second},
                                               {1e-3, 1e-6},
                                               {3e-3, 9e-6}};
  for (const auto& p : points) {
    const auto k = chasles::detail::sim3_coefficients<S>(p.first, p.second);
    const auto ref = reference(p.first, p.second);
    EXPECT_TRUE(near_scalar<S>(k.a, ref[0], 2)) << p.first << " " << p.second;
    // B and C reach W multiplied by theta and theta^2; their own error is
    // bounded by eps / r and eps / r^2 (sim3.hpp): check what reaches W.
    const LD th = std::sqrt(LD(p.second));
    EXPECT_TRUE(near_scalar<S>(k.b * th, ref[1] * th, 2)) << p.first << " " << p.second;
    EXPECT_TRUE(near_scalar<S>(k.c * p.second, ref[2] * LD(p.second), 2)) << p.first << " " << p.second;
    EXPECT_TRUE(near_scalar<S>(k.e, std::exp(LD(p.first)), 2));
  }
}

}  // namespace
