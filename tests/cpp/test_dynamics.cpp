// The dynamics of a chasles::Chain (inverse dynamics, mass matrix, forward dynamics of a
// serial chain), on random arms of revolute and prismatic joints with random
// physical inertias, against independent oracles:
// - M(q) positive definite (Cholesky) and its columns equal to
//   inverse_dynamics(q, 0, e_i) - inverse_dynamics(q, 0, 0);
// - 1/2 qd^T M qd equal to the links' kinetic energy sum_i 1/2 V_i.G_i V_i;
// - the gravity torques equal to the gradient of the potential energy
//   (central differences);
// - the power balance qd . (tau - g(q)) = dT/dt along a trajectory (dT/dt by
//   central differences of T = 1/2 qd^T M qd);
// - the Coriolis terms equal to the Christoffel form M' qd - 1/2 d/dq
//   (qd^T M qd), dM/dq by automatic differentiation (itself checked against
//   central differences);
// - the tip wrench's torques equal to J_b(q)^T F_tip (Chain::jacobian_body);
// - forward_dynamics inverting inverse_dynamics, and equal to Eigen's LLT
//   solve on physical arms; its status where M(q) is not positive definite
//   (a massless link, point masses on the joint axes, an indefinite
//   inertia, a pivot of rounding size) and on both sides of its threshold;
// - energy conserved by an RK4 simulation with no torque;
// - float and double against the same algorithm in long double (rounding);
// - the analytic derivatives of inverse and forward dynamics
//   (dynamics_derivatives.hpp) against automatic differentiation of the
//   algorithms themselves and against central differences in long double,
//   on random arms of revolute, prismatic and helical joints with screws of
//   any norm; M(q)^-1 against M(q).
// The modern_robotics package (and Pinocchio, bench/) check the values
// themselves from Python (tests/python/test_dynamics.py).
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/dynamics.hpp>
#include <chasles/dynamics_derivatives.hpp>
#include <chasles/kinematics.hpp>

#include "support/arms.hpp"
#include "support/group_traits.hpp"
#include "support/scalar_types.hpp"

namespace {

using namespace chasles_test;
using chasles::Chain;
using chasles::RealOf;
using chasles::SE3;
using chasles::SpatialInertia;
using chasles::Wrench;

constexpr int kMax = 8;
template <typename S>
using Dyn = Chain<S, Eigen::Dynamic, kMax>;

/// A random arm in double: n joints (revolute with probability 3/4, else
/// prismatic) with axes through points within 1 m of the base, a random home
/// pose, and for each link a box of mass 0.5 to 3 kg and sides 0.05 to 0.5 m
/// (principal moments of a box: physical), turned and placed near its joint.
struct Arm {
  Dyn<double>::Screws S;
  SE3<double> M;
  Dyn<double>::Inertias I;
  Eigen::Vector3d gravity;
};

Arm random_arm(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), side(0.05, 0.5), mass(0.5, 3.0), coin(0.0, 1.0);
  auto vec = [&] { return Eigen::Vector3d(u(rng), u(rng), u(rng)); };
  Arm a;
  a.S.resize(6, n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d point = vec(), direction = vec();
    a.S.col(i) = coin(rng) < 0.75 ? Chain<double, Eigen::Dynamic, kMax>::revolute_screw(point, direction)
                                  : Chain<double, Eigen::Dynamic, kMax>::prismatic_screw(direction);
    const double m = mass(rng), x = side(rng), y = side(rng), z = side(rng);
    const Eigen::Vector3d moments(m * (y * y + z * z) / 12, m * (x * x + z * z) / 12, m * (x * x + y * y) / 12);
    const Eigen::Matrix3d R = chasles::SO3<double>::exp(vec()).matrix();
    a.I[static_cast<std::size_t>(i)] =
        SpatialInertia<double>(m, Eigen::Vector3d(point + 0.3 * vec()), R * moments.asDiagonal() * R.transpose());
  }
  Eigen::Matrix<double, 6, 1> xi;
  xi << vec(), vec();
  a.M = SE3<double>::exp(xi);
  a.gravity = Eigen::Vector3d(0, 0, -9.81);
  return a;
}

template <typename S>
Dyn<S> dynamics_of(const Arm& a) {
  typename Dyn<S>::Inertias I;
  for (std::size_t i = 0; i < kMax; ++i) I[i] = a.I[i].template cast<S>();
  return Dyn<S>(a.S.template cast<S>(), a.M.template cast<S>(), I, a.gravity.template cast<S>());
}

template <typename S>
typename Dyn<S>::JointVector random_joints(std::mt19937& rng, int n, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  typename Dyn<S>::JointVector q(n);
  for (int i = 0; i < n; ++i) q(i) = S(u(rng));
  return q;
}

template <typename S>
class DynamicsTest : public ::testing::Test {};
TYPED_TEST_SUITE(DynamicsTest, ScalarTypes, ScalarName);

// Rounding: every result is a sum over the n links of products of a few
// exps, adjoints and inertias (entries up to ~10 for these arms): k = 64 n
// ulps of the largest magnitude in the result or its terms. `scale` below is
// the largest |tau| of the gravity, inertial and velocity terms, each of
// order 100 for these arms at |qd|, |qdd| <= 2.
constexpr LD kPerJoint = 64;

TYPED_TEST(DynamicsTest, AgreesWithLongDouble) {
  using S = TypeParam;
  std::mt19937 rng(21);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 1 + trial % kMax;
    const Arm arm = random_arm(rng, n);
    const Dyn<S> d = dynamics_of<S>(arm);
    const Dyn<LD> dl = dynamics_of<LD>(arm);
    const auto q = random_joints<S>(rng, n, 3.0), qd = random_joints<S>(rng, n, 2.0),
               qdd = random_joints<S>(rng, n, 2.0);
    const Wrench<S> F(Eigen::Matrix<S, 3, 1>(S(1), S(-2), S(3)), Eigen::Matrix<S, 3, 1>(S(0.5), S(0.1), S(-0.3)));
    const auto tau = inverse_dynamics(d, q, qd, qdd, F);
    const auto taul = inverse_dynamics(dl, to_ld(q), to_ld(qd), to_ld(qdd), F.template cast<LD>());
    const LD scale = std::max(LD(100), max_abs(taul));
    EXPECT_TRUE(near<S>(tau, taul, kPerJoint * n, scale)) << "n = " << n;
    EXPECT_TRUE(near<S>(mass_matrix(d, q), mass_matrix(dl, to_ld(q)), kPerJoint * n, 10));
    EXPECT_TRUE(near<S>(gravity_torques(d, q), gravity_torques(dl, to_ld(q)), kPerJoint * n, scale));
    EXPECT_TRUE(near<S>(coriolis(d, q, qd), coriolis(dl, to_ld(q), to_ld(qd)), kPerJoint * n, scale));
  }
}

TYPED_TEST(DynamicsTest, MassMatrixIsPositiveDefiniteAndTheColumnsOfInverseDynamics) {
  using S = TypeParam;
  std::mt19937 rng(22);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 1 + trial % kMax;
    const Dyn<S> d = dynamics_of<S>(random_arm(rng, n));
    const auto q = random_joints<S>(rng, n, 3.0);
    const auto M = mass_matrix(d, q);
    EXPECT_EQ(M, M.transpose());
    EXPECT_EQ(Eigen::LLT<typename Dyn<S>::MassMatrix>(M).info(), Eigen::Success) << "n = " << n;
    const typename Dyn<S>::JointVector zero = Dyn<S>::JointVector::Zero(n);
    const auto tau0 = inverse_dynamics(d, q, zero, zero);  // gravity on: g(q)
    for (int i = 0; i < n; ++i) {
      const typename Dyn<S>::JointVector ei = Dyn<S>::JointVector::Unit(n, i);
      const typename Dyn<S>::JointVector column = inverse_dynamics(d, q, zero, ei) - tau0;
      EXPECT_TRUE(near<S>(column, M.col(i), kPerJoint * n, std::max(LD(100), max_abs(tau0)))) << "column " << i;
    }
  }
}

