// The laws every Lie group obeys, as one typed suite over {SO3, SE3} x
// {float, double}, on the shared samples (identity, tiny angles, 1e-8, near
// pi, exactly pi, random; fixed seeds). Each law is checked against an
// independent computation where one exists: products, inverses and
// conjugations of the plain 3x3 / 4x4 matrices in long double, Eigen's
// JacobiSVD for the nearest rotation, closed forms written here.
//
// Tolerances are k * eps of the scalar under test times the scale of the
// data (support/group_traits.hpp, `near`). The k used below:
//   kOp    = 4:  one product, inverse or action: every entry is a dot product
//              of at most 3 terms plus one addition, error <= gamma_4.
//   kChain = 16: two to four such operations in a row (associativity,
//              conjugation, adjoint products), each adding a few eps.
//   kExp   = 16: exp or log alone, "a few ulps" (design.md) with margin, and
//              an exp/log round trip (exp to a few ulps, then log).
//   kProj  = 16: the nearest rotation, a converged 4x4 Jacobi eigenvector
//              (its error is eps * |M| / gap; the gap enters explicitly).
// The angle below which log(exp(x)) must give back x: pi - kPiMargin * eps.
// Closer to pi, the matrix exp(x), correct to a few eps, may be the rotation
// of angle pi - tiny or of angle pi + tiny, i.e. of angle pi - tiny about -w:
// both logs are correct; the law checked there is exp(log(g)) = g.
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <chasles/chasles.hpp>

#include "support/group_traits.hpp"
#include "support/samples.hpp"
#include "support/scalar_types.hpp"

namespace {

using namespace chasles_test;
using chasles::SE3;
using chasles::SO3;

constexpr LD kOp = 4;
constexpr LD kChain = 16;
constexpr LD kExp = 16;
constexpr LD kProj = 16;
constexpr LD kPiMargin = 16;

template <typename Derived>
bool all_equal(const Eigen::MatrixBase<Derived>& a, const Eigen::MatrixBase<Derived>& b) {
  return (a.array() == b.array()).all();
}

template <typename G>
class GroupLaws : public ::testing::Test {
 public:
  using Traits = GroupTraits<G>;
  using S = typename Traits::Scalar;
  using Tangent = typename Traits::Tangent;
  using Matrix = typename Traits::Matrix;
  using Point = typename Traits::Point;
  using M3 = Eigen::Matrix<S, 3, 3>;
  static constexpr int kDim = Traits::kDim;
  using MatrixLD = Eigen::Matrix<LD, kDim, kDim>;

  std::vector<Tangent> xs = Traits::tangents();
  std::vector<G> gs = elements<G>();

  /// Deterministic partners of sample i, mixing special and random samples.
  const G& second(std::size_t i) const { return gs[(7 * i + 3) % gs.size()]; }
  const G& third(std::size_t i) const { return gs[(13 * i + 5) % gs.size()]; }
  const Tangent& other_tangent(std::size_t i) const { return xs[(11 * i + 2) % xs.size()]; }

  static MatrixLD ld(const G& g) { return to_ld(g.matrix()); }
};

struct GroupName {
  template <typename G>
  static std::string GetName(int) {
    std::string n = std::is_same<G, SO3<typename G::Scalar>>::value ? "SO3" : "SE3";
    return n + (std::is_same<typename G::Scalar, float>::value ? "f" : "d");
  }
};

using GroupTypes = ::testing::Types<SO3<float>, SO3<double>, SE3<float>, SE3<double>>;
TYPED_TEST_SUITE(GroupLaws, GroupTypes, GroupName);

// ---- group axioms -----------------------------------------------------------

TYPED_TEST(GroupLaws, Associativity) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (std::size_t i = 0; i < this->gs.size(); ++i) {
    const TypeParam &a = this->gs[i], &b = this->second(i), &c = this->third(i);
    const LD scale = T::scale(a) + T::scale(b) + T::scale(c);
    EXPECT_TRUE(near<S>(((a * b) * c).matrix(), (a * (b * c)).matrix(), kChain, scale)) << "sample " << i;
  }
}

TYPED_TEST(GroupLaws, IdentityIsNeutralExactly) {
  const TypeParam e = TypeParam::identity();
  EXPECT_TRUE(all_equal(e.matrix(), TestFixture::Matrix::Identity().eval()));
  EXPECT_TRUE(all_equal(TypeParam().matrix(), TestFixture::Matrix::Identity().eval()));
  for (const auto& g : this->gs) {
    // R * I and I * R are exact in IEEE arithmetic (products by 1 and 0).
    EXPECT_TRUE(all_equal((e * g).matrix(), g.matrix()));
    EXPECT_TRUE(all_equal((g * e).matrix(), g.matrix()));
  }
}

TYPED_TEST(GroupLaws, InverseOnBothSides) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  const auto I = TestFixture::Matrix::Identity().eval();
  for (const auto& g : this->gs) {
    // Two operations each (the inverse, then a product or a second inverse).
    EXPECT_TRUE(near<S>((g * g.inverse()).matrix(), I, kChain, T::scale(g)));
    EXPECT_TRUE(near<S>((g.inverse() * g).matrix(), I, kChain, T::scale(g)));
    EXPECT_TRUE(near<S>(g.inverse().inverse().matrix(), g.matrix(), kChain, T::scale(g)));
  }
}

