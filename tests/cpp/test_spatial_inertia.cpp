// chasles::SpatialInertia, typed over float and double, against independent
// references in long double:
// - a cloud of point masses: its momentum sum_k m_k (v_k, r_k x v_k) and
//   kinetic energy sum_k 1/2 m_k |v_k|^2 (v_k = v + w x r_k), against G V
//   and 1/2 V^T G V of the inertia built from the cloud's mass, center of
//   mass and I_c = sum_k m_k (|d_k|^2 1 - d_k d_k^T), d_k = r_k - c;
// - the change of frame against the 6x6 product Ad_g^-T G Ad_g^-1 (Ad_g^-1
//   by LU in long double) and against the moved cloud;
// - the parallel-axis theorem: the rotational block of G is
//   I_c + m (|c|^2 1 - c c^T), the inertia about the origin;
// - the kinetic energy is the same in every frame;
// - is_physical on both sides of each condition.
// Tolerances: k * eps of the scalar under test times the data's scale
// (support/group_traits.hpp, `near`), k = 64: a handful of 3x3 products of
// entries of order 10 (each a few ulps).
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include <chasles/spatial_inertia.hpp>

#include "support/group_traits.hpp"
#include "support/scalar_types.hpp"

namespace {

using namespace chasles_test;
using chasles::RealOf;
using chasles::SE3;
using chasles::SpatialInertia;
using chasles::Twist;

using V3L = Eigen::Matrix<LD, 3, 1>;
using V6L = Eigen::Matrix<LD, 6, 1>;
using M3L = Eigen::Matrix<LD, 3, 3>;
using M6L = Eigen::Matrix<LD, 6, 6>;

constexpr LD kInertia = 64;

struct Cloud {
  std::vector<LD> m;
  std::vector<V3L> r;
};

Cloud random_cloud(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), um(0.1, 2.0);
  Cloud c;
  for (int k = 0; k < 5; ++k) {
    c.m.push_back(LD(um(rng)));
    c.r.push_back(V3L(LD(u(rng)) + 0.5L, LD(u(rng)), LD(u(rng)) - 0.3L));
  }
  return c;
}

/// (mass, com, I_c) of the cloud, in long double.
void cloud_parameters(const Cloud& c, LD& m, V3L& com, M3L& Ic) {
  m = 0;
  com.setZero();
  for (std::size_t k = 0; k < c.m.size(); ++k) {
    m += c.m[k];
    com += c.m[k] * c.r[k];
  }
  com /= m;
  Ic.setZero();
  for (std::size_t k = 0; k < c.m.size(); ++k) {
    const V3L d = c.r[k] - com;
    Ic += c.m[k] * (d.squaredNorm() * M3L::Identity() - d * d.transpose());
  }
}

template <typename S>
SpatialInertia<S> inertia_of(const Cloud& c) {
  LD m;
  V3L com;
  M3L Ic;
  cloud_parameters(c, m, com, Ic);
  return SpatialInertia<S>(S(m), com.cast<S>(), Ic.cast<S>());
}

/// Momentum sum_k m_k (v_k, r_k x v_k) of the cloud moving with V = (v, w).
V6L cloud_momentum(const Cloud& c, const V6L& V) {
  V6L h = V6L::Zero();
  for (std::size_t k = 0; k < c.m.size(); ++k) {
    const V3L vk = V.head<3>() + V3L(V.tail<3>()).cross(c.r[k]);
    h.head<3>() += c.m[k] * vk;
    h.tail<3>() += c.m[k] * c.r[k].cross(vk);
  }
  return h;
}

LD cloud_energy(const Cloud& c, const V6L& V) {
  LD T = 0;
  for (std::size_t k = 0; k < c.m.size(); ++k) {
    const V3L vk = V.head<3>() + V3L(V.tail<3>()).cross(c.r[k]);
    T += c.m[k] * vk.squaredNorm() / 2;
  }
  return T;
}