TYPED_TEST(DynamicsTest, KineticEnergyIsHalfQdMQd) {
  using S = TypeParam;
  std::mt19937 rng(23);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 1 + trial % kMax;
    const Dyn<S> d = dynamics_of<S>(random_arm(rng, n));
    const auto q = random_joints<S>(rng, n, 3.0), qd = random_joints<S>(rng, n, 2.0);
    const LD T = kinetic_energy(d, q, qd);
    const LD TM = LD(qd.dot(mass_matrix(d, q) * qd)) / 2;
    EXPECT_GT(T, 0);
    EXPECT_LE(std::fabs(T - TM), kPerJoint * n * eps<S>() * std::max(LD(10), T)) << "n = " << n;
  }
}

TYPED_TEST(DynamicsTest, TipWrenchGivesTheBodyJacobianTranspose) {
  using S = TypeParam;
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 1 + trial % kMax;
    const Arm arm = random_arm(rng, n);
    const Dyn<S> d = dynamics_of<S>(arm);
    const Chain<S, Eigen::Dynamic, kMax> chain(arm.S.template cast<S>(), arm.M.template cast<S>());
    const auto q = random_joints<S>(rng, n, 3.0), qd = random_joints<S>(rng, n, 2.0),
               qdd = random_joints<S>(rng, n, 2.0);
    Eigen::Matrix<S, 6, 1> Fv;
    for (int k = 0; k < 6; ++k) Fv(k) = S(u(rng));
    const typename Dyn<S>::JointVector diff =
        inverse_dynamics(d, q, qd, qdd, Wrench<S>(Fv)) - inverse_dynamics(d, q, qd, qdd);
    const typename Dyn<S>::JointVector expected = chain.jacobian_body(q).transpose() * Fv;
    const LD scale = std::max(LD(100), max_abs(inverse_dynamics(d, q, qd, qdd)));
    EXPECT_TRUE(near<S>(diff, expected, kPerJoint * n, scale)) << "n = " << n;
  }
}

TYPED_TEST(DynamicsTest, ForwardDynamicsInvertsInverseDynamics) {
  using S = TypeParam;
  std::mt19937 rng(25);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 1 + trial % kMax;
    const Dyn<S> d = dynamics_of<S>(random_arm(rng, n));
    const auto q = random_joints<S>(rng, n, 3.0), qd = random_joints<S>(rng, n, 2.0),
               qdd = random_joints<S>(rng, n, 2.0);
    const Wrench<S> F(Eigen::Matrix<S, 3, 1>(S(1), S(-2), S(3)), Eigen::Matrix<S, 3, 1>(S(0.5), S(0.1), S(-0.3)));
    const auto tau = inverse_dynamics(d, q, qd, qdd, F);
    const auto forward = forward_dynamics(d, q, qd, tau, F);
    ASSERT_TRUE(forward) << "n = " << n;
    ASSERT_EQ(forward.joint, -1);
    const auto& back = forward.qdd;
    // Conditioning: the error of qdd is cond(M) times the rounding of tau.
    const auto M = mass_matrix(d, q);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(M.template cast<double>());
    const LD cond = LD(es.eigenvalues().maxCoeff() / es.eigenvalues().minCoeff());
    EXPECT_TRUE(near<S>(back, to_ld(qdd), kPerJoint * n * cond,
                        std::max(LD(100), max_abs(tau)) / LD(es.eigenvalues().maxCoeff())))
        << "n = " << n << ", cond(M) = " << static_cast<double>(cond);
    // bias = coriolis + gravity.
    EXPECT_TRUE(near<S>(bias(d, q, qd), Eigen::Matrix<S, Eigen::Dynamic, 1>(coriolis(d, q, qd) + gravity_torques(d, q)),
                        4, std::max(LD(100), max_abs(tau))));
  }
}

template <typename S>
using ChainOf = Chain<S, Eigen::Dynamic, kMax>;

/// The chain of an arm with a base frame: its screws and home pose moved
/// back by the base (S0 = Ad_base^-1 S, M0 = base^-1 M) and its inertias
/// likewise, so that in the world frame it is `a` carried by `base`.
template <typename S>
ChainOf<S> chain_of(const Arm& a, const SE3<double>& base, const Eigen::Vector3d& gravity) {
  using C = ChainOf<S>;
  const Eigen::Index n = a.S.cols();
  typename C::Inertias I{};
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) I[i] = a.I[i].template cast<S>();
  typename C::JointTypes types{};
  for (Eigen::Index i = 0; i < n; ++i)
    types[static_cast<std::size_t>(i)] =
        a.S.col(i).tail<3>().squaredNorm() > 0 ? chasles::JointType::revolute : chasles::JointType::prismatic;
  const typename C::JointVector inf = C::JointVector::Constant(n, S(std::numeric_limits<double>::infinity()));
  return C(a.S.template cast<S>(), a.M.template cast<S>(), types, -inf, inf, inf, inf, base.template cast<S>(),
           SE3<S>(), gravity.template cast<S>(), I);
}

TYPED_TEST(DynamicsTest, FromAChainEqualsFromItsParts) {
  using S = TypeParam;
  std::mt19937 rng(31);
  Eigen::Matrix<double, 6, 1> xi;
  xi << 0.3, -1.2, 0.8, 0.4, -0.6, 1.1;
  const SE3<double> base = SE3<double>::exp(xi);
  for (int n = 1; n <= kMax; ++n) {
    const Arm arm = random_arm(rng, n);
    const ChainOf<S> chain = chain_of<S>(arm, base, Eigen::Vector3d(0.2, -0.1, -9.8));
    const Dyn<S> a(chain);
    const Dyn<S> b(chain.space_screws(), chain.home(), typename Dyn<S>::HomeAsGiven(), chain.link_inertias(),
                   chain.gravity());
    const auto q = random_joints<S>(rng, n, 3.0), qd = random_joints<S>(rng, n, 2.0),
               qdd = random_joints<S>(rng, n, 2.0);
    const Wrench<S> F(Eigen::Matrix<S, 3, 1>(S(1), S(-2), S(3)), Eigen::Matrix<S, 3, 1>(S(0.5), S(0.1), S(-0.3)));
    using V = Eigen::Matrix<S, Eigen::Dynamic, 1>;
    using Mat = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
    EXPECT_EQ(V(inverse_dynamics(a, q, qd, qdd, F)), V(inverse_dynamics(b, q, qd, qdd, F)));
    EXPECT_EQ(Mat(mass_matrix(a, q)), Mat(mass_matrix(b, q)));
    EXPECT_EQ(V(forward_dynamics(a, q, qd, qdd, F).qdd), V(forward_dynamics(b, q, qd, qdd, F).qdd));
    EXPECT_EQ(V(gravity_torques(a, q)), V(gravity_torques(b, q)));
    EXPECT_EQ(V(coriolis(a, q, qd)), V(coriolis(b, q, qd)));
    EXPECT_TRUE(a.space_screws() == chain.space_screws() && a.gravity() == chain.gravity());
  }
}