TYPED_TEST(GroupLaws, InverseMatchesMatrixInverse) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (const auto& g : this->gs) {
    // g.inverse() uses R^T, the exact inverse of M = R only when M is exactly
    // orthogonal: M^-1 = M^T (M M^T)^-1 differs from M^T by about the defect
    // of M (a few eps for a computed exp), which the tolerance adds.
    const typename TestFixture::MatrixLD inv = this->ld(g).inverse();
    const LD defect = reference_rotation_defect(T::rotation_block(g.matrix()));
    EXPECT_TRUE(near<S>(g.inverse().matrix(), inv, kOp + 2 * defect / eps<S>(), T::scale(g)));
  }
}

TYPED_TEST(GroupLaws, MatrixOfCompositionIsProductOfMatrices) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (std::size_t i = 0; i < this->gs.size(); ++i) {
    const TypeParam &a = this->gs[i], &b = this->second(i);
    const typename TestFixture::MatrixLD ab = this->ld(a) * this->ld(b);
    EXPECT_TRUE(near<S>((a * b).matrix(), ab, kOp, T::scale(a) + T::scale(b)));
    TypeParam c = a;
    c *= b;
    EXPECT_TRUE(all_equal(c.matrix(), (a * b).matrix())) << "*= differs from *";
  }
}

TYPED_TEST(GroupLaws, ActionMatchesMatrixTimesHomogeneousPoint) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  using P = typename TestFixture::Point;
  const std::vector<P> points = {P::Zero(), P(1, 0, 0), P(S(0.3), S(-2), S(5)), P(S(1e3), S(-2e2), S(7))};
  for (const auto& g : this->gs)
    for (const P& p : points) {
      const auto ref = T::dehomogenize(this->ld(g) * T::homogeneous(p));
      const LD scale = T::scale(g) + max_abs(p);
      EXPECT_TRUE(near<S>(g.act(p), ref, kOp, scale));
      EXPECT_TRUE(all_equal(g.act(p), P(g * p)));
    }
}

// ---- exp and log --------------------------------------------------------------

TYPED_TEST(GroupLaws, ExpOfZeroIsIdentityAndLogOfIdentityIsZeroExactly) {
  using Tangent = typename TestFixture::Tangent;
  EXPECT_TRUE(all_equal(TypeParam::exp(Tangent::Zero()).matrix(), TestFixture::Matrix::Identity().eval()));
  EXPECT_TRUE(all_equal(TypeParam::identity().log(), Tangent::Zero().eval()));
}

TYPED_TEST(GroupLaws, LogOfExpIsIdentityBelowPi) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  int checked = 0;
  for (const auto& x : this->xs) {
    if (!(rotation_angle<TypeParam>(x) < kPi - kPiMargin * eps<S>())) continue;
    ++checked;
    EXPECT_TRUE(near<S>(TypeParam::exp(x).log(), x, kExp, T::scale(x))) << "x = " << x.transpose();
  }
  EXPECT_GT(checked, 60);
}

TYPED_TEST(GroupLaws, AtPiLogIsAValidAngleOfPi) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  int checked = 0;
  for (const auto& x : this->xs) {
    const LD angle = rotation_angle<TypeParam>(x);
    if (angle < kPi - kPiMargin * eps<S>()) continue;
    ++checked;
    const TypeParam g = TypeParam::exp(x);
    const typename TestFixture::Tangent y = g.log();
    EXPECT_TRUE(near_scalar<S>(rotation_angle<TypeParam>(y), kPi, kExp)) << "x = " << x.transpose();
    EXPECT_TRUE(near<S>(TypeParam::exp(y).matrix(), g.matrix(), kExp, T::scale(x))) << "x = " << x.transpose();
    // The axis is w or -w: either sign is a correct log at pi.
    const auto w = to_ld(T::rotation_part(x)), u = to_ld(T::rotation_part(y));
    const bool same = max_abs_diff(u, w) <= max_abs_diff(u, -w);
    EXPECT_TRUE(near<S>(u, same ? w : Eigen::Matrix<LD, 3, 1>(-w), kExp, kPi)) << "x = " << x.transpose();
  }
  // Along each of the 4 sample axes: exactly pi (and pi - 1e-6 in float,
  // which is within kPiMargin float eps of pi).
  EXPECT_GE(checked, 4);
}

TYPED_TEST(GroupLaws, ExpOfLogIsIdentity) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (const auto& g : this->gs) EXPECT_TRUE(near<S>(TypeParam::exp(g.log()).matrix(), g.matrix(), kExp, T::scale(g)));
  // And on products, which are not exp of a sample.
  for (std::size_t i = 0; i < this->gs.size(); ++i) {
    const TypeParam g = this->gs[i] * this->second(i);
    EXPECT_TRUE(near<S>(TypeParam::exp(g.log()).matrix(), g.matrix(), kExp, T::scale(g)));
  }
}

// ---- Lie algebra --------------------------------------------------------------