/// Ad_g (6x6, (v, w) order) in long double.
M6L adjoint_ld(const M3L& R, const V3L& p) {
  M3L P;
  P << 0, -p(2), p(1), p(2), 0, -p(0), -p(1), p(0), 0;
  M6L A = M6L::Zero();
  A.topLeftCorner<3, 3>() = R;
  A.topRightCorner<3, 3>() = P * R;
  A.bottomRightCorner<3, 3>() = R;
  return A;
}

template <typename S>
class SpatialInertiaTest : public ::testing::Test {};
TYPED_TEST_SUITE(SpatialInertiaTest, ScalarTypes, ScalarName);

TYPED_TEST(SpatialInertiaTest, MomentumAndEnergyOfAPointCloud) {
  using S = TypeParam;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Cloud c = random_cloud(rng);
    const SpatialInertia<S> I = inertia_of<S>(c);
    Eigen::Matrix<S, 6, 1> V;
    for (int k = 0; k < 6; ++k) V(k) = S(u(rng));
    const V6L VL = to_ld(V);
    const LD scale = 10;  // |G| |V| for masses <= 10, |r| <= 2, |V| <= 2*sqrt(6)
    EXPECT_TRUE(near<S>(I.momentum(Twist<S>(V)).vector(), cloud_momentum(c, VL), kInertia, scale));
    EXPECT_TRUE(near<S>(Eigen::Matrix<S, 6, 1>(I.matrix() * V), cloud_momentum(c, VL), kInertia, scale));
    const LD T = cloud_energy(c, VL);
    EXPECT_LE(std::fabs(LD(I.kinetic_energy(Twist<S>(V))) - T), kInertia * eps<S>() * std::max(LD(1), T));
    // 1/2 V^T G V with the matrix.
    EXPECT_LE(std::fabs(LD(V.dot(I.matrix() * V)) / 2 - T), kInertia * eps<S>() * std::max(LD(10), T));
  }
}

TYPED_TEST(SpatialInertiaTest, MatrixIsTheParallelAxisFormula) {
  using S = TypeParam;
  std::mt19937 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const Cloud c = random_cloud(rng);
    LD m;
    V3L com;
    M3L Ic;
    cloud_parameters(c, m, com, Ic);
    const SpatialInertia<S> I = inertia_of<S>(c);
    const auto G = I.matrix();
    // Rotational inertia about the origin: I_c + m (|c|^2 1 - c c^T),
    // also sum_k m_k (|r_k|^2 1 - r_k r_k^T) directly from the cloud.
    M3L Io = M3L::Zero();
    for (std::size_t k = 0; k < c.m.size(); ++k)
      Io += c.m[k] * (c.r[k].squaredNorm() * M3L::Identity() - c.r[k] * c.r[k].transpose());
    EXPECT_TRUE(near<S>(Eigen::Matrix<S, 3, 3>(G.template bottomRightCorner<3, 3>()), Io, kInertia, 10));
    EXPECT_TRUE(near<S>(Eigen::Matrix<S, 3, 3>(G.template bottomRightCorner<3, 3>()),
                        M3L(Ic + m * (com.squaredNorm() * M3L::Identity() - com * com.transpose())), kInertia, 10));
    EXPECT_TRUE(near<S>(Eigen::Matrix<S, 3, 3>(G.template topLeftCorner<3, 3>()), M3L(m * M3L::Identity()), 4));
    // Symmetric; the off-diagonal blocks are m [c] and its transpose.
    EXPECT_EQ(G, G.transpose());
    // from_matrix_unchecked recovers (m, c, I_c).
    EXPECT_TRUE(SpatialInertia<S>::from_matrix_unchecked(G).is_approx(I, RealOf<S>(kInertia * eps<S>() * 10)));
  }
  // A massless body: the zero matrix gives SpatialInertia() (c = 0, not 0 / 0), and a
  // rotational inertia alone comes back as it is.
  const SpatialInertia<S> zero = SpatialInertia<S>::from_matrix_unchecked(Eigen::Matrix<S, 6, 6>::Zero());
  EXPECT_EQ(zero.mass(), S(0));
  EXPECT_TRUE(zero.com().isZero(0) && zero.inertia().isZero(0));
  Eigen::Matrix<S, 6, 6> spin = Eigen::Matrix<S, 6, 6>::Zero();
  spin.template bottomRightCorner<3, 3>() = Eigen::Matrix<S, 3, 1>(S(1), S(2), S(3)).asDiagonal();
  const SpatialInertia<S> flywheel = SpatialInertia<S>::from_matrix_unchecked(spin);
  EXPECT_TRUE(flywheel.com().isZero(0));
  EXPECT_TRUE(flywheel.matrix() == spin);
}