// A chain on a base frame, given its screws, home and inertias in the base
// frame, has the dynamics of the same chain without a base under gravity
// rotated into the base frame (R_base^T gravity): the joints cannot tell.
// Both sides are compared with the unbased chain in long double.
TYPED_TEST(DynamicsTest, TheBaseFrameMovesTheInertias) {
  using S = TypeParam;
  std::mt19937 rng(32);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 16; ++trial) {
    const int n = 1 + trial % kMax;
    const Arm arm = random_arm(rng, n);
    Eigen::Matrix<double, 6, 1> xi;
    for (int k = 0; k < 6; ++k) xi(k) = 2 * u(rng);
    const SE3<double> base = SE3<double>::exp(xi);
    const Eigen::Vector3d gravity(0, 0, -9.81);
    const Dyn<S> based(chain_of<S>(arm, base, gravity));
    const Eigen::Vector3d rotated = base.rotation().matrix().transpose() * gravity;
    const Dyn<LD> reference(chain_of<LD>(arm, SE3<double>(), rotated));
    const auto q = random_joints<S>(rng, n, 3.0), qd = random_joints<S>(rng, n, 2.0),
               qdd = random_joints<S>(rng, n, 2.0);
    const Wrench<S> F(Eigen::Matrix<S, 3, 1>(S(1), S(-2), S(3)), Eigen::Matrix<S, 3, 1>(S(0.5), S(0.1), S(-0.3)));
    const auto taul = inverse_dynamics(reference, to_ld(q), to_ld(qd), to_ld(qdd), F.template cast<LD>());
    const LD scale = std::max(LD(100), max_abs(taul));
    // twice the rounding of AgreesWithLongDouble: the base frame adds a change of frame to every quantity
    EXPECT_TRUE(near<S>(inverse_dynamics(based, q, qd, qdd, F), taul, 2 * kPerJoint * n, scale)) << "n = " << n;
    EXPECT_TRUE(near<S>(mass_matrix(based, q), mass_matrix(reference, to_ld(q)), 2 * kPerJoint * n, 10));
    EXPECT_TRUE(near<S>(gravity_torques(based, q), gravity_torques(reference, to_ld(q)), 2 * kPerJoint * n, scale));
    EXPECT_TRUE(near<S>(coriolis(based, q, qd), coriolis(reference, to_ld(q), to_ld(qd)), 2 * kPerJoint * n, scale));
    // and not the same without rotating gravity (the test can fail)
    if (base.rotation().matrix().col(2).z() < 0.9) {
      const Dyn<LD> unrotated(chain_of<LD>(arm, SE3<double>(), gravity));
      EXPECT_FALSE(near<S>(gravity_torques(based, q), gravity_torques(unrotated, to_ld(q)), 2 * kPerJoint * n, scale));
    }
  }
}

TYPED_TEST(DynamicsTest, AChainWithoutInertiasIsMassless) {
  using S = TypeParam;
  std::mt19937 rng(33);
  const Arm arm = random_arm(rng, 5);
  using C = ChainOf<S>;
  const C chain(arm.S.template cast<S>(), arm.M.template cast<S>());  // no inertias given
  const Dyn<S> d(chain);
  const auto q = random_joints<S>(rng, 5, 3.0), qd = random_joints<S>(rng, 5, 2.0), qdd = random_joints<S>(rng, 5, 2.0);
  EXPECT_TRUE(inverse_dynamics(d, q, qd, qdd).isZero(0));
  EXPECT_TRUE(mass_matrix(d, q).isZero(0));
  // only a tip wrench needs torques: J_b(q)^T F_tip
  const Wrench<S> F(Eigen::Matrix<S, 3, 1>(S(1), S(-2), S(3)), Eigen::Matrix<S, 3, 1>(S(0.5), S(0.1), S(-0.3)));
  const Eigen::Matrix<S, Eigen::Dynamic, 1> expected = chain.jacobian_body(q).transpose() * F.vector();
  EXPECT_TRUE(near<S>(inverse_dynamics(d, q, qd, qdd, F), expected, kPerJoint * 5, 10));
}

TEST(Dynamics, FixedSizeGivesTheSameBitsAsBounded) {
  std::mt19937 rng(26);
  const Arm arm = random_arm(rng, 6);
  const Dyn<double> d = dynamics_of<double>(arm);
  Chain<double, 6>::Inertias I6;
  for (std::size_t i = 0; i < 6; ++i) I6[i] = arm.I[i];
  const Chain<double, 6> f(Eigen::Matrix<double, 6, 6>(arm.S), arm.M, I6, arm.gravity);
  const auto q = random_joints<double>(rng, 6, 3.0), qd = random_joints<double>(rng, 6, 2.0);
  const Eigen::Matrix<double, 6, 1> q6 = q, qd6 = qd;
  EXPECT_EQ(Eigen::VectorXd(inverse_dynamics(f, q6, qd6, qd6)), Eigen::VectorXd(inverse_dynamics(d, q, qd, qd)));
  EXPECT_EQ(Eigen::MatrixXd(mass_matrix(f, q6)), Eigen::MatrixXd(mass_matrix(d, q)));
  EXPECT_TRUE(near<double>(forward_dynamics(f, q6, qd6, qd6).qdd, forward_dynamics(d, q, qd, qd).qdd, 64, 10));
}

// Central differences in double, five points, step h: truncation
// h^4 / 30 |f^(5)|, rounding ~ eps |f| / h. With h = 1e-3 and |f^(5)| <= 1e4
// (energies ~ 100 J whose derivatives grow by at most ~5 per order for
// these arms) truncation is <= 3e-9 and rounding <= 3e-11: bound 1e-7 of
// the scale.
template <typename F>
double derivative(F f, double h = 1e-3) {
  return (-f(2 * h) + 8 * f(h) - 8 * f(-h) + f(-2 * h)) / (12 * h);
}

TEST(Dynamics, GravityTorquesAreTheGradientOfThePotentialEnergy) {
  std::mt19937 rng(27);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 1 + trial % kMax;
    const Dyn<double> d = dynamics_of<double>(random_arm(rng, n));
    const auto q = random_joints<double>(rng, n, 3.0);
    const auto g = gravity_torques(d, q);
    for (int i = 0; i < n; ++i) {
      const double dU = derivative([&](double t) {
        Dyn<double>::JointVector qt = q;
        qt(i) += t;
        return potential_energy(d, qt);
      });
      EXPECT_NEAR(g(i), dU, 1e-7 * std::max(100.0, g.cwiseAbs().maxCoeff())) << "n = " << n << ", joint " << i;
    }
  }
}

TEST(Dynamics, PowerBalanceAlongATrajectory) {
  // q(t) = q0 + a sin(w t): tau = ID(q, qd, qdd) with gravity; the power of
  // tau - g(q) is the rate of the kinetic energy T = 1/2 qd^T M qd.
  std::mt19937 rng(28);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 1 + trial % kMax;
    const Dyn<double> d = dynamics_of<double>(random_arm(rng, n));
    const auto q0 = random_joints<double>(rng, n, 3.0), a = random_joints<double>(rng, n, 1.0),
               w = random_joints<double>(rng, n, 2.0);
    auto state = [&](double t, Dyn<double>::JointVector& q, Dyn<double>::JointVector& qd,
                     Dyn<double>::JointVector& qdd) {
      q = q0;
      qd.resize(n);
      qdd.resize(n);
      for (int i = 0; i < n; ++i) {
        q(i) += a(i) * std::sin(w(i) * t);
        qd(i) = a(i) * w(i) * std::cos(w(i) * t);
        qdd(i) = -a(i) * w(i) * w(i) * std::sin(w(i) * t);
      }
    };
    auto energy = [&](double t) {
      Dyn<double>::JointVector q, qd, qdd;
      state(t, q, qd, qdd);
      return qd.dot(mass_matrix(d, q) * qd) / 2;
    };
    for (double t : {0.0, 0.4, 1.3}) {
      Dyn<double>::JointVector q, qd, qdd;
      state(t, q, qd, qdd);
      const auto tau = inverse_dynamics(d, q, qd, qdd);
      const double power = qd.dot(tau - gravity_torques(d, q));
      const double dT = derivative([&](double s) { return energy(t + s); });
      EXPECT_NEAR(power, dT, 1e-7 * std::max(100.0, tau.cwiseAbs().maxCoeff() * qd.cwiseAbs().maxCoeff()))
          << "n = " << n << ", t = " << t;
    }
  }
}