/// The hat matrix written out from the seed: [w] = [[0, -w3, w2], [w3, 0,
/// -w1], [-w2, w1, 0]], and [xi] = [[ [w], v ], [0, 0]].
template <typename S>
Eigen::Matrix<S, 3, 3> skew(const Eigen::Matrix<S, 3, 1>& w) {
  Eigen::Matrix<S, 3, 3> W;
  W << 0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0;
  return W;
}
template <typename S>
Eigen::Matrix<S, 3, 3> expected_hat(const Eigen::Matrix<S, 3, 1>& w) {
  return skew(w);
}
template <typename S>
Eigen::Matrix<S, 4, 4> expected_hat(const Eigen::Matrix<S, 6, 1>& xi) {
  Eigen::Matrix<S, 4, 4> X = Eigen::Matrix<S, 4, 4>::Zero();
  X.template topLeftCorner<3, 3>() = skew(Eigen::Matrix<S, 3, 1>(xi.template tail<3>()));
  X.template topRightCorner<3, 1>() = xi.template head<3>();
  return X;
}

TYPED_TEST(GroupLaws, HatVeeRoundTrip) {
  using T = typename TestFixture::Traits;
  using S = typename TestFixture::S;
  using Matrix = typename TestFixture::Matrix;
  for (const auto& x : this->xs) {
    const Matrix X = T::hat(x);
    EXPECT_TRUE(all_equal(X, expected_hat<S>(x)));
    EXPECT_TRUE(all_equal(T::vee(X), x));  // halves of +-w: exact
    EXPECT_TRUE(all_equal(T::hat(T::vee(X)), X));
    // vee reads the antisymmetric part: a symmetric addition changes nothing.
    Matrix Y = X;
    Y.template topLeftCorner<3, 3>() += (Eigen::Matrix<S, 3, 3>() << 1, 2, 3, 2, 5, 6, 3, 6, 9).finished();
    EXPECT_TRUE(near<S>(T::vee(Y), x, kOp, T::scale(x) + 9));
  }
}

TYPED_TEST(GroupLaws, HatActsAsVelocityOfPoints) {
  // [w] p = w x p; [xi] (p, 1) = (w x p + v, 0).
  using T = typename TestFixture::Traits;
  using S = typename TestFixture::S;
  using P = typename TestFixture::Point;
  const P p(S(0.5), S(-1.5), S(2));
  for (const auto& x : this->xs) {
    const auto w = to_ld(T::rotation_part(x));
    Eigen::Matrix<LD, 3, 1> expected = w.cross(to_ld(p));
    if constexpr (T::kDim == 4) expected += to_ld(x.template head<3>());
    const auto got = (to_ld(T::hat(x)) * T::homogeneous(p)).eval();
    EXPECT_TRUE(near<S>(got.template head<3>(), expected, kOp, T::scale(x) * 2));
    if constexpr (T::kDim == 4) {
      EXPECT_EQ(got[3], LD(0));
    }
  }
}

TYPED_TEST(GroupLaws, AdjointOfProductIsProductOfAdjoints) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (std::size_t i = 0; i < this->gs.size(); ++i) {
    const TypeParam &a = this->gs[i], &b = this->second(i);
    const auto ref = (to_ld(a.adjoint()) * to_ld(b.adjoint())).eval();
    EXPECT_TRUE(near<S>((a * b).adjoint(), ref, kChain, T::scale(a) + T::scale(b))) << "sample " << i;
  }
}

TYPED_TEST(GroupLaws, AdjointOfInverseIsInverseOfAdjoint) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (const auto& g : this->gs) {
    const auto inv = to_ld(g.adjoint()).inverse().eval();
    EXPECT_TRUE(near<S>(g.inverse().adjoint(), inv, kChain, T::scale(g)));
  }
}

TYPED_TEST(GroupLaws, AdjointIsConjugationOfHat) {
  // Ad_g x = (G [x] G^-1)^vee, with G the matrix of g, in long double.
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (std::size_t i = 0; i < this->gs.size(); ++i) {
    const TypeParam& g = this->gs[i];
    const auto& x = this->other_tangent(i);
    const auto G = this->ld(g);
    const auto C = (G * to_ld(T::hat(x)) * G.inverse()).eval();
    const typename TestFixture::Tangent got = g.adjoint() * x;
    // The conjugate is in the algebra; its vee, read off directly.
    Eigen::Matrix<LD, T::kDoF, 1> ref;
    const Eigen::Matrix<LD, 3, 1> w(C(2, 1), C(0, 2), C(1, 0));
    if constexpr (T::kDim == 4) {
      ref << C.template topRightCorner<3, 1>(), w;
    } else {
      ref = w;
    }
    EXPECT_TRUE(near<S>(got, ref, kChain, T::scale(g) * T::scale(x))) << "sample " << i;
  }
}

TYPED_TEST(GroupLaws, ConjugateOfExpIsExpOfAdjoint) {
  // g exp(x) g^-1 = exp(Ad_g x).
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (std::size_t i = 0; i < this->gs.size(); ++i) {
    const TypeParam& g = this->gs[i];
    const auto& x = this->other_tangent(i);
    const typename TestFixture::Tangent adx = g.adjoint() * x;
    const LD scale = T::scale(g) * T::scale(x) + T::scale(g);
    EXPECT_TRUE(near<S>((g * TypeParam::exp(x) * g.inverse()).matrix(), TypeParam::exp(adx).matrix(), kChain, scale))
        << "sample " << i;
  }
}