TYPED_TEST(SpatialInertiaTest, ChangeOfFrameIsTheAdjointProduct) {
  using S = TypeParam;
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (int trial = 0; trial < 50; ++trial) {
    const Cloud c = random_cloud(rng);
    const SpatialInertia<S> Ib = inertia_of<S>(c);
    Eigen::Matrix<S, 6, 1> xi;
    for (int k = 0; k < 6; ++k) xi(k) = S(u(rng));
    const SE3<S> g = SE3<S>::exp(xi);  // g = g_ab
    const SpatialInertia<S> Ia = Ib.transform(g);
    const M3L R = to_ld(g.rotation().matrix());
    const V3L p = to_ld(g.translation());
    const M6L Ad_inv = adjoint_ld(R, p).inverse();
    const M6L Ga = Ad_inv.transpose() * to_ld(Ib.matrix()) * Ad_inv;
    EXPECT_TRUE(near<S>(Ia.matrix(), Ga, 4 * kInertia, 30));
    // The moved cloud: r_a = R r_b + p.
    Cloud moved = c;
    for (auto& r : moved.r) r = R * r + p;
    EXPECT_TRUE(Ia.is_approx(inertia_of<S>(moved), RealOf<S>(4 * kInertia * eps<S>() * 10)));
    // transform_inv undoes transform.
    EXPECT_TRUE(Ia.transform_inv(g).is_approx(Ib, RealOf<S>(4 * kInertia * eps<S>() * 10)));
    // Kinetic energy of a twist V_b (frame b) and of the same motion in frame a, Ad_g V_b.
    Eigen::Matrix<S, 6, 1> Vb;
    for (int k = 0; k < 6; ++k) Vb(k) = S(u(rng));
    const Twist<S> Va = g.act(Twist<S>(Vb));
    const LD Tb = Ib.kinetic_energy(Twist<S>(Vb)), Ta = Ia.kinetic_energy(Va);
    EXPECT_LE(std::fabs(Ta - Tb), 4 * kInertia * eps<S>() * std::max(LD(10), Tb));
    // Momentum is a wrench: h_a = Ad_g^-T h_b.
    EXPECT_TRUE(Ia.momentum(Va).is_approx(g.act(Ib.momentum(Twist<S>(Vb))), RealOf<S>(8 * kInertia * eps<S>())));
  }
}

TYPED_TEST(SpatialInertiaTest, SumIsTheSumOfMatrices) {
  using S = TypeParam;
  std::mt19937 rng(14);
  for (int trial = 0; trial < 20; ++trial) {
    const Cloud a = random_cloud(rng), b = random_cloud(rng);
    Cloud ab = a;
    ab.m.insert(ab.m.end(), b.m.begin(), b.m.end());
    ab.r.insert(ab.r.end(), b.r.begin(), b.r.end());
    const SpatialInertia<S> sum = inertia_of<S>(a) + inertia_of<S>(b);
    EXPECT_TRUE(sum.is_approx(inertia_of<S>(ab), RealOf<S>(kInertia * eps<S>() * 10)));
    EXPECT_TRUE(near<S>(sum.matrix(),
                        to_ld(Eigen::Matrix<S, 6, 6>(inertia_of<S>(a).matrix() + inertia_of<S>(b).matrix())), kInertia,
                        10));
  }
}