TEST(Dynamics, CoriolisIsTheChristoffelFormOfTheMassMatrixDerivative) {
  // C(q, qd) qd = M'(q) qd - 1/2 [qd^T dM/dq_k qd]_k (Lagrange's equations),
  // dM/dq_k by forward-mode automatic differentiation through mass_matrix,
  // checked against five-point central differences.
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 6, 1>>;
  std::mt19937 rng(29);
  for (int trial = 0; trial < 10; ++trial) {
    const Arm arm = random_arm(rng, 6);
    Chain<AD, 6>::Inertias Ia;
    Chain<double, 6>::Inertias Id;
    for (std::size_t i = 0; i < 6; ++i) {
      Ia[i] = arm.I[i].cast<AD>();
      Id[i] = arm.I[i];
    }
    const Eigen::Matrix<double, 6, 6> S6 = arm.S;
    const Chain<AD, 6> da(S6.cast<AD>(), arm.M.cast<AD>(), Ia, arm.gravity.cast<AD>());
    const Chain<double, 6> d(S6, arm.M, Id, arm.gravity);
    const Eigen::Matrix<double, 6, 1> q = random_joints<double>(rng, 6, 3.0), qd = random_joints<double>(rng, 6, 2.0);
    Eigen::Matrix<AD, 6, 1> qa;
    for (int i = 0; i < 6; ++i) qa(i) = AD(q(i), 6, i);
    const auto Ma = mass_matrix(da, qa);
    std::array<Eigen::Matrix<double, 6, 6>, 6> dM;
    for (int k = 0; k < 6; ++k) {
      for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) dM[static_cast<std::size_t>(k)](r, c) = Ma(r, c).derivatives()(k);
      const auto M_at = [&](double t) {
        return Eigen::Matrix<double, 6, 6>(
            mass_matrix(d, Eigen::Matrix<double, 6, 1>(q + t * Eigen::Matrix<double, 6, 1>::Unit(k))));
      };
      // Five-point difference, h = 1e-3: truncation h^4/30 |M^(5)| <= 3e-12 for
      // |M^(5)| <= 1e2 (these arms' masses and reaches), rounding ~ eps |M| / h <= 1e-11.
      const double h = 1e-3;
      const Eigen::Matrix<double, 6, 6> fd = (-M_at(2 * h) + 8 * M_at(h) - 8 * M_at(-h) + M_at(-2 * h)) / (12 * h);
      EXPECT_LE((dM[static_cast<std::size_t>(k)] - fd).cwiseAbs().maxCoeff(), 1e-9) << "dM/dq_" << k;
    }
    Eigen::Matrix<double, 6, 6> Mdot = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> christoffel;
    for (int k = 0; k < 6; ++k) {
      Mdot += dM[static_cast<std::size_t>(k)] * qd(k);
      christoffel(k) = qd.dot(dM[static_cast<std::size_t>(k)] * qd) / 2;
    }
    const Eigen::Matrix<double, 6, 1> expected = Mdot * qd - christoffel;
    const auto c = coriolis(d, q, qd);
    EXPECT_TRUE(near<double>(c, expected, 64 * 6, 100)) << "coriolis\n"
                                                        << c.transpose() << "\nexpected\n"
                                                        << expected.transpose();
  }
}

TEST(Dynamics, RungeKuttaSimulationConservesEnergy) {
  // No torque, no gravity: T = 1/2 qd^T M qd is constant. RK4 with step h has
  // a global error of order T h^4 |d^5 x/dt^5| per unit time: with joint
  // rates <= 1 rad/s and h = 1e-3 s, about 1e-12 T per second; over 0.5 s
  // the drift bound 2.5e-10 T leaves room for arms whose accelerations reach
  // ~10x the rates. With gravity, T + U is conserved to the same order. (Each
  // arm size with and without gravity, 500 steps: the sanitizer build runs
  // this at -O0, where 2 s of 6 arms took 134 s.)
  std::mt19937 rng(30);
  for (const bool with_gravity : {false, true}) {
    for (const int n : {6, 7}) {
      Arm arm = random_arm(rng, n);
      if (!with_gravity) arm.gravity.setZero();
      const Dyn<double> d = dynamics_of<double>(arm);
      Dyn<double>::JointVector q = random_joints<double>(rng, n, 3.0), qd = random_joints<double>(rng, n, 1.0);
      const Dyn<double>::JointVector zero = Dyn<double>::JointVector::Zero(n);
      auto total = [&](const Dyn<double>::JointVector& x, const Dyn<double>::JointVector& xd) {
        return kinetic_energy(d, x, xd) + potential_energy(d, x);
      };
      const double E0 = total(q, qd);
      const double h = 1e-3;
      double worst = 0;
      for (int step = 0; step < 500; ++step) {
        const Dyn<double>::JointVector k1q = qd, k1v = forward_dynamics(d, q, qd, zero).qdd;
        const Dyn<double>::JointVector q2 = q + h / 2 * k1q, v2 = qd + h / 2 * k1v;
        const Dyn<double>::JointVector k2q = v2, k2v = forward_dynamics(d, q2, v2, zero).qdd;
        const Dyn<double>::JointVector q3 = q + h / 2 * k2q, v3 = qd + h / 2 * k2v;
        const Dyn<double>::JointVector k3q = v3, k3v = forward_dynamics(d, q3, v3, zero).qdd;
        const Dyn<double>::JointVector q4 = q + h * k3q, v4 = qd + h * k3v;
        const Dyn<double>::JointVector k4q = v4, k4v = forward_dynamics(d, q4, v4, zero).qdd;
        q += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
        qd += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        worst = std::max(worst, std::fabs(total(q, qd) - E0));
      }
      const double T0 = kinetic_energy(d, q, qd);
      EXPECT_GT(T0, 0);
      EXPECT_LE(worst, 2.5e-10 * std::max(std::fabs(E0), T0))
          << "n = " << n << ", gravity " << with_gravity << ", E0 = " << E0;
    }
  }
}

// ---- forward dynamics where M(q) is not positive definite --------------------
//
// Before the status, each failing case below went unnoticed: Eigen's LLT
// reports a pivot <= 0 only through info(), which was not read (inf, NaN or
// finite accelerations from a half-factorized M), and a pivot of rounding
// size passes its test (accelerations of 1e10 and more, meaningless).

using chasles::DynamicsStatus;
using chasles::ForwardDynamicsResult;
using chasles_test::PandaLike;

template <typename S>
using Panda = Chain<S, 7>;

/// The Panda-like arm of support/arms.hpp with the given link inertias.
template <typename S>
Panda<S> panda_with(const std::array<SpatialInertia<S>, 7>& inertias) {
  const PandaLike<S> arm;
  return Panda<S>(arm.screws, arm.home, inertias, Eigen::Matrix<S, 3, 1>(S(0), S(0), S(-9.81)));
}

/// q uniform within the Panda-like arm's limits, qd and tau in [-2, 2] and [-20, 20].
template <typename S>
struct PandaState {
  Eigen::Matrix<S, 7, 1> q, qd, tau;
  explicit PandaState(std::mt19937& rng) {
    const PandaLike<S> arm;
    std::uniform_real_distribution<double> u(0.0, 1.0), v(-2.0, 2.0);
    for (int i = 0; i < 7; ++i) {
      q(i) = arm.lower(i) + S(u(rng)) * (arm.upper(i) - arm.lower(i));
      qd(i) = S(v(rng));
      tau(i) = S(10 * v(rng));
    }
  }
};

/// The value of a scalar (of an autodiff scalar: its value).
template <typename S>
double value_of(const S& x) {
  if constexpr (std::is_arithmetic<S>::value)
    return static_cast<double>(x);
  else
    return x.value();
}

/// r reports M(q) not positive definite at `joint`, with NaN accelerations.
template <typename JointVector>
::testing::AssertionResult fails_at(const ForwardDynamicsResult<JointVector>& r, Eigen::Index joint) {
  Eigen::VectorXd qdd(r.qdd.size());
  for (Eigen::Index i = 0; i < r.qdd.size(); ++i) qdd(i) = value_of(r.qdd(i));
  if (r || r.status != DynamicsStatus::mass_matrix_not_positive_definite)
    return ::testing::AssertionFailure() << "status ok, qdd = " << qdd.transpose();
  if (r.joint != joint) return ::testing::AssertionFailure() << "failed at joint " << r.joint << ", not " << joint;
  if (!qdd.array().isNaN().all()) return ::testing::AssertionFailure() << "qdd not NaN: " << qdd.transpose();
  return ::testing::AssertionSuccess();
}