TYPED_TEST(GroupLaws, BracketIsMatrixCommutator) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (std::size_t i = 0; i < this->xs.size(); ++i) {
    const auto& a = this->xs[i];
    const auto& b = this->other_tangent(i);
    const auto A = to_ld(T::hat(a)), B = to_ld(T::hat(b));
    const auto C = (A * B - B * A).eval();
    Eigen::Matrix<LD, T::kDoF, 1> ref;
    const Eigen::Matrix<LD, 3, 1> w(C(2, 1), C(0, 2), C(1, 0));
    if constexpr (T::kDim == 4) {
      ref << C.template topRightCorner<3, 1>(), w;
      EXPECT_EQ(max_abs(C.template bottomRows<1>()), LD(0));
    } else {
      ref = w;
    }
    // The commutator is skew in its rotation block: it is in the algebra.
    EXPECT_EQ(max_abs(C.template topLeftCorner<3, 3>() + C.template topLeftCorner<3, 3>().transpose()), LD(0));
    const LD scale = T::scale(a) * T::scale(b);
    EXPECT_TRUE(near<S>(T::bracket(a, b), ref, kOp, scale)) << "sample " << i;
    EXPECT_TRUE(near<S>(T::ad(a) * b, ref, kOp, scale)) << "sample " << i;
    EXPECT_TRUE(all_equal(T::bracket(a, b), typename TestFixture::Tangent(-T::bracket(b, a))));
  }
}

// ---- construction from matrices -----------------------------------------------

TYPED_TEST(GroupLaws, CheckedFromMatrixAcceptsElementsUnchanged) {
  using T = typename TestFixture::Traits;
  static_assert(noexcept(TypeParam::from_matrix(std::declval<typename TestFixture::Matrix>())));
  static_assert(noexcept(TypeParam::from_matrix_projected(std::declval<typename TestFixture::Matrix>())));
  for (const auto& g : this->gs) {
    const auto r = T::from_matrix(g.matrix());
    ASSERT_TRUE(r.has_value());
    EXPECT_TRUE(all_equal(r->matrix(), g.matrix()));
  }
}

TYPED_TEST(GroupLaws, CheckedFromMatrixRefusesDefectAboveTolerance) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  using Matrix = typename TestFixture::Matrix;
  const S tol = chasles::ThresholdsOf<S>::rotation_tolerance;
  for (const auto& g : this->gs) {
    // Entry (0, 0) off by d moves M^T M by at least d * max_j |R_0j| >=
    // d / sqrt(3) and at most 2d + d^2, and det M by d * R_00: defect in
    // [d / sqrt(3), 2d + d^2].
    Matrix bad = g.matrix(), good = g.matrix();
    bad(0, 0) += 10 * tol;
    good(0, 0) += tol / 10;
    EXPECT_FALSE(T::from_matrix(bad).has_value());
    EXPECT_GT(T::defect(bad), tol);
    EXPECT_TRUE(T::from_matrix(good).has_value());
    // An explicit tolerance overrides the default.
    EXPECT_TRUE(T::from_matrix(bad, S(100) * tol).has_value());
    EXPECT_FALSE(T::from_matrix(good, tol / S(1000)).has_value());
  }
  // A reflection and a scaled rotation: refused.
  EXPECT_FALSE(T::from_matrix(T::with_rotation_block(Matrix::Identity(), Eigen::Matrix<S, 3, 1>(1, 1, -1).asDiagonal()))
                   .has_value());
  EXPECT_FALSE(T::from_matrix(T::with_rotation_block(Matrix::Identity(), Eigen::Matrix<S, 3, 3>::Identity() * S(1.01)))
                   .has_value());
  if constexpr (T::kDim == 4) {
    // The bottom row of a 4x4 must be (0, 0, 0, 1).
    Matrix m = Matrix::Identity();
    m(3, 0) = 10 * tol;
    EXPECT_FALSE(T::from_matrix(m).has_value());
    EXPECT_EQ(T::defect(m), m(3, 0));
    m(3, 0) = 0;
    m(3, 3) = 1 + tol / 10;
    EXPECT_TRUE(T::from_matrix(m).has_value());
  }
}

// A regression test: rotation_defect and transform_defect once took the
// maximum with `if (!(e <= d)) d = e`, which lets a NaN entry replace d but
// lets the next finite entry replace a NaN d again, so the defect of
// diag(inf, 1, 1) came out 0 and from_matrix accepted it (fixed in 808373c:
// the defect of a non-finite matrix is +inf).
TYPED_TEST(GroupLaws, CheckedFromMatrixRefusesNonFinite) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  using Matrix = typename TestFixture::Matrix;
  const S inf = std::numeric_limits<S>::infinity(), nan = std::numeric_limits<S>::quiet_NaN();
  // The identity with one entry made non-finite (for a 4x4: the translation
  // and the bottom row too).
  std::ostringstream accepted;
  int n_accepted = 0, n_cases = 0;
  for (int i = 0; i < T::kDim; ++i)
    for (int j = 0; j < T::kDim; ++j)
      for (const S bad : {inf, -inf, nan}) {
        Matrix M = Matrix::Identity();
        M(i, j) = bad;
        ++n_cases;
        const S d = T::defect(M);
        // Refused whatever the tolerance; the defect is +inf (documented).
        if (T::from_matrix(M).has_value() || T::from_matrix(M, S(1)).has_value() || !(d == inf)) {
          ++n_accepted;
          accepted << " M(" << i << "," << j << ")=" << bad << " (defect " << d << ")";
        }
      }
  EXPECT_EQ(n_accepted, 0) << n_accepted << " of " << n_cases << " non-finite matrices accepted:" << accepted.str();
}