TYPED_TEST(SpatialInertiaTest, IsPhysicalOnBothSidesOfEachCondition) {
  using S = TypeParam;
  using M3 = Eigen::Matrix<S, 3, 3>;
  using V3 = Eigen::Matrix<S, 3, 1>;
  const RealOf<S> tol = chasles::ThresholdsOf<S>::inertia_tolerance;
  const V3 c(S(0.1), S(0.2), S(0.3));
  const M3 box = Eigen::Vector3<S>(S(1), S(2), S(2.5)).asDiagonal();
  EXPECT_TRUE(SpatialInertia<S>(S(1), c, box).is_physical());
  // Mass: positive and finite.
  EXPECT_FALSE(SpatialInertia<S>(S(0), c, box).is_physical());
  EXPECT_FALSE(SpatialInertia<S>(S(-1), c, box).is_physical());
  EXPECT_FALSE(SpatialInertia<S>(std::numeric_limits<S>::infinity(), c, box).is_physical());
  EXPECT_FALSE(SpatialInertia<S>(std::numeric_limits<S>::quiet_NaN(), c, box).is_physical());
  EXPECT_FALSE(SpatialInertia<S>(S(1), V3(S(0), std::numeric_limits<S>::quiet_NaN(), S(0)), box).is_physical());
  // Symmetry, to tol times the largest entry (2.5).
  M3 asym = box;
  asym(0, 1) = S(2.5 * 0.5 * tol);
  EXPECT_TRUE(SpatialInertia<S>(S(1), c, asym).is_physical());
  asym(0, 1) = S(2.5 * 2 * tol);
  EXPECT_FALSE(SpatialInertia<S>(S(1), c, asym).is_physical());
  // Positive definite: a rod (one principal moment 0) and a negative moment are refused.
  EXPECT_FALSE(SpatialInertia<S>(S(1), c, M3(Eigen::Vector3<S>(S(0), S(1), S(1)).asDiagonal())).is_physical());
  EXPECT_FALSE(SpatialInertia<S>(S(1), c, M3(Eigen::Vector3<S>(S(-1), S(2), S(2)).asDiagonal())).is_physical());
  // Triangle inequality: a thin plate (I_3 = I_1 + I_2) passes; I_3 = 2 + d
  // passes for d < ~8 tol (Sigma's eigenvalue -d/2 against tol * trace).
  EXPECT_TRUE(SpatialInertia<S>(S(1), c, M3(Eigen::Vector3<S>(S(1), S(1), S(2)).asDiagonal())).is_physical());
  EXPECT_TRUE(SpatialInertia<S>(S(1), c, M3(Eigen::Vector3<S>(S(1), S(1), S(2 + 4 * tol)).asDiagonal())).is_physical());
  EXPECT_FALSE(
      SpatialInertia<S>(S(1), c, M3(Eigen::Vector3<S>(S(1), S(1), S(2 + 16 * tol)).asDiagonal())).is_physical());
  EXPECT_FALSE(SpatialInertia<S>(S(1), c, M3(Eigen::Vector3<S>(S(1), S(1), S(3)).asDiagonal())).is_physical());
  // Scale-invariant, without overflow or underflow: a thin plate of moments
  // near the largest finite value passes, moments (0.1, 0.2, max) do not.
  const S big = std::numeric_limits<S>::max();
  EXPECT_TRUE(SpatialInertia<S>(S(1), c, M3(Eigen::Vector3<S>(big / 2, big / 2, big).asDiagonal())).is_physical());
  EXPECT_FALSE(SpatialInertia<S>(S(1), c, M3(Eigen::Vector3<S>(S(0.1), S(0.2), big).asDiagonal())).is_physical());
  const S tiny = std::numeric_limits<S>::denorm_min() * S(64);
  EXPECT_TRUE(SpatialInertia<S>(S(1), c, M3(box * tiny)).is_physical());
  EXPECT_FALSE(SpatialInertia<S>(S(1), c, M3::Zero()).is_physical());
  // The same, rotated (the check is not only on diagonal matrices).
  const M3 R = chasles::SO3<S>::exp(V3(S(0.4), S(-0.3), S(1.1))).matrix();
  EXPECT_TRUE(SpatialInertia<S>(S(1), c, M3(R * box * R.transpose())).is_physical());
  EXPECT_FALSE(
      SpatialInertia<S>(S(1), c, M3(R * M3(Eigen::Vector3<S>(S(1), S(1), S(2.1)).asDiagonal()) * R.transpose()))
          .is_physical());
}

}  // namespace