/// qdd by Eigen's LLT of mass_matrix(q), as forward_dynamics computed it before its status.
template <typename D, typename V>
typename D::JointVector llt_solve(const D& d, const V& q, const V& qd, const V& tau,
                                  const Wrench<typename D::Scalar>& F = Wrench<typename D::Scalar>()) {
  const typename D::JointVector zero = D::JointVector::Zero(d.n_joints());
  const Eigen::LLT<typename D::MassMatrix> llt(mass_matrix(d, q));
  return llt.solve(typename D::JointVector(tau - inverse_dynamics(d, q, qd, zero, F)));
}

TYPED_TEST(DynamicsTest, ForwardDynamicsOfPhysicalArmsIsOkAndEigensCholeskySolve) {
  using S = TypeParam;
  const Wrench<S> F(Eigen::Matrix<S, 3, 1>(S(1), S(-2), S(3)), Eigen::Matrix<S, 3, 1>(S(0.5), S(0.1), S(-0.3)));
  // The Panda-like arm within its limits: the factorization is Eigen's
  // unblocked LLT, operation for operation, so the bits are those of before.
  std::mt19937 rng(40);
  const Panda<S> panda = panda_with<S>(PandaLike<S>().inertias);
  for (int trial = 0; trial < 200; ++trial) {
    const PandaState<S> x(rng);
    const auto r = forward_dynamics(panda, x.q, x.qd, x.tau, F);
    ASSERT_TRUE(r) << "q = " << x.q.transpose();
    EXPECT_EQ(r.status, DynamicsStatus::ok);
    EXPECT_EQ(r.joint, -1);
    EXPECT_EQ(r.qdd, llt_solve(panda, x.q, x.qd, x.tau, F)) << "q = " << x.q.transpose();
  }
  // Random arms of 1 to 8 revolute and prismatic joints.
  for (int trial = 0; trial < 80; ++trial) {
    const int n = 1 + trial % kMax;
    const Dyn<S> d = dynamics_of<S>(random_arm(rng, n));
    const auto q = random_joints<S>(rng, n, 3.0), qd = random_joints<S>(rng, n, 2.0),
               tau = random_joints<S>(rng, n, 20.0);
    const auto r = forward_dynamics(d, q, qd, tau, F);
    ASSERT_TRUE(r) << "n = " << n;
    EXPECT_EQ(r.qdd, llt_solve(d, q, qd, tau, F)) << "n = " << n;
  }
}

TYPED_TEST(DynamicsTest, ForwardDynamicsReportsAMasslessLink) {
  using S = TypeParam;
  std::mt19937 rng(41);
  // The Panda-like arm without its hand (the last link): M's last row is 0.
  std::array<SpatialInertia<S>, 7> I = PandaLike<S>().inertias;
  I[6] = SpatialInertia<S>();
  const Panda<S> panda = panda_with<S>(I);
  for (int trial = 0; trial < 50; ++trial) {
    const PandaState<S> x(rng);
    EXPECT_TRUE(fails_at(forward_dynamics(panda, x.q, x.qd, x.tau), 6));
  }
  // Random arms whose last link is massless, and a chain without inertias (M = 0).
  for (int n = 1; n <= kMax; ++n) {
    Arm arm = random_arm(rng, n);
    arm.I[static_cast<std::size_t>(n - 1)] = SpatialInertia<double>();
    const Dyn<S> d = dynamics_of<S>(arm);
    const auto q = random_joints<S>(rng, n, 3.0), qd = random_joints<S>(rng, n, 2.0);
    EXPECT_TRUE(fails_at(forward_dynamics(d, q, qd, qd), n - 1)) << "n = " << n;
    const Dyn<S> massless(ChainOf<S>(arm.S.template cast<S>(), arm.M.template cast<S>()));
    EXPECT_TRUE(fails_at(forward_dynamics(massless, q, qd, qd), 0)) << "n = " << n;
  }
  // A massless link inside the chain is fine: the links after it move with its joint.
  I = PandaLike<S>().inertias;
  I[3] = SpatialInertia<S>();
  const PandaState<S> x(rng);
  EXPECT_TRUE(forward_dynamics(panda_with<S>(I), x.q, x.qd, x.tau));
}

/// The Panda-like arm with each link a point mass (its own mass, I_c = 0)
/// on its joint's axis, `offset` from it (0: on the axis) along a direction
/// normal to the axis, at `along` times i + 1 from the axis' point.
template <typename S>
Panda<S> panda_point_masses(double offset, double along) {
  const PandaLike<double> arm;
  std::array<SpatialInertia<S>, 7> I;
  for (int i = 0; i < 7; ++i) {
    const Eigen::Vector3d w = arm.screws.col(i).tail<3>(), v = arm.screws.col(i).head<3>();
    const Eigen::Vector3d point = w.cross(v);  // the axis' point nearest the origin (v = -w x p)
    const Eigen::Vector3d normal = w.unitOrthogonal();
    const Eigen::Vector3d c = point + along * (i + 1) * w + offset * normal;
    I[static_cast<std::size_t>(i)] =
        SpatialInertia<double>(arm.inertias[static_cast<std::size_t>(i)].mass(), c, Eigen::Matrix3d::Zero())
            .template cast<S>();
  }
  return panda_with<S>(I);
}

TYPED_TEST(DynamicsTest, ForwardDynamicsReportsPointMassesOnTheJointAxes) {
  using S = TypeParam;
  std::mt19937 rng(42);
  // The last link then has no inertia about its joint's axis: M_77 and its
  // row are 0 but for rounding, which Eigen's LLT mostly took as a pivot.
  const Panda<S> panda = panda_point_masses<S>(0.0, 0.05);
  int unnoticed = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const PandaState<S> x(rng);
    EXPECT_TRUE(fails_at(forward_dynamics(panda, x.q, x.qd, x.tau), 6)) << "q = " << x.q.transpose();
    const auto before = llt_solve(panda, x.q, x.qd, x.tau);
    if (Eigen::LLT<typename Panda<S>::MassMatrix>(mass_matrix(panda, x.q)).info() == Eigen::Success) {
      ++unnoticed;
      EXPECT_GT(max_abs(before), LD(1e4)) << "q = " << x.q.transpose();  // |qdd| of a real arm: < 1e3
    }
  }
  if (std::is_same<S, double>::value) {
    EXPECT_GT(unnoticed, 0);  // what the status is for
  }
}

TYPED_TEST(DynamicsTest, ForwardDynamicsReportsANearlySingularMassMatrix) {
  using S = TypeParam;
  std::mt19937 rng(43);
  // Point masses eps^(1/2) of a metre off their axes: M_77 = m d^2 is
  // eps / 4 of the scale of the terms it is summed from (s = 2.8 kg m^2 for
  // the hand), so it is rounding: below the threshold.
  const double offset = std::sqrt(double(std::numeric_limits<S>::epsilon()));
  const Panda<S> panda = panda_point_masses<S>(offset, 0.05);
  for (int trial = 0; trial < 100; ++trial) {
    const PandaState<S> x(rng);
    EXPECT_TRUE(fails_at(forward_dynamics(panda, x.q, x.qd, x.tau), 6)) << "q = " << x.q.transpose();
  }
  // Eigen's LLT took most of these pivots (double): accelerations of 1e9 and more.
  if (std::is_same<S, double>::value) {
    const PandaState<S> x(rng);
    EXPECT_EQ(Eigen::LLT<typename Panda<S>::MassMatrix>(mass_matrix(panda, x.q)).info(), Eigen::Success);
    EXPECT_GT(max_abs(llt_solve(panda, x.q, x.qd, x.tau)), LD(1e9));
  }
}