TYPED_TEST(GroupLaws, DefectValues) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  using Matrix = typename TestFixture::Matrix;
  using M3 = typename TestFixture::M3;
  // Exactly 0 for rotations with exact entries.
  EXPECT_EQ(T::defect(Matrix::Identity()), S(0));
  M3 quarter;
  quarter << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  EXPECT_EQ(T::defect(T::with_rotation_block(Matrix::Identity(), quarter)), S(0));
  // Exactly 2 for the reflection diag(1, 1, -1): M^T M = I, det M = -1.
  EXPECT_EQ(T::defect(T::with_rotation_block(Matrix::Identity(), Eigen::Matrix<S, 3, 1>(1, 1, -1).asDiagonal())), S(2));
  // One entry of I off by d: M^T M - I = diag(2d + d^2, 0, 0), det - 1 = d.
  for (S d : {S(1e-6), S(1e-3), S(0.1)}) {
    Matrix M = Matrix::Identity();
    M(0, 0) += d;
    const LD dl = LD(M(0, 0)) - 1;
    EXPECT_TRUE(near_scalar<S>(T::defect(M), 2 * dl + dl * dl, kOp)) << "d = " << d;
  }
  // (1 + d) R: M^T M - I = (2d + d^2) I, det - 1 = 3d + 3d^2 + d^3 (the larger).
  // Every sample, and perturbed samples, against the long-double reference.
  std::mt19937_64 rng(kSeed + 7);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (const auto& g : this->gs) {
    const M3 R = T::rotation_block(g.matrix());
    EXPECT_LE(T::defect(g.matrix()), kExp * eps<S>());  // exp is a rotation to a few eps
    EXPECT_TRUE(near_scalar<S>(T::defect(g.matrix()), reference_rotation_defect(R), kOp));
    const S d = S(1e-3);
    const M3 scaled = R * (1 + d);
    const LD dl = reference_rotation_defect(scaled);
    EXPECT_TRUE(near_scalar<S>(dl, 3 * d + 3 * d * d + d * d * d, kChain));
    EXPECT_TRUE(near_scalar<S>(T::defect(T::with_rotation_block(g.matrix(), scaled)), dl, kOp));
    M3 N;
    for (int k = 0; k < 9; ++k) N(k / 3, k % 3) = S(n01(rng));
    const M3 perturbed = R + S(1e-2) * N;
    EXPECT_TRUE(near_scalar<S>(T::defect(T::with_rotation_block(g.matrix(), perturbed)),
                               reference_rotation_defect(perturbed), kOp));
    // A reflection of a rotation: M^T M = I, det = -1: 2 up to rounding.
    const M3 reflected = R * Eigen::Matrix<S, 3, 1>(1, -1, 1).asDiagonal();
    EXPECT_TRUE(near_scalar<S>(T::defect(T::with_rotation_block(g.matrix(), reflected)), 2, kOp));
  }
}

/// The nearest rotation by the SVD, in long double: U diag(1, 1, det(U V^T))
/// V^T. `gap` gets s2 + det(U V^T) s3: the minimizer is unique iff gap > 0,
/// and the eigenvector the library computes is accurate to eps |M| / gap.
inline Eigen::Matrix<LD, 3, 3> svd_nearest_rotation(const Eigen::Matrix<LD, 3, 3>& M, LD* gap) {
  Eigen::JacobiSVD<Eigen::Matrix<LD, 3, 3>> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix<LD, 3, 3> U = svd.matrixU(), V = svd.matrixV();
  const LD d = (U * V.transpose()).determinant() > 0 ? LD(1) : LD(-1);
  *gap = svd.singularValues()[1] + d * svd.singularValues()[2];
  return U * Eigen::Matrix<LD, 3, 1>(1, 1, d).asDiagonal() * V.transpose();
}