TYPED_TEST(DynamicsTest, ForwardDynamicsReportsAnIndefiniteInertia) {
  using S = TypeParam;
  std::mt19937 rng(44);
  // The hand's I_zz with a sign error (-I_zz: principal moments that break
  // the triangle inequality, not positive definite), as a URDF may give it:
  // the hand turning about its own axis has a negative kinetic energy.
  std::array<SpatialInertia<S>, 7> I = PandaLike<S>().inertias;
  typename SpatialInertia<S>::Matrix3 Ic = I[6].inertia();
  Ic(2, 2) = -Ic(2, 2);
  I[6] = SpatialInertia<S>(I[6].mass(), I[6].com(), Ic);
  ASSERT_FALSE(I[6].is_physical());
  const Panda<S> panda = panda_with<S>(I);
  for (int trial = 0; trial < 50; ++trial) {
    const PandaState<S> x(rng);
    EXPECT_TRUE(fails_at(forward_dynamics(panda, x.q, x.qd, x.tau), 6)) << "q = " << x.q.transpose();
  }
  // An inertia that breaks the triangle inequality (I_zz = 3 (I_xx + I_yy))
  // but is positive definite gives a positive definite M: such inertias are
  // accepted (SpatialInertia::is_physical tells), and M is what is checked.
  Ic(2, 2) = 3 * (Ic(0, 0) + Ic(1, 1));
  I[6] = SpatialInertia<S>(I[6].mass(), I[6].com(), Ic);
  ASSERT_FALSE(I[6].is_physical());
  const Panda<S> triangle = panda_with<S>(I);
  for (int trial = 0; trial < 50; ++trial) {
    const PandaState<S> x(rng);
    const auto r = forward_dynamics(triangle, x.q, x.qd, x.tau);
    ASSERT_TRUE(r) << "q = " << x.q.transpose();
    EXPECT_EQ(r.qdd, llt_solve(triangle, x.q, x.qd, x.tau));
  }
}

TYPED_TEST(DynamicsTest, ForwardDynamicsThresholdOnBothSides) {
  using S = TypeParam;
  // One revolute joint about z through the origin moving a thin disc of
  // moments (J/2, J/2, J) centered 1 m up the axis, m = 1 kg: M = J exactly
  // (the parallel-axis terms cancel exactly along the axis) and the pivot's
  // scale is s = tr(I_c) + 2 m |c|^2 = 2 J + 2, so d / s = J / (2 J + 2).
  const S tol = S(chasles::ThresholdsOf<S>::mass_matrix_pivot_tolerance);
  typename Chain<S, 1>::Screws screw;
  screw << S(0), S(0), S(0), S(0), S(0), S(1);
  const auto disc = [&](S J) {
    typename Chain<S, 1>::Inertias I;
    I[0] = SpatialInertia<S>(S(1), Eigen::Matrix<S, 3, 1>(S(0), S(0), S(1)),
                             Eigen::Matrix<S, 3, 1>(J / 2, J / 2, J).asDiagonal().toDenseMatrix());
    return Chain<S, 1>(screw, SE3<S>(), I, Eigen::Matrix<S, 3, 1>(S(0), S(0), S(-9.81)));
  };
  for (const S q : {S(0), S(0.3), S(-2)}) {
    const Eigen::Matrix<S, 1, 1> q1(q), qd(S(0.5)), tau(S(1e-14));
    // d / s = 1.5 tol: ok, qdd = tau / J (no gravity torque about z, no Coriolis term for one joint).
    const S above = 3 * tol;
    const auto r = forward_dynamics(disc(above), q1, qd, tau);
    ASSERT_TRUE(r) << "q = " << q;
    EXPECT_EQ(mass_matrix(disc(above), q1)(0, 0), above);
    EXPECT_TRUE(near<S>(r.qdd, Eigen::Matrix<LD, 1, 1>(LD(tau(0)) / LD(above)), 4)) << r.qdd;
    // d / s = 0.5 tol: not positive definite, though Eigen's LLT takes it.
    const S below = tol;
    EXPECT_TRUE(fails_at(forward_dynamics(disc(below), q1, qd, tau), 0)) << "q = " << q;
    using M1 = Eigen::Matrix<S, 1, 1>;
    EXPECT_EQ(Eigen::LLT<M1>(mass_matrix(disc(below), q1)).info(), Eigen::Success);
  }
  // A pivot of the smallest normal number (a 1 kg disc of J = 1e-38 or
  // 1e-308 kg m^2), and of 0.
  const Eigen::Matrix<S, 1, 1> q0(S(0.1)), qd0(S(0)), tau0(S(1));
  EXPECT_TRUE(fails_at(forward_dynamics(disc(S(std::numeric_limits<S>::min())), q0, qd0, tau0), 0));
  EXPECT_TRUE(fails_at(forward_dynamics(disc(S(0)), q0, qd0, tau0), 0));
}

TYPED_TEST(DynamicsTest, ForwardDynamicsOfANaNIsNaNNotAFailure) {
  using S = TypeParam;
  std::mt19937 rng(45);
  const Panda<S> panda = panda_with<S>(PandaLike<S>().inertias);
  PandaState<S> x(rng);
  x.tau(2) = std::numeric_limits<S>::quiet_NaN();
  auto r = forward_dynamics(panda, x.q, x.qd, x.tau);
  EXPECT_TRUE(r);
  EXPECT_TRUE(r.qdd.array().isNaN().any());
  x.q(0) = std::numeric_limits<S>::quiet_NaN();
  r = forward_dynamics(panda, x.q, x.qd, x.tau);
  EXPECT_TRUE(r);
  EXPECT_TRUE(r.qdd.array().isNaN().all());
}

TEST(Dynamics, ForwardDynamicsWithAutomaticDifferentiation) {
  // d qdd / d tau = M(q)^-1 through the factorization, and the status with
  // autodiff scalars (compared by value).
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 7, 1>>;
  std::mt19937 rng(46);
  const PandaLike<double> arm;
  std::array<SpatialInertia<AD>, 7> Ia;
  for (std::size_t i = 0; i < 7; ++i) Ia[i] = arm.inertias[i].cast<AD>();
  const Panda<AD> da = panda_with<AD>(Ia);
  const Panda<double> d = panda_with<double>(arm.inertias);
  for (int trial = 0; trial < 10; ++trial) {
    const PandaState<double> x(rng);
    Eigen::Matrix<AD, 7, 1> tau;
    for (int i = 0; i < 7; ++i) tau(i) = AD(x.tau(i), 7, i);
    const auto r = forward_dynamics(da, x.q.cast<AD>(), x.qd.cast<AD>(), tau);
    ASSERT_TRUE(r);
    Eigen::Matrix<double, 7, 7> J;
    Eigen::Matrix<double, 7, 1> value;
    for (int i = 0; i < 7; ++i) {
      J.row(i) = r.qdd(i).derivatives().transpose();
      value(i) = r.qdd(i).value();
    }
    const Eigen::Matrix<double, 7, 7> Mq = mass_matrix(d, x.q), Minv = Mq.inverse();
    // both sides round to cond(M) eps |M^-1| (the hand's inertia is small: cond ~ 1e4)
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 7, 7>> es(Mq);
    const LD cond = LD(es.eigenvalues().maxCoeff() / es.eigenvalues().minCoeff());
    EXPECT_TRUE(near<double>(J, Minv, 64 * cond, max_abs(Minv)));
    // the value: the double computation, to the rounding of autodiff's own operation order (times cond(M))
    const Eigen::Matrix<double, 7, 1> qdd = forward_dynamics(d, x.q, x.qd, x.tau).qdd;
    EXPECT_TRUE(near<double>(value, qdd, 64 * cond, max_abs(qdd)));
  }
  Ia[6] = SpatialInertia<AD>();
  const PandaState<double> x(rng);
  EXPECT_TRUE(fails_at(forward_dynamics(panda_with<AD>(Ia), x.q.cast<AD>(), x.qd.cast<AD>(), x.tau.cast<AD>()), 6));
}

// ---- the derivatives (dynamics_derivatives.hpp) -----------------------------------

/// random_arm with some joints helical (a revolute screw plus pitch h w,
/// h in [-0.3, 0.3] m/rad) and every screw scaled by a factor in [0.5, 2]
/// (a joint variable in other units than radians or metres).
Arm random_screw_arm(std::mt19937& rng, int n) {
  Arm a = random_arm(rng, n);
  std::uniform_real_distribution<double> pitch(-0.3, 0.3), norm(0.5, 2.0), coin(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    if (a.S.col(i).tail<3>().squaredNorm() > 0 && coin(rng) < 0.5)
      a.S.col(i).head<3>() += pitch(rng) * a.S.col(i).tail<3>();
    a.S.col(i) *= norm(rng);
  }
  return a;
}

/// An autodiff scalar with derivatives with respect to 3 kMax variables
/// (fixed-size: constants carry zero derivatives, not empty ones).
constexpr int kVariables = 3 * kMax;
using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, kVariables, 1>>;

/// x as the autodiff variables first, first + 1, ...
Dyn<AD>::JointVector variables(const Dyn<double>::JointVector& x, int first) {
  Dyn<AD>::JointVector v(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) v(i) = AD(x(i), kVariables, first + static_cast<int>(i));
  return v;
}

/// Columns [first, first + n) of the derivatives of r.
Eigen::MatrixXd derivatives_of(const Dyn<AD>::JointVector& r, int first, int n) {
  Eigen::MatrixXd J(r.size(), n);
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    for (int j = 0; j < n; ++j) J(i, j) = r(i).derivatives()(first + j);
  }
  return J;
}

Dyn<double>::JointVector joints(std::mt19937& rng, int n, double scale) { return random_joints<double>(rng, n, scale); }

TEST(DynamicsDerivatives, InverseDynamicsEqualsAutomaticDifferentiation) {
  // d tau / d q and d tau / d qd against the derivatives of inverse_dynamics
  // itself (forward-mode autodiff through the recursion), with a tip
  // wrench, on 60 random arms of 1 to 8 joints.
  std::mt19937 rng(50);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 1 + trial % kMax;
    const Arm a = random_screw_arm(rng, n);
    const Dyn<double> d = dynamics_of<double>(a);
    const Dyn<AD> da = dynamics_of<AD>(a);
    const Dyn<double>::JointVector q = joints(rng, n, 3), qd = joints(rng, n, 2), qdd = joints(rng, n, 2);
    const Eigen::Matrix<double, 6, 1> w = Eigen::Matrix<double, 6, 1>::Random() * 10;
    const auto D = chasles::inverse_dynamics_derivatives(d, q, qd, qdd, Wrench<double>(w));
    const Dyn<AD>::JointVector tau = inverse_dynamics(da, variables(q, 0), variables(qd, n),
                                                      Dyn<AD>::JointVector(qdd.cast<AD>()), Wrench<AD>(w.cast<AD>()));
    EXPECT_TRUE(near<double>(D.dtau_dq, derivatives_of(tau, 0, n), kPerJoint * n)) << "trial " << trial;
    EXPECT_TRUE(near<double>(D.dtau_dqd, derivatives_of(tau, n, n), kPerJoint * n)) << "trial " << trial;
  }
}

TEST(DynamicsDerivatives, InverseDynamicsEqualsCentralDifferencesInLongDouble) {
  // A second oracle, independent of the recursion's code: central
  // differences of inverse_dynamics in long double with step 1e-5
  // (truncation about 1e-10 of the third derivative, rounding about
  // 1e-19 / 1e-5 of tau: 1e-8 relative is far above both).
  std::mt19937 rng(51);
  for (int trial = 0; trial < 16; ++trial) {
    const int n = 1 + trial % kMax;
    const Arm a = random_screw_arm(rng, n);
    const Dyn<double> d = dynamics_of<double>(a);
    const Dyn<LD> dl = dynamics_of<LD>(a);
    const Dyn<double>::JointVector q = joints(rng, n, 3), qd = joints(rng, n, 2), qdd = joints(rng, n, 2);
    const auto D = chasles::inverse_dynamics_derivatives(d, q, qd, qdd);
    const LD h = 1e-5L;
    const Dyn<LD>::JointVector ql = q.cast<LD>(), qdl = qd.cast<LD>(), qddl = qdd.cast<LD>();
    Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic> cq(n, n), cqd(n, n);
    for (int j = 0; j < n; ++j) {
      Dyn<LD>::JointVector e = Dyn<LD>::JointVector::Zero(n);
      e(j) = h;
      cq.col(j) = (inverse_dynamics(dl, Dyn<LD>::JointVector(ql + e), qdl, qddl) -
                   inverse_dynamics(dl, Dyn<LD>::JointVector(ql - e), qdl, qddl)) /
                  (2 * h);
      cqd.col(j) = (inverse_dynamics(dl, ql, Dyn<LD>::JointVector(qdl + e), qddl) -
                    inverse_dynamics(dl, ql, Dyn<LD>::JointVector(qdl - e), qddl)) /
                   (2 * h);
    }
    const LD scale = std::max({LD(1), max_abs(cq), max_abs(cqd)});
    EXPECT_LE(max_abs_diff(D.dtau_dq.cast<LD>(), cq), 1e-8L * scale) << "trial " << trial;
    EXPECT_LE(max_abs_diff(D.dtau_dqd.cast<LD>(), cqd), 1e-8L * scale) << "trial " << trial;
  }
}

TEST(DynamicsDerivatives, ForwardDynamicsEqualsAutomaticDifferentiation) {
  // d qdd / d (q, qd, tau) against autodiff through forward_dynamics (its
  // Cholesky solve included), and d qdd / d tau = M(q)^-1 =
  // mass_matrix_inverse. The two differ by rounding, which cond(M) and the
  // cancellation in the terms of M(q) and tau (a link's inertia about the
  // base origin, m |c|^2 against I_c) magnify: 1e-11 cond(M) relative to the
  // result (seen: 1e-12 at cond(M) 1); an error in the formulas is of the
  // result's own size.
  std::mt19937 rng(52);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 1 + trial % kMax;
    const Arm a = random_screw_arm(rng, n);
    const Dyn<double> d = dynamics_of<double>(a);
    const Dyn<AD> da = dynamics_of<AD>(a);
    const Dyn<double>::JointVector q = joints(rng, n, 3), qd = joints(rng, n, 2), tau = joints(rng, n, 20);
    const Eigen::Matrix<double, 6, 1> w = Eigen::Matrix<double, 6, 1>::Random() * 10;
    const auto D = chasles::forward_dynamics_derivatives(d, q, qd, tau, Wrench<double>(w));
    ASSERT_TRUE(D) << "trial " << trial;
    EXPECT_EQ(D.joint, -1);
    const auto r =
        forward_dynamics(da, variables(q, 0), variables(qd, n), variables(tau, 2 * n), Wrench<AD>(w.cast<AD>()));
    ASSERT_TRUE(r);
    const Eigen::MatrixXd Mq = mass_matrix(d, q);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Mq);
    const LD tol = 1e-11L * LD(es.eigenvalues().maxCoeff() / es.eigenvalues().minCoeff());
    const auto close = [&](const Dyn<double>::MassMatrix& a, const Eigen::MatrixXd& b) {
      return max_abs_diff(a, b) <= tol * std::max(LD(1), max_abs(b));
    };
    EXPECT_TRUE(close(D.dqdd_dq, derivatives_of(r.qdd, 0, n))) << "trial " << trial;
    EXPECT_TRUE(close(D.dqdd_dqd, derivatives_of(r.qdd, n, n))) << "trial " << trial;
    EXPECT_TRUE(close(D.dqdd_dtau, derivatives_of(r.qdd, 2 * n, n))) << "trial " << trial;
    const auto Minv = chasles::mass_matrix_inverse(d, q);
    ASSERT_TRUE(Minv);
    EXPECT_EQ(Minv.inverse, D.dqdd_dtau);  // the same factorization and solves
    EXPECT_TRUE(close(Dyn<double>::MassMatrix(Mq * Minv.inverse), Eigen::MatrixXd::Identity(n, n)));
  }
}