/// 3x3 test matrices for the projection, with a name: near rotations,
/// general matrices of both determinant signs, a scaled rotation, a pure
/// reflection (nearest rotation not unique), rank 2 (unique), rank 1 (not
/// unique), zero.
template <typename S>
std::vector<std::pair<std::string, Eigen::Matrix<S, 3, 3>>> projection_cases() {
  using M3 = Eigen::Matrix<S, 3, 3>;
  std::mt19937_64 rng(kSeed + 11);
  std::normal_distribution<double> n01(0.0, 1.0);
  auto gauss = [&] {
    Eigen::Matrix3d N;
    for (int k = 0; k < 9; ++k) N(k / 3, k % 3) = n01(rng);
    return N;
  };
  auto rot = [&] {
    return SO3<double>::exp(std::uniform_real_distribution<double>(0, 3.1)(rng) * random_unit<double>(rng)).matrix();
  };
  std::vector<std::pair<std::string, M3>> out;
  auto add = [&out](const std::string& name, const Eigen::Matrix3d& M) {
    out.emplace_back(name, M3(M.template cast<S>()));
  };
  for (int i = 0; i < 8; ++i) {
    const std::string k = " " + std::to_string(i);
    add("near rotation" + k, rot() + 1e-3 * gauss());
    add("off rotation" + k, rot() + 0.3 * gauss());
    Eigen::Matrix3d G = gauss();
    if (G.determinant() < 0) G = -G;
    add("general det>0" + k, G);
    add("general det<0" + k, -G);
    add("scaled rotation" + k, 5.0 * rot());
    add("reflection" + k, rot() * Eigen::Vector3d(1, 1, -1).asDiagonal());
    add("det<0 diag(3,2,-1)" + k, rot() * Eigen::Vector3d(3, 2, -1).asDiagonal() * rot());
    add("rank 2" + k, rot() * Eigen::Vector3d(2, 1, 0).asDiagonal() * rot());
    add("rank 1" + k, random_unit<double>(rng) * random_unit<double>(rng).transpose());
  }
  out.emplace_back("zero", M3::Zero());
  out.emplace_back("reflection diag(1,1,-1)", Eigen::Matrix<S, 3, 1>(1, 1, -1).asDiagonal());
  out.emplace_back("diag(-1,-1,-1)", -M3::Identity());
  return out;
}

TYPED_TEST(GroupLaws, ProjectedFromMatrixIsIdentityOnElements) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (const auto& g : this->gs) {
    const TypeParam h = T::from_matrix_projected(g.matrix());
    EXPECT_TRUE(near<S>(h.matrix(), g.matrix(), kProj, T::scale(g)));
    if constexpr (T::kDim == 4) {
      EXPECT_TRUE(all_equal(h.translation(), g.translation()));
    }
  }
}

TYPED_TEST(GroupLaws, ProjectedFromMatrixIsNearestRotation) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  using Matrix = typename TestFixture::Matrix;
  using M3 = typename TestFixture::M3;
  int unique = 0;
  for (const auto& [name, M] : projection_cases<S>()) {
    // Embedded in a 4x4 for SE3, with a translation and a bottom row that
    // from_matrix_projected must keep and ignore.
    Matrix big = T::with_rotation_block(Matrix::Identity(), M);
    if constexpr (T::kDim == 4) {
      big.template topRightCorner<3, 1>() << S(1.5), S(-20), S(300);
      big.template bottomRows<1>() << S(7), S(8), S(9), S(10);
    }
    const M3 R = T::rotation_block(T::from_matrix_projected(big).matrix());
    if constexpr (T::kDim == 4) {
      const auto g = T::from_matrix_projected(big);
      EXPECT_TRUE(all_equal(g.translation(), typename TestFixture::Point(big.template topRightCorner<3, 1>())));
      EXPECT_TRUE(all_equal(R, SO3<S>::from_matrix_projected(M).matrix()));
    }
    const LD size = std::max(LD(1), to_ld(M).norm());
    // A rotation to working precision, whatever M is.
    EXPECT_LE(reference_rotation_defect(R), kProj * eps<S>()) << name;
    LD gap = 0;
    const Eigen::Matrix<LD, 3, 3> ref = svd_nearest_rotation(to_ld(M), &gap);
    // As near to M as the SVD's answer (Frobenius norm), always.
    const LD d_lib = (to_ld(R) - to_ld(M)).norm(), d_ref = (ref - to_ld(M)).norm();
    EXPECT_LE(d_lib, d_ref + kProj * eps<S>() * size)
        << name << ": |R - M| = " << double(d_lib) << ", SVD's " << double(d_ref);
    // The same rotation where the nearest is unique (gap well above rounding).
    if (gap > LD(1e-2) * size) {
      ++unique;
      EXPECT_TRUE(near<S>(R, ref, kProj * size / gap)) << name << " (gap " << double(gap) << ")";
    }
  }
  // 7 of the 9 kinds of case have a unique nearest rotation (not the pure
  // reflections, rank 1, zero).
  EXPECT_GE(unique, 50);
}

TYPED_TEST(GroupLaws, NormalizedRemovesDrift) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  using M3 = typename TestFixture::M3;
  std::mt19937_64 rng(kSeed + 13);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (std::size_t i = 0; i < this->gs.size(); ++i) {
    const TypeParam& g = this->gs[i];
    // Already valid: unchanged to rounding.
    EXPECT_TRUE(near<S>(g.normalized().matrix(), g.matrix(), kProj, T::scale(g)));
    // Drifted by 1e-4: normalized() is the projection of the drifted matrix.
    M3 N;
    for (int k = 0; k < 9; ++k) N(k / 3, k % 3) = S(n01(rng));
    const auto drifted =
        T::from_matrix_unchecked(T::with_rotation_block(g.matrix(), M3(T::rotation_block(g.matrix()) + S(1e-4) * N)));
    const TypeParam n = drifted.normalized();
    EXPECT_TRUE(all_equal(n.matrix(), T::from_matrix_projected(drifted.matrix()).matrix()));
    EXPECT_LE(reference_rotation_defect(T::rotation_block(n.matrix())), kProj * eps<S>());
    EXPECT_TRUE(T::from_matrix(n.matrix()).has_value());
  }
  // Drift accumulated by many compositions.
  TypeParam acc = TypeParam::identity();
  for (int k = 0; k < 2000; ++k) acc = acc * this->gs[(k % (this->gs.size() - 1)) + 1];
  const LD before = reference_rotation_defect(T::rotation_block(acc.matrix()));
  const LD after = reference_rotation_defect(T::rotation_block(acc.normalized().matrix()));
  EXPECT_LE(after, kProj * eps<S>()) << "defect before " << double(before);
  EXPECT_TRUE(near<S>(acc.normalized().matrix(), acc.matrix(), 2 * before / eps<S>() + kProj, T::scale(acc)));
}

// ---- interpolation, casts, comparison -------------------------------------------

TYPED_TEST(GroupLaws, InterpolateEndpointsAndMidpoint) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  for (std::size_t i = 0; i < this->gs.size(); ++i) {
    const TypeParam &a = this->gs[i], &b = this->second(i);
    const LD scale = T::scale(a) + T::scale(b);
    EXPECT_TRUE(all_equal(chasles::interpolate(a, b, S(0)).matrix(), a.matrix())) << "sample " << i;
    EXPECT_TRUE(near<S>(chasles::interpolate(a, b, S(1)).matrix(), b.matrix(), kChain, scale)) << "sample " << i;
    const TypeParam mid = chasles::interpolate(a, b, S(0.5));
    const auto first = (a.inverse() * mid).log(), second = (mid.inverse() * b).log();
    // The two halves are the same motion: log(a^-1 mid) = log(mid^-1 b) =
    // log(a^-1 b) / 2, so in particular d(a, mid) = d(mid, b).
    EXPECT_TRUE(near<S>(first, second, kChain, scale * scale)) << "sample " << i;
    EXPECT_TRUE(near_scalar<S>(to_ld(first).norm(), to_ld(second).norm(), kChain, scale * scale)) << "sample " << i;
    const typename TestFixture::Tangent half = (a.inverse() * b).log() * S(0.5);
    EXPECT_TRUE(near<S>(first, half, kChain, scale * scale)) << "sample " << i;
  }
}

template <typename G>
struct Wider;
template <>
struct Wider<SO3<float>> {
  using type = SO3<double>;
};
template <>
struct Wider<SO3<double>> {
  using type = SO3<long double>;
};
template <>
struct Wider<SE3<float>> {
  using type = SE3<double>;
};
template <>
struct Wider<SE3<double>> {
  using type = SE3<long double>;
};

TYPED_TEST(GroupLaws, CastRoundTrip) {
  using S = typename TestFixture::S;
  using Wide = typename Wider<TypeParam>::type;
  using WS = typename Wide::Scalar;
  for (const auto& g : this->gs) {
    const Wide w = g.template cast<WS>();
    EXPECT_TRUE(all_equal(to_ld(w.matrix()), to_ld(g.matrix())));  // widening is exact
    EXPECT_TRUE(all_equal(w.template cast<S>().matrix(), g.matrix()));
    EXPECT_TRUE(all_equal(g.template cast<S>().matrix(), g.matrix()));
    // To float: each entry rounded once.
    const auto f = g.template cast<float>();
    for (int k = 0; k < g.matrix().size(); ++k) EXPECT_EQ(f.matrix()(k), static_cast<float>(g.matrix()(k)));
  }
}

TYPED_TEST(GroupLaws, IsApproxTrueAndFalse) {
  using S = typename TestFixture::S;
  using T = typename TestFixture::Traits;
  using Tangent = typename TestFixture::Tangent;
  const S tol = S(1e-4);
  for (std::size_t i = 0; i < this->gs.size(); ++i) {
    const TypeParam& g = this->gs[i];
    EXPECT_TRUE(g.is_approx(g, 0));
    // A rotation by delta about x changes some entry of R by at least
    // delta / sqrt(3) (R [e_x] has the columns R e_z and -R e_y), at most delta.
    Tangent dx = Tangent::Zero();
    dx[T::kDoF - 3] = 100 * tol;
    EXPECT_FALSE(g.is_approx(g * TypeParam::exp(dx), tol)) << "sample " << i;
    dx[T::kDoF - 3] = tol / 100;
    EXPECT_TRUE(g.is_approx(g * TypeParam::exp(dx), tol)) << "sample " << i;
    EXPECT_TRUE((g * TypeParam::exp(dx)).is_approx(g, tol)) << "symmetric";
  }
  typename TestFixture::Matrix nan = TestFixture::Matrix::Identity();
  nan(0, 1) = std::numeric_limits<S>::quiet_NaN();
  EXPECT_FALSE(T::from_matrix_unchecked(nan).is_approx(TypeParam::identity(), S(1)));
  EXPECT_FALSE(TypeParam::identity().is_approx(T::from_matrix_unchecked(nan), S(1)));
  if constexpr (T::kDim == 4) {
    // Translations compare relative to their size beyond 1.
    const SE3<S> far(SO3<S>(), typename TestFixture::Point(1000, 0, 0));
    const SE3<S> moved(SO3<S>(), typename TestFixture::Point(S(1000.5), 0, 0));
    EXPECT_TRUE(far.is_approx(moved, S(1e-3)));
    EXPECT_FALSE(far.is_approx(moved, S(1e-4)));
    const SE3<S> near0(SO3<S>(), typename TestFixture::Point(S(0.5), 0, 0));
    EXPECT_FALSE(SE3<S>().is_approx(near0, S(0.1)));
    EXPECT_TRUE(SE3<S>().is_approx(near0, S(0.5)));
  }
}