TEST(ArticulatedBody, EqualsForwardDynamics) {
  // The articulated-body algorithm against the composite inertias and
  // Cholesky solve, on the random arms (helical joints, screws of any norm,
  // a tip wrench): the same accelerations to rounding (cond(M) eps).
  std::mt19937 rng(55);
  for (int trial = 0; trial < 80; ++trial) {
    const int n = 1 + trial % kMax;
    const Dyn<double> d = dynamics_of<double>(random_screw_arm(rng, n));
    const Dyn<double>::JointVector q = joints(rng, n, 3), qd = joints(rng, n, 2), tau = joints(rng, n, 20);
    const Wrench<double> w(Eigen::Matrix<double, 6, 1>(Eigen::Matrix<double, 6, 1>::Random() * 10));
    const auto crba = forward_dynamics(d, q, qd, tau, w);
    const auto aba = chasles::forward_dynamics_articulated(d, q, qd, tau, w);
    ASSERT_TRUE(crba && aba) << "trial " << trial;
    EXPECT_EQ(aba.joint, -1);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(mass_matrix(d, q)));
    const LD cond = LD(es.eigenvalues().maxCoeff() / es.eigenvalues().minCoeff());
    EXPECT_TRUE(near<double>(aba.qdd, crba.qdd, kPerJoint * n * cond, max_abs(tau))) << "trial " << trial;
  }
  // The Panda-like arm in float and double: rounding only.
  const Panda<float> f = panda_with<float>(PandaLike<float>().inertias);
  for (int trial = 0; trial < 20; ++trial) {
    const PandaState<float> x(rng);
    EXPECT_TRUE(near<float>(chasles::forward_dynamics_articulated(f, x.q, x.qd, x.tau).qdd,
                            forward_dynamics(f, x.q, x.qd, x.tau).qdd, 1e4L, max_abs(x.tau)));
  }
}

TEST(ArticulatedBody, ReportsWhereTheArticulatedInertiaIsNotPositive) {
  // A massless last link: the tip's articulated inertia is zero, its pivot
  // fails first (the algorithm works from the tip in); an indefinite
  // inertia gives a negative pivot. NaN accelerations, the joint named.
  std::array<SpatialInertia<double>, 7> I = PandaLike<double>().inertias;
  I[6] = SpatialInertia<double>();
  std::mt19937 rng(56);
  const PandaState<double> x(rng);
  EXPECT_TRUE(fails_at(chasles::forward_dynamics_articulated(panda_with<double>(I), x.q, x.qd, x.tau), 6));
  I = PandaLike<double>().inertias;
  I[6] = SpatialInertia<double>::from_matrix_unchecked(Eigen::Matrix<double, 6, 6>(-I[6].matrix()));
  EXPECT_TRUE(fails_at(chasles::forward_dynamics_articulated(panda_with<double>(I), x.q, x.qd, x.tau), 6));
}

TEST(ArticulatedBody, ForwardDynamicsTakesItOnLongChains) {
  // forward_dynamics is forward_dynamics_composite below
  // articulated_body_min_joints joints and forward_dynamics_articulated from
  // there on (bit for bit: the same function runs), and the two agree on
  // the long chains too (revolute joints about random axes, boxes of 1 to
  // 4 kg, as bench/bench_chain_length.cpp): to cond(M) eps per joint.
  using Long = Chain<double, Eigen::Dynamic, 32>;
  constexpr Eigen::Index kFrom = chasles::articulated_body_min_joints;
  static_assert(kFrom > 7 && kFrom < 32, "the arms of the field use the composite inertias");
  std::mt19937 rng(57);
  std::uniform_real_distribution<double> u(-1, 1), m(1, 4), side(0.05, 0.3);
  for (const Eigen::Index n : {kFrom - 1, kFrom, Eigen::Index(32)}) {
    Long::Screws S(6, n);
    Long::Inertias inertias;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    for (Eigen::Index i = 0; i < n; ++i) {
      S.col(i) = Long::revolute_screw(point, Eigen::Vector3d(u(rng), u(rng), u(rng)));
      const double mass = m(rng), x = side(rng), y = side(rng), z = side(rng);
      const Eigen::Vector3d moments(mass * (y * y + z * z) / 12, mass * (x * x + z * z) / 12,
                                    mass * (x * x + y * y) / 12);
      inertias[std::size_t(i)] =
          SpatialInertia<double>(mass, point + Eigen::Vector3d(0.05, 0, 0), moments.asDiagonal());
      point += Eigen::Vector3d(0.1, 0.02 * u(rng), 0.02 * u(rng));
    }
    const Long chain(S, SE3<double>(), inertias);
    for (int trial = 0; trial < 5; ++trial) {
      Long::JointVector q(n), qd(n), tau(n);
      for (Eigen::Index j = 0; j < n; ++j) q(j) = 3 * u(rng), qd(j) = 2 * u(rng), tau(j) = 10 * u(rng);
      Eigen::Matrix<double, 6, 1> wrench;
      for (int k = 0; k < 6; ++k) wrench(k) = u(rng);
      const Wrench<double> w(wrench);
      const auto fd = chasles::forward_dynamics(chain, q, qd, tau, w);
      const auto crba = chasles::forward_dynamics_composite(chain, q, qd, tau, w);
      const auto aba = chasles::forward_dynamics_articulated(chain, q, qd, tau, w);
      ASSERT_TRUE(fd && crba && aba) << "n = " << n;
      EXPECT_EQ(fd.qdd, n >= kFrom ? aba.qdd : crba.qdd) << "n = " << n;
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(mass_matrix(chain, q)));
      const LD cond = LD(es.eigenvalues().maxCoeff() / es.eigenvalues().minCoeff());
      EXPECT_TRUE(near<double>(aba.qdd, crba.qdd, kPerJoint * LD(n) * cond, max_abs(tau))) << "n = " << n;
    }
  }
}

TEST(DynamicsDerivatives, FailuresAreForwardDynamicsFailures) {
  // A massless last link: forward_dynamics fails at joint 6, and so do its
  // derivatives and M(q)^-1, all NaN.
  std::array<SpatialInertia<double>, 7> I = PandaLike<double>().inertias;
  I[6] = SpatialInertia<double>();
  const Panda<double> arm = panda_with<double>(I);
  std::mt19937 rng(53);
  const PandaState<double> x(rng);
  const auto D = chasles::forward_dynamics_derivatives(arm, x.q, x.qd, x.tau);
  EXPECT_FALSE(D);
  EXPECT_EQ(D.status, DynamicsStatus::mass_matrix_not_positive_definite);
  EXPECT_EQ(D.joint, 6);
  EXPECT_TRUE(D.dqdd_dq.array().isNaN().all() && D.dqdd_dqd.array().isNaN().all() && D.dqdd_dtau.array().isNaN().all());
  const auto Minv = chasles::mass_matrix_inverse(arm, x.q);
  EXPECT_FALSE(Minv);
  EXPECT_EQ(Minv.joint, 6);
  EXPECT_TRUE(Minv.inverse.array().isNaN().all());
}

TEST(DynamicsDerivatives, FloatAgreesWithDouble) {
  // The Panda-like arm in float against double: rounding only.
  std::mt19937 rng(54);
  const Panda<double> d = panda_with<double>(PandaLike<double>().inertias);
  const Panda<float> f = panda_with<float>(PandaLike<float>().inertias);
  for (int trial = 0; trial < 20; ++trial) {
    const PandaState<double> x(rng);
    const Eigen::Matrix<double, 7, 1> qdd = x.tau / 10;
    const auto Dd = chasles::inverse_dynamics_derivatives(d, x.q, x.qd, qdd);
    const auto Df = chasles::inverse_dynamics_derivatives(f, Eigen::Matrix<float, 7, 1>(x.q.cast<float>()),
                                                          Eigen::Matrix<float, 7, 1>(x.qd.cast<float>()),
                                                          Eigen::Matrix<float, 7, 1>(qdd.cast<float>()));
    EXPECT_TRUE(near<float>(Df.dtau_dq.cast<double>(), Dd.dtau_dq, kPerJoint * 7, max_abs(Dd.dtau_dq)));
    EXPECT_TRUE(near<float>(Df.dtau_dqd.cast<double>(), Dd.dtau_dqd, kPerJoint * 7, max_abs(Dd.dtau_dqd)));
  }
}

}  // namespace