// ---- SO(3) only: quaternions -------------------------------------------------------

template <typename S>
class SO3Quaternion : public ::testing::Test {};
TYPED_TEST_SUITE(SO3Quaternion, ScalarTypes, ScalarName);

/// q and -q are the same rotation: the distance to the nearer of the two.
template <typename S>
::testing::AssertionResult same_quaternion(const Eigen::Quaternion<S>& q, const Eigen::Matrix<LD, 4, 1>& ref_wxyz,
                                           LD k) {
  const Eigen::Matrix<LD, 4, 1> got(q.w(), q.x(), q.y(), q.z());
  const bool plus = max_abs_diff(got, ref_wxyz) <= max_abs_diff(got, -ref_wxyz);
  return near<S>(got, plus ? ref_wxyz : Eigen::Matrix<LD, 4, 1>(-ref_wxyz), k);
}

TYPED_TEST(SO3Quaternion, MatchesAxisAngleClosedForm) {
  // exp(theta n) has the quaternion +-(cos(theta/2), sin(theta/2) n).
  using S = TypeParam;
  for (const auto& w : rotation_vectors<S>()) {
    const Eigen::Matrix<LD, 3, 1> wl = to_ld(w);
    const LD theta = wl.norm();
    Eigen::Matrix<LD, 4, 1> ref(1, 0, 0, 0);
    if (theta > 0) ref << std::cos(theta / 2), std::sin(theta / 2) * wl / theta;
    const auto q = SO3<S>::exp(w).quaternion();
    EXPECT_TRUE(same_quaternion<S>(q, ref, kExp)) << "w = " << w.transpose();
    EXPECT_TRUE(near_scalar<S>(to_ld(q.coeffs()).norm(), 1, kOp));
    // Shepperd's sign: the largest component is positive.
    EXPECT_GT(q.coeffs().maxCoeff(), -q.coeffs().minCoeff() * S(0.999));
  }
}

TYPED_TEST(SO3Quaternion, RoundTrips) {
  using S = TypeParam;
  std::mt19937_64 rng(kSeed + 17);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (const auto& g : elements<SO3<S>>()) {
    const auto q = g.quaternion();
    EXPECT_TRUE(near<S>(SO3<S>::from_quaternion(q).matrix(), g.matrix(), kExp));
    // Eigen's own conversion, in long double, as a second reference.
    const Eigen::Quaternion<LD> e(to_ld(g.matrix()));
    EXPECT_TRUE(same_quaternion<S>(q, Eigen::Matrix<LD, 4, 1>(e.w(), e.x(), e.y(), e.z()), kExp));
    // -q is the same rotation; a non-unit quaternion is normalized.
    const Eigen::Quaternion<S> neg(-q.w(), -q.x(), -q.y(), -q.z());
    EXPECT_TRUE(near<S>(SO3<S>::from_quaternion(neg).matrix(), g.matrix(), kExp));
    const Eigen::Quaternion<S> big(S(2.5) * q.w(), S(2.5) * q.x(), S(2.5) * q.y(), S(2.5) * q.z());
    EXPECT_TRUE(near<S>(SO3<S>::from_quaternion(big).matrix(), g.matrix(), kExp));
  }
  for (int i = 0; i < 64; ++i) {
    const double r[4] = {n01(rng), n01(rng), n01(rng), n01(rng)};
    const Eigen::Quaternion<S> q0(static_cast<S>(r[0]), static_cast<S>(r[1]), static_cast<S>(r[2]),
                                  static_cast<S>(r[3]));
    const Eigen::Matrix<LD, 4, 1> unit = Eigen::Matrix<LD, 4, 1>(q0.w(), q0.x(), q0.y(), q0.z()).normalized();
    const SO3<S> R = SO3<S>::from_quaternion(q0);
    EXPECT_TRUE(same_quaternion<S>(R.quaternion(), unit, kExp));
    // Against Eigen's quaternion-to-matrix, in long double.
    const Eigen::Quaternion<LD> ql(unit[0], unit[1], unit[2], unit[3]);
    EXPECT_TRUE(near<S>(R.matrix(), ql.toRotationMatrix(), kExp));
  }
  // Zero and non-finite quaternions: the identity, as documented.
  EXPECT_TRUE(all_equal(SO3<S>::from_quaternion(Eigen::Quaternion<S>(0, 0, 0, 0)).matrix(),
                        Eigen::Matrix<S, 3, 3>::Identity().eval()));
  EXPECT_TRUE(
      all_equal(SO3<S>::from_quaternion(Eigen::Quaternion<S>(std::numeric_limits<S>::quiet_NaN(), 0, 0, 0)).matrix(),
                Eigen::Matrix<S, 3, 3>::Identity().eval()));
}

}  // namespace
