// chasles against Pinocchio (4.x) in one binary and one run, on the UR5,
// Panda and xArm7 of example-robot-data (bench/dynamics_vs_pinocchio.py
// compares the two from Python; this is the C++ side, without the calls'
// overhead): inverse dynamics (rnea), the mass matrix (crba, both of
// Pinocchio's conventions), gravity torques, forward dynamics (aba, both
// conventions; chasles' forward_dynamics, and its articulated-body
// forward_dynamics_articulated beside it), the tool's pose with its body
// Jacobian (chasles' fused body pass, Chain::forward_body(q, J), against
// Pinocchio's computeFrameJacobian(LOCAL), whose backward pass leaves the
// tool's pose in data.iMf[0], and against computeJointJacobians +
// updateFramePlacement + getFrameJacobian), the derivatives of inverse and
// forward dynamics (computeRNEADerivatives, computeABADerivatives) and
// M(q)^-1 (computeMinverse).
//
// Protocol (the project's rule for timings on a shared machine): per arm,
// 1000 random states (q uniform within the limits clipped to [-pi, pi]; qd,
// qdd, tau uniform in [-2, 2]); each operation is timed over all the states,
// chasles then Pinocchio, round after round (15 rounds), and each library
// keeps its least-disturbed (minimum) round: ns per call and the ratio
// chasles / Pinocchio, with the medians beside them. Before any timing,
// every operation is compared on every state: largest relative difference
// max |a - b| / max(1, max |b|) at most 1e-10, or the program stops.
//
// The models: chasles loads the URDF with its own loader (chain_from_urdf of
// chasles/urdf.hpp, Debian's urdfdom); Pinocchio with
// pinocchio::urdf::buildModel and buildReducedModel (the joints off the
// chain locked at neutral, as the Python comparison does), in the pin
// wheel's own compiled code. Each loader runs in a module of its own, this
// file built again with CHASLES_PINBENCH_LOAD_CHASLES or
// CHASLES_PINBENCH_LOAD_PINOCCHIO (portable flags, dlopen'ed with
// RTLD_DEEPBIND), which hands back plain numbers: chasles' stored chain
// (screws, home pose, types, limits, inertias: the benchmark builds it again
// with Chain's Stored constructor), and Pinocchio's joint types, placements,
// inertias and tool frame (the benchmark builds its pinocchio::Model again
// with addJoint, the same numbers bit for bit). Three reasons:
// - layouts: code compiled with -march=native (AVX-512 here) aligns Eigen's
//   fixed-size objects and allocates its dynamic ones to 64 bytes, portable
//   code to 16 (and with plain malloc): a Model built by the wheel and freed
//   here would corrupt the heap (chasles' own loader had the same fault
//   until its detail::UrdfDescription held standard containers only);
// - urdfdom twice: the wheel's urdfdom 6 and Debian's urdfdom 3 export the
//   same unversioned symbols (urdf::parseURDF): in one link map, one would
//   parse for the other; with RTLD_DEEPBIND each module resolves to its own;
// - the same chasles loader for both builds of the benchmark.
// Pinocchio's algorithms are compiled here from its headers with chasles'
// flags (the same -O3, the same -march=native or not): the two libraries'
// algorithms under the same compiler and the same flags. The wheel's
// precompiled instantiations are not used (nothing here defines
// PINOCCHIO_ENABLE_TEMPLATE_INSTANTIATION).
//
// Build and run (bench/CMakeLists.txt: optional, only where Pinocchio's
// headers are found; the pin and example-robot-data wheels in the venv):
//
//   cmake -S . -B build/pinbench -G Ninja -DCMAKE_BUILD_TYPE=Release -DCHASLES_BUILD_BENCH=ON
//         -DCHASLES_PINOCCHIO_PREFIX="$(build/dev/bin/python -m cmeel cmake)"
//   nice -n 19 ninja -C build/pinbench -j1 chasles_bench_vs_pinocchio_portable
//   nice -n 19 ninja -C build/pinbench -j1 chasles_bench_vs_pinocchio_native
//   build/pinbench/bench/chasles_bench_vs_pinocchio_portable
//   build/pinbench/bench/chasles_bench_vs_pinocchio_native
//
// (--arm UR5 times one arm, --op "mass matrix" the operations whose name
// contains the text.)
//
// (cmake's arguments on one line). Options: --rounds R (15), --states N
// (1000), --arm NAME (one arm), --robots DIR (example-robot-data's robots/
// directory; default: the one CMake found), --seed S.
#include <cstddef>
#include <cstring>

namespace pinbench {

/// What the loader modules hand back: plain numbers, no Eigen or Pinocchio
/// type (the modules and the benchmark do not share their layouts).
constexpr int kMaxPodJoints = 16;
constexpr std::size_t kName = 128;

/// Pinocchio's joint types that a URDF's 1-dof joints become.
enum JointKind : int {
  kRX,
  kRY,
  kRZ,
  kRevoluteUnaligned,
  kRUBX,
  kRUBY,
  kRUBZ,
  kRevoluteUnboundedUnaligned,
  kPX,
  kPY,
  kPZ,
  kPrismaticUnaligned,
};

struct JointPod {
  char name[kName];
  int kind;
  double axis[3];       ///< the unaligned joints' axis
  double rotation[9];   ///< jointPlacements[i]: column-major R
  double translation[3];
  double mass;
  double lever[3];
  double inertia[6];  ///< Symmetric3's data (xx, xy, yy, xz, yz, zz)
};

struct ArmPod {
  int n;
  JointPod joints[kMaxPodJoints];
  int tip_joint;  ///< the tool frame's parent joint
  double tip_rotation[9];
  double tip_translation[3];
  double gravity[3];
  char error[512];
};

/// chasles' chain as Chain stores it (Chain's accessors), in the world frame.
struct ChainPod {
  int n;
  char names[kMaxPodJoints][kName];
  int types[kMaxPodJoints];  ///< chasles::JointType
  double screws[kMaxPodJoints][6];
  double lower[kMaxPodJoints], upper[kMaxPodJoints], velocity[kMaxPodJoints], effort[kMaxPodJoints];
  double mass[kMaxPodJoints], com[kMaxPodJoints][3], inertia[kMaxPodJoints][9];  ///< column-major I_c
  double home[16], base[16], tool[16];  ///< column-major 4 x 4
  double gravity[3];
  char error[512];
};

/// chasles_pinbench_load_pinocchio(urdf, tip, keep, n_keep, out): 0 on
/// success; else out->error says why.
using LoadPinocchio = int (*)(const char*, const char*, const char* const*, int, ArmPod*);
/// chasles_pinbench_load_chasles(urdf, tip, out): the same.
using LoadChasles = int (*)(const char*, const char*, ChainPod*);

inline void copy_string(char* to, std::size_t size, const char* from) {
  std::strncpy(to, from, size - 1);
  to[size - 1] = '\0';
}

}  // namespace pinbench

#if defined(CHASLES_PINBENCH_LOAD_PINOCCHIO)
// ---------------------------------------------------------------------------
// The Pinocchio loader module: Pinocchio's URDF parser and
// buildReducedModel, in the wheel's compiled code and with its (portable)
// layouts.

#include <exception>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/algorithm/model.hpp>
#include <pinocchio/multibody.hpp>
#include <pinocchio/parsers/urdf.hpp>

namespace {

template <typename Vector>
void copy_axis(const Vector& axis, double* out) {
  for (int k = 0; k < 3; ++k) out[k] = axis(k);
}

int joint_kind(const pinocchio::Model::JointModel& joint, double* axis) {
  const std::string s = joint.shortname();
  if (s == "JointModelRX") return pinbench::kRX;
  if (s == "JointModelRY") return pinbench::kRY;
  if (s == "JointModelRZ") return pinbench::kRZ;
  if (s == "JointModelRUBX") return pinbench::kRUBX;
  if (s == "JointModelRUBY") return pinbench::kRUBY;
  if (s == "JointModelRUBZ") return pinbench::kRUBZ;
  if (s == "JointModelPX") return pinbench::kPX;
  if (s == "JointModelPY") return pinbench::kPY;
  if (s == "JointModelPZ") return pinbench::kPZ;
  if (s == "JointModelRevoluteUnaligned") {
    copy_axis(boost::get<pinocchio::JointModelRevoluteUnaligned>(joint.toVariant()).axis, axis);
    return pinbench::kRevoluteUnaligned;
  }
  if (s == "JointModelRevoluteUnboundedUnaligned") {
    copy_axis(boost::get<pinocchio::JointModelRevoluteUnboundedUnaligned>(joint.toVariant()).axis, axis);
    return pinbench::kRevoluteUnboundedUnaligned;
  }
  if (s == "JointModelPrismaticUnaligned") {
    copy_axis(boost::get<pinocchio::JointModelPrismaticUnaligned>(joint.toVariant()).axis, axis);
    return pinbench::kPrismaticUnaligned;
  }
  throw std::runtime_error("joint type " + s + " is not handled by bench_vs_pinocchio");
}

template <typename SE3>
void copy_placement(const SE3& M, double* rotation, double* translation) {
  for (int c = 0; c < 3; ++c) {
    translation[c] = M.translation()(c);
    for (int r = 0; r < 3; ++r) rotation[3 * c + r] = M.rotation()(r, c);
  }
}

}  // namespace

/// Pinocchio's model of the URDF with every joint not named in `keep`
/// locked at its neutral configuration (pin.buildReducedModel), as numbers.
extern "C" __attribute__((visibility("default"))) int chasles_pinbench_load_pinocchio(const char* urdf, const char* tip,
                                                                                      const char* const* keep,
                                                                                      int n_keep,
                                                                                      pinbench::ArmPod* out) noexcept {
  try {
    *out = pinbench::ArmPod{};
    pinocchio::Model full;
    pinocchio::urdf::buildModel(std::string(urdf), full);
    const std::set<std::string> kept(keep, keep + n_keep);
    std::vector<pinocchio::JointIndex> lock;
    for (pinocchio::JointIndex i = 1; i < pinocchio::JointIndex(full.njoints); ++i)
      if (!kept.count(full.names[i])) lock.push_back(i);
    const pinocchio::Model model = pinocchio::buildReducedModel(full, lock, pinocchio::neutral(full));
    if (model.njoints - 1 != n_keep || n_keep > pinbench::kMaxPodJoints)
      throw std::runtime_error("the reduced model has " + std::to_string(model.njoints - 1) + " joints, not " +
                               std::to_string(n_keep));
    out->n = n_keep;
    for (int j = 0; j < n_keep; ++j) {
      const auto i = pinocchio::JointIndex(j + 1);
      if (model.names[i] != keep[j] || model.parents[i] != i - 1)
        throw std::runtime_error("joint " + std::to_string(j) + " of the reduced model is '" + model.names[i] +
                                 "', not '" + keep[j] + "' on a chain");
      pinbench::JointPod& J = out->joints[j];
      pinbench::copy_string(J.name, sizeof J.name, model.names[i].c_str());
      J.kind = joint_kind(model.joints[i], J.axis);
      copy_placement(model.jointPlacements[i], J.rotation, J.translation);
      const pinocchio::Inertia& Y = model.inertias[i];
      J.mass = Y.mass();
      for (int k = 0; k < 3; ++k) J.lever[k] = Y.lever()(k);
      for (int k = 0; k < 6; ++k) J.inertia[k] = Y.inertia().data()(k);
    }
    if (!model.existFrame(tip)) throw std::runtime_error(std::string("no frame '") + tip + "'");
    const pinocchio::Model::Frame& frame = model.frames[model.getFrameId(tip)];
    out->tip_joint = int(frame.parentJoint);
    copy_placement(frame.placement, out->tip_rotation, out->tip_translation);
    for (int k = 0; k < 3; ++k) out->gravity[k] = model.gravity.linear()(k);
    if (model.gravity.angular().norm() != 0.0) throw std::runtime_error("gravity with an angular part");
    if (model.armature.size() > 0 && model.armature.cwiseAbs().maxCoeff() != 0.0)
      throw std::runtime_error("a nonzero armature (chasles has none)");
    return 0;
  } catch (const std::exception& e) {
    pinbench::copy_string(out->error, sizeof out->error, e.what());
    return 1;
  }
}

#elif defined(CHASLES_PINBENCH_LOAD_CHASLES)
// ---------------------------------------------------------------------------
// The chasles loader module: chain_from_urdf, built with the flags of
// src/urdf.cpp (portable), and the chain it returns as numbers.

#include <chasles/urdf.hpp>

namespace {

template <typename SE3>
void copy_pose(const SE3& g, double* out) {
  const Eigen::Matrix4d m = g.matrix();
  for (int k = 0; k < 16; ++k) out[k] = m(k % 4, k / 4);
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int chasles_pinbench_load_chasles(const char* urdf, const char* tip,
                                                                                    pinbench::ChainPod* out) noexcept {
  *out = pinbench::ChainPod{};
  const auto loaded = chasles::chain_from_urdf<double, pinbench::kMaxPodJoints>(urdf, tip);
  if (!loaded) {
    pinbench::copy_string(out->error, sizeof out->error, loaded.error.c_str());
    return 1;
  }
  const auto& chain = *loaded.chain;
  out->n = int(chain.n_joints());
  for (int j = 0; j < out->n; ++j) {
    const auto k = std::size_t(j);
    pinbench::copy_string(out->names[j], pinbench::kName, loaded.joint_names[k].c_str());
    out->types[j] = int(chain.joint_type(j));
    for (int r = 0; r < 6; ++r) out->screws[j][r] = chain.space_screws()(r, j);
    out->lower[j] = chain.lower()(j);
    out->upper[j] = chain.upper()(j);
    out->velocity[j] = chain.velocity_limits()(j);
    out->effort[j] = chain.effort_limits()(j);
    const auto& G = chain.link_inertias()[k];
    out->mass[j] = G.mass();
    for (int r = 0; r < 3; ++r) out->com[j][r] = G.com()(r);
    for (int r = 0; r < 9; ++r) out->inertia[j][r] = G.inertia()(r % 3, r / 3);
  }
  copy_pose(chain.home(), out->home);
  copy_pose(chain.base(), out->base);
  copy_pose(chain.tool(), out->tool);
  for (int r = 0; r < 3; ++r) out->gravity[r] = chain.gravity()(r);
  return 0;
}

#else
// ---------------------------------------------------------------------------
// The benchmark.

#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <chasles/dynamics.hpp>
#include <chasles/dynamics_derivatives.hpp>
#include <chasles/kinematics.hpp>

#include <pinocchio/algorithm/aba-derivatives.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/frames.hpp>
#include <pinocchio/algorithm/jacobian.hpp>
#include <pinocchio/algorithm/rnea-derivatives.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody.hpp>

#ifndef CHASLES_PINBENCH_MAX_JOINTS
#define CHASLES_PINBENCH_MAX_JOINTS 7
#endif
#ifndef CHASLES_PINBENCH_VARIANT
#define CHASLES_PINBENCH_VARIANT "?"
#endif
#ifndef CHASLES_PINBENCH_ROBOTS_DIR
#define CHASLES_PINBENCH_ROBOTS_DIR ""
#endif
#ifndef CHASLES_PINBENCH_LOAD_PINOCCHIO_PATH
#define CHASLES_PINBENCH_LOAD_PINOCCHIO_PATH ""
#endif
#ifndef CHASLES_PINBENCH_LOAD_CHASLES_PATH
#define CHASLES_PINBENCH_LOAD_CHASLES_PATH ""
#endif

namespace {

/// The chain type of the benchmark: loaded from a URDF, so Dynamic joints,
/// with a compile-time bound (7: the largest of the three arms).
using Chain = chasles::Chain<double, Eigen::Dynamic, CHASLES_PINBENCH_MAX_JOINTS>;
constexpr double kTolerance = 1e-10;

struct Arm {
  const char* name;
  const char* urdf;  ///< under example-robot-data's robots/
  const char* tip;
};
const Arm kArms[] = {
    {"UR5", "ur_description/urdf/ur5_robot.urdf", "tool0"},
    {"Panda", "panda_description/urdf/panda.urdf", "panda_hand"},
    {"xArm7", "xarm_description/urdf/xarm7.urdf", "link7"},
};

/// One state, in each library's own types: chasles' fixed-capacity joint
/// vectors, Pinocchio's dynamic ones (qp: its configuration, (cos, sin) for
/// a continuous joint).
struct State {
  Chain::JointVector q, qd, qdd, tau;
  Eigen::VectorXd qp, v, a, t;
};

/// Keeps the compiler from dropping or hoisting the computation of v.
template <typename T>
inline void keep(const T& v) {
  asm volatile("" : : "r"(&v) : "memory");
}

chasles::SE3d pose(const double* m) {
  Eigen::Matrix3d R;
  Eigen::Vector3d p;
  for (int r = 0; r < 3; ++r) {
    p(r) = m[12 + r];
    for (int c = 0; c < 3; ++c) R(r, c) = m[4 * c + r];
  }
  return chasles::SE3d(chasles::SO3d::from_matrix_unchecked(R), p);
}

/// The loader's chain built again here (Chain's Stored constructor: the
/// stored screws, home pose and inertias taken as they are).
Chain chain_from_pod(const pinbench::ChainPod& P) {
  const Eigen::Index n = P.n;
  Chain::Screws S(6, n);
  Chain::JointTypes types{};
  Chain::JointVector lower(n), upper(n), velocity(n), effort(n);
  Chain::Inertias inertias{};
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto k = std::size_t(j);
    for (int r = 0; r < 6; ++r) S(r, j) = P.screws[j][r];
    types[k] = chasles::JointType(P.types[j]);
    lower(j) = P.lower[j];
    upper(j) = P.upper[j];
    velocity(j) = P.velocity[j];
    effort(j) = P.effort[j];
    Eigen::Matrix3d I;
    for (int r = 0; r < 9; ++r) I(r % 3, r / 3) = P.inertia[j][r];
    inertias[k] = chasles::SpatialInertia<double>(P.mass[j], Eigen::Vector3d(P.com[j][0], P.com[j][1], P.com[j][2]), I);
  }
  return Chain(Chain::Stored(), S, pose(P.home), types, lower, upper, velocity, effort, pose(P.base), pose(P.tool),
               Eigen::Vector3d(P.gravity[0], P.gravity[1], P.gravity[2]), inertias);
}

pinocchio::Model::JointModel make_joint(const pinbench::JointPod& J) {
  const Eigen::Vector3d axis(J.axis[0], J.axis[1], J.axis[2]);
  switch (J.kind) {
    case pinbench::kRX: return pinocchio::JointModelRX();
    case pinbench::kRY: return pinocchio::JointModelRY();
    case pinbench::kRZ: return pinocchio::JointModelRZ();
    case pinbench::kRevoluteUnaligned: return pinocchio::JointModelRevoluteUnaligned(axis);
    case pinbench::kRUBX: return pinocchio::JointModelRUBX();
    case pinbench::kRUBY: return pinocchio::JointModelRUBY();
    case pinbench::kRUBZ: return pinocchio::JointModelRUBZ();
    case pinbench::kRevoluteUnboundedUnaligned: return pinocchio::JointModelRevoluteUnboundedUnaligned(axis);
    case pinbench::kPX: return pinocchio::JointModelPX();
    case pinbench::kPY: return pinocchio::JointModelPY();
    case pinbench::kPZ: return pinocchio::JointModelPZ();
    case pinbench::kPrismaticUnaligned: return pinocchio::JointModelPrismaticUnaligned(axis);
    default: std::fprintf(stderr, "unknown joint kind %d\n", J.kind); std::exit(1);
  }
}

pinocchio::SE3 placement(const double* rotation, const double* translation) {
  return pinocchio::SE3(Eigen::Map<const Eigen::Matrix3d>(rotation),
                        Eigen::Vector3d(translation[0], translation[1], translation[2]));
}

/// The loader's model built again here, in this binary's layouts: the same
/// joint types, placements and inertias (bit for bit) and the tool frame.
pinocchio::Model build_model(const pinbench::ArmPod& pod, const char* tip) {
  pinocchio::Model model;
  pinocchio::JointIndex parent = 0;
  for (int j = 0; j < pod.n; ++j) {
    const pinbench::JointPod& J = pod.joints[j];
    parent = model.addJoint(parent, make_joint(J), placement(J.rotation, J.translation), J.name);
    Eigen::Matrix<double, 6, 1> I;
    for (int k = 0; k < 6; ++k) I(k) = J.inertia[k];
    model.inertias[parent] =
        pinocchio::Inertia(J.mass, Eigen::Vector3d(J.lever[0], J.lever[1], J.lever[2]), pinocchio::Symmetric3(I));
  }
  model.gravity.linear(Eigen::Vector3d(pod.gravity[0], pod.gravity[1], pod.gravity[2]));
  model.addFrame(pinocchio::Frame(tip, pinocchio::JointIndex(pod.tip_joint),
                                  placement(pod.tip_rotation, pod.tip_translation), pinocchio::OP_FRAME),
                 false);
  return model;
}

std::string joint_types(const pinocchio::Model& model) {
  std::string s;
  for (pinocchio::JointIndex i = 1; i < pinocchio::JointIndex(model.njoints); ++i) {
    std::string name = model.joints[i].shortname();
    if (name.rfind("JointModel", 0) == 0) name = name.substr(10);
    s += (i > 1 ? " " : "") + name;
  }
  return s;
}

std::vector<State> random_states(const Chain& chain, const pinocchio::Model& model, std::size_t count,
                                 std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Index n = chain.n_joints();
  std::vector<State> states(count);
  for (State& s : states) {
    s.q.resize(n), s.qd.resize(n), s.qdd.resize(n), s.tau.resize(n);
    for (Eigen::Index j = 0; j < n; ++j) {
      const double lo = std::max(chain.lower()(j), -M_PI), hi = std::min(chain.upper()(j), M_PI);
      s.q(j) = lo + (hi - lo) * unit(rng);
      s.qd(j) = -2 + 4 * unit(rng);
      s.qdd(j) = -2 + 4 * unit(rng);
      s.tau(j) = -2 + 4 * unit(rng);
    }
    s.qp.resize(model.nq);
    for (pinocchio::JointIndex i = 1; i < pinocchio::JointIndex(model.njoints); ++i) {
      const double angle = s.q(Eigen::Index(i - 1));
      if (model.joints[i].nq() == 2) {
        s.qp(model.joints[i].idx_q()) = std::cos(angle);
        s.qp(model.joints[i].idx_q() + 1) = std::sin(angle);
      } else {
        s.qp(model.joints[i].idx_q()) = angle;
      }
    }
    s.v = s.qd;
    s.a = s.qdd;
    s.t = s.tau;
  }
  return states;
}

/// max |a - b| / max(1, max |b|).
template <typename A, typename B>
double rel(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return INFINITY;
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

/// Pinocchio's symmetric results (M, M^-1) have their upper triangle only.
template <typename Derived>
Eigen::MatrixXd from_upper(const Eigen::MatrixBase<Derived>& M) {
  Eigen::MatrixXd S = M.template triangularView<Eigen::Upper>();
  S.template triangularView<Eigen::StrictlyLower>() = M.transpose();
  return S;
}

/// Every operation of both libraries on every state: the largest relative
/// difference per operation; false (and a message) past kTolerance.
bool verify(const char* arm, const Chain& chain, const pinocchio::Model& model, pinocchio::Data& data,
            pinocchio::FrameIndex frame, const std::vector<State>& states) {
  const Eigen::Index n = chain.n_joints();
  struct Worst {
    std::string op;
    double error;
  };
  std::vector<Worst> worst;
  auto note = [&](const std::string& op, double e) {
    for (Worst& w : worst)
      if (w.op == op) {
        if (!std::isnan(w.error) && !(e <= w.error)) w.error = e;  // a NaN stays (and fails)
        return;
      }
    worst.push_back({op, e});
  };
  pinocchio::Data::Matrix6x J(6, model.nv);
  Chain::Jacobian Jb(6, n);
  for (const State& s : states) {
    const chasles::SE3d g = chain.forward_body(s.q, Jb);
    J.setZero();
    pinocchio::computeFrameJacobian(model, data, s.qp, frame, pinocchio::LOCAL, J);
    note("pose (iMf[0])", rel(g.matrix(), data.iMf[0].toHomogeneousMatrix()));
    note("body Jacobian (computeFrameJacobian)", rel(Jb, J));
    J.setZero();
    pinocchio::computeJointJacobians(model, data, s.qp);
    const pinocchio::SE3& oMf = pinocchio::updateFramePlacement(model, data, frame);
    pinocchio::getFrameJacobian(model, data, frame, pinocchio::LOCAL, J);
    note("pose (oMf)", rel(g.matrix(), oMf.toHomogeneousMatrix()));
    note("body Jacobian (getFrameJacobian)", rel(Jb, J));

    note("rnea", rel(chasles::inverse_dynamics(chain, s.q, s.qd, s.qdd), pinocchio::rnea(model, data, s.qp, s.v, s.a)));
    const Chain::MassMatrix M = chasles::mass_matrix(chain, s.q);
    note("crba LOCAL", rel(M, from_upper(pinocchio::crba(model, data, s.qp, pinocchio::Convention::LOCAL))));
    note("crba WORLD", rel(M, from_upper(pinocchio::crba(model, data, s.qp, pinocchio::Convention::WORLD))));
    note("gravity", rel(chasles::gravity_torques(chain, s.q), pinocchio::computeGeneralizedGravity(model, data, s.qp)));
    const auto fd = chasles::forward_dynamics(chain, s.q, s.qd, s.tau);
    const auto fda = chasles::forward_dynamics_articulated(chain, s.q, s.qd, s.tau);
    if (!fd || !fda) {
      std::fprintf(stderr, "%s: forward dynamics failed\n", arm);
      return false;
    }
    note("aba LOCAL", rel(fd.qdd, pinocchio::aba(model, data, s.qp, s.v, s.t, pinocchio::Convention::LOCAL)));
    note("aba WORLD", rel(fd.qdd, pinocchio::aba(model, data, s.qp, s.v, s.t, pinocchio::Convention::WORLD)));
    note("forward_dynamics_articulated", rel(fda.qdd, data.ddq));

    const auto did = chasles::inverse_dynamics_derivatives(chain, s.q, s.qd, s.qdd);
    pinocchio::computeRNEADerivatives(model, data, s.qp, s.v, s.a);
    note("d rnea / dq", rel(did.dtau_dq, data.dtau_dq));
    note("d rnea / dv", rel(did.dtau_dqd, data.dtau_dv));
    note("d rnea / da (M)", rel(M, from_upper(data.M)));
    const auto dfd = chasles::forward_dynamics_derivatives(chain, s.q, s.qd, s.tau);
    pinocchio::computeABADerivatives(model, data, s.qp, s.v, s.t);
    note("d aba / dq", rel(dfd.dqdd_dq, data.ddq_dq));
    note("d aba / dv", rel(dfd.dqdd_dqd, data.ddq_dv));
    note("d aba / dtau (M^-1)", rel(dfd.dqdd_dtau, from_upper(data.Minv)));
    note("minv", rel(chasles::mass_matrix_inverse(chain, s.q).inverse,
                     from_upper(pinocchio::computeMinverse(model, data, s.qp))));
  }
  bool ok = true;
  std::printf("%s: largest relative difference over %zu states (tolerance %.0e):\n", arm, states.size(), kTolerance);
  for (const Worst& w : worst) {
    const bool pass = w.error <= kTolerance;
    ok = ok && pass;
    std::printf("  %-38s %9.2e%s\n", w.op.c_str(), w.error, pass ? "" : "  FAILED");
  }
  return ok;
}

struct Row {
  std::string op, chasles_call, pinocchio_call;
  double c_min, c_med, p_min, p_med;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t k = v.size() / 2;
  return v.size() % 2 ? v[k] : (v[k - 1] + v[k]) / 2;
}

/// ns per call of f over the states (one pass).
template <typename F>
double pass_ns(const F& f, std::size_t count) {
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < count; ++i) f(i);
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::nano>(t1 - t0).count() / double(count);
}

/// The operations to time (--op: those whose name contains it; all when empty).
std::string g_op_filter;

/// chasles then Pinocchio, round after round (an untimed pass of each first);
/// a row of zeros, left out of the table, when --op excludes the operation.
template <typename C, typename P>
Row time_pair(const std::string& op, const std::string& chasles_call, const std::string& pinocchio_call,
              std::size_t count, int rounds, const C& c, const P& p) {
  if (op.find(g_op_filter) == std::string::npos) return {op, chasles_call, pinocchio_call, 0, 0, 0, 0};
  pass_ns(c, count);
  pass_ns(p, count);
  std::vector<double> tc, tp;
  for (int r = 0; r < rounds; ++r) {
    tc.push_back(pass_ns(c, count));
    tp.push_back(pass_ns(p, count));
  }
  return {op,
          chasles_call,
          pinocchio_call,
          *std::min_element(tc.begin(), tc.end()),
          median(tc),
          *std::min_element(tp.begin(), tp.end()),
          median(tp)};
}

std::vector<Row> time_arm(const Chain& chain, const pinocchio::Model& model, pinocchio::Data& data,
                          pinocchio::FrameIndex frame, const std::vector<State>& S, int rounds) {
  using pinocchio::Convention;
  const std::size_t N = S.size();
  std::vector<Row> rows;
  Chain::Jacobian Jb(6, chain.n_joints());
  pinocchio::Data::Matrix6x J = pinocchio::Data::Matrix6x::Zero(6, model.nv);

  const auto c_fk = [&](std::size_t i) {
    const chasles::SE3d g = chain.forward_body(S[i].q, Jb);
    keep(g);
    keep(Jb);
  };
  rows.push_back(time_pair("pose + body Jacobian", "forward_body(q, J)",
                           "computeFrameJacobian(LOCAL); pose = data.iMf[0]", N, rounds, c_fk, [&](std::size_t i) {
                             pinocchio::computeFrameJacobian(model, data, S[i].qp, frame, pinocchio::LOCAL, J);
                             keep(data.iMf[0]);
                             keep(J);
                           }));
  rows.push_back(time_pair("pose + body Jacobian", "forward_body(q, J)",
                           "computeJointJacobians + updateFramePlacement + getFrameJacobian(LOCAL)", N, rounds, c_fk,
                           [&](std::size_t i) {
                             pinocchio::computeJointJacobians(model, data, S[i].qp);
                             const pinocchio::SE3& oMf = pinocchio::updateFramePlacement(model, data, frame);
                             pinocchio::getFrameJacobian(model, data, frame, pinocchio::LOCAL, J);
                             keep(oMf);
                             keep(J);
                           }));
  rows.push_back(time_pair(
      "inverse dynamics", "inverse_dynamics", "rnea", N, rounds,
      [&](std::size_t i) { keep(chasles::inverse_dynamics(chain, S[i].q, S[i].qd, S[i].qdd)); },
      [&](std::size_t i) { keep(pinocchio::rnea(model, data, S[i].qp, S[i].v, S[i].a)); }));
  const auto c_M = [&](std::size_t i) { keep(chasles::mass_matrix(chain, S[i].q)); };
  rows.push_back(time_pair("mass matrix", "mass_matrix", "crba(LOCAL) (upper triangle)", N, rounds, c_M,
                           [&](std::size_t i) { keep(pinocchio::crba(model, data, S[i].qp, Convention::LOCAL)); }));
  rows.push_back(time_pair("mass matrix", "mass_matrix", "crba(WORLD) (upper triangle)", N, rounds, c_M,
                           [&](std::size_t i) { keep(pinocchio::crba(model, data, S[i].qp, Convention::WORLD)); }));
  rows.push_back(time_pair(
      "gravity torques", "gravity_torques", "computeGeneralizedGravity", N, rounds,
      [&](std::size_t i) { keep(chasles::gravity_torques(chain, S[i].q)); },
      [&](std::size_t i) { keep(pinocchio::computeGeneralizedGravity(model, data, S[i].qp)); }));
  const auto c_fd = [&](std::size_t i) { keep(chasles::forward_dynamics(chain, S[i].q, S[i].qd, S[i].tau)); };
  const auto p_aba_local = [&](std::size_t i) {
    keep(pinocchio::aba(model, data, S[i].qp, S[i].v, S[i].t, Convention::LOCAL));
  };
  rows.push_back(time_pair("forward dynamics", "forward_dynamics", "aba(LOCAL)", N, rounds, c_fd, p_aba_local));
  rows.push_back(time_pair("forward dynamics", "forward_dynamics", "aba(WORLD)", N, rounds, c_fd, [&](std::size_t i) {
    keep(pinocchio::aba(model, data, S[i].qp, S[i].v, S[i].t, Convention::WORLD));
  }));
  rows.push_back(time_pair(
      "forward dynamics", "forward_dynamics_articulated", "aba(LOCAL)", N, rounds,
      [&](std::size_t i) { keep(chasles::forward_dynamics_articulated(chain, S[i].q, S[i].qd, S[i].tau)); },
      p_aba_local));
  rows.push_back(time_pair(
      "d inverse dynamics", "inverse_dynamics_derivatives", "computeRNEADerivatives (also M)", N, rounds,
      [&](std::size_t i) { keep(chasles::inverse_dynamics_derivatives(chain, S[i].q, S[i].qd, S[i].qdd)); },
      [&](std::size_t i) {
        pinocchio::computeRNEADerivatives(model, data, S[i].qp, S[i].v, S[i].a);
        keep(data.dtau_dq);
        keep(data.dtau_dv);
      }));
  rows.push_back(time_pair(
      "d forward dynamics", "forward_dynamics_derivatives", "computeABADerivatives", N, rounds,
      [&](std::size_t i) { keep(chasles::forward_dynamics_derivatives(chain, S[i].q, S[i].qd, S[i].tau)); },
      [&](std::size_t i) {
        pinocchio::computeABADerivatives(model, data, S[i].qp, S[i].v, S[i].t);
        keep(data.ddq_dq);
        keep(data.ddq_dv);
        keep(data.Minv);
      }));
  rows.push_back(time_pair(
      "M^-1", "mass_matrix_inverse", "computeMinverse (upper triangle)", N, rounds,
      [&](std::size_t i) { keep(chasles::mass_matrix_inverse(chain, S[i].q)); },
      [&](std::size_t i) { keep(pinocchio::computeMinverse(model, data, S[i].qp)); }));
  return rows;
}

[[noreturn]] void usage(const char* what) {
  std::fprintf(stderr,
               "%s\nusage: chasles_bench_vs_pinocchio [--rounds R] [--states N] [--arm NAME] [--robots DIR] "
               "[--seed S] [--op TEXT]\n",
               what);
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  int rounds = 15;
  std::size_t count = 1000;
  std::uint64_t seed = 20240917;
  std::string only, robots = CHASLES_PINBENCH_ROBOTS_DIR;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (k + 1 >= argc) usage(("missing value after " + a).c_str());
    const char* v = argv[++k];
    if (a == "--rounds")
      rounds = std::atoi(v);
    else if (a == "--states")
      count = std::size_t(std::atol(v));
    else if (a == "--arm")
      only = v;
    else if (a == "--robots")
      robots = v;
    else if (a == "--seed")
      seed = std::uint64_t(std::atoll(v));
    else if (a == "--op")
      g_op_filter = v;
    else
      usage(("unknown option " + a).c_str());
  }
  if (rounds < 1 || count < 1) usage("--rounds and --states must be positive");
  if (robots.empty()) usage("no example-robot-data directory: --robots DIR (its robots/ folder)");

  // RTLD_DEEPBIND: each module and its libraries resolve their symbols among
  // themselves first (the wheel's urdfdom and Debian's share their names).
  const auto open = [](const char* path, const char* symbol) -> void* {
    void* module = dlopen(path, RTLD_NOW | RTLD_LOCAL | RTLD_DEEPBIND);
    if (!module) {
      std::fprintf(stderr, "cannot load the module '%s': %s\n", path, dlerror());
      std::exit(1);
    }
    void* f = dlsym(module, symbol);
    if (!f) {
      std::fprintf(stderr, "no %s in '%s'\n", symbol, path);
      std::exit(1);
    }
    return f;
  };
  const auto load_chasles = reinterpret_cast<pinbench::LoadChasles>(
      open(CHASLES_PINBENCH_LOAD_CHASLES_PATH, "chasles_pinbench_load_chasles"));
  const auto load_pinocchio = reinterpret_cast<pinbench::LoadPinocchio>(
      open(CHASLES_PINBENCH_LOAD_PINOCCHIO_PATH, "chasles_pinbench_load_pinocchio"));

  std::printf("chasles against Pinocchio %s, %s build (g++ %d.%d, Eigen %d.%d.%d, SIMD: %s)\n", PINOCCHIO_VERSION,
              CHASLES_PINBENCH_VARIANT, __GNUC__, __GNUC_MINOR__, EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
              EIGEN_MINOR_VERSION, Eigen::SimdInstructionSetsInUse());
  std::printf(
      "chasles chain: Chain<double, Dynamic, %d>; %zu states per arm, %d rounds, minimum (median) per library\n\n",
      CHASLES_PINBENCH_MAX_JOINTS, count, rounds);

  struct ArmRows {
    std::string arm;
    std::vector<Row> rows;
  };
  std::vector<ArmRows> results;
  for (const Arm& arm : kArms) {
    if (!only.empty() && only != arm.name) continue;
    const std::string path = robots + "/" + arm.urdf;
    static pinbench::ChainPod chain_pod;
    if (load_chasles(path.c_str(), arm.tip, &chain_pod) != 0) {
      std::fprintf(stderr, "%s: chasles: %s\n", arm.name, chain_pod.error);
      return 1;
    }
    if (chain_pod.n > CHASLES_PINBENCH_MAX_JOINTS) {
      std::fprintf(stderr, "%s: %d joints, more than CHASLES_PINBENCH_MAX_JOINTS\n", arm.name, chain_pod.n);
      return 1;
    }
    const Chain chain = chain_from_pod(chain_pod);
    std::vector<const char*> names;
    for (int j = 0; j < chain_pod.n; ++j) names.push_back(chain_pod.names[j]);
    static pinbench::ArmPod pod;
    if (load_pinocchio(path.c_str(), arm.tip, names.data(), int(names.size()), &pod) != 0) {
      std::fprintf(stderr, "%s: Pinocchio: %s\n", arm.name, pod.error);
      return 1;
    }
    const pinocchio::Model model = build_model(pod, arm.tip);
    pinocchio::Data data(model);
    const pinocchio::FrameIndex frame = model.getFrameId(arm.tip);
    std::printf("%s: %d joints (Pinocchio: %s)\n", arm.name, int(chain.n_joints()), joint_types(model).c_str());
    const std::vector<State> states = random_states(chain, model, count, seed);
    if (!verify(arm.name, chain, model, data, frame, states)) {
      std::fprintf(stderr, "%s: the two libraries disagree: no timing\n", arm.name);
      return 1;
    }
    results.push_back({arm.name, time_arm(chain, model, data, frame, states, rounds)});
  }

  std::printf("\nns per call, %s build: minimum (median) of %d rounds over %zu states; ratio chasles / Pinocchio\n",
              CHASLES_PINBENCH_VARIANT, rounds, count);
  std::printf("%-6s %-20s %-29s %-68s %17s %17s %14s\n", "arm", "operation", "chasles", "Pinocchio", "chasles ns",
              "Pinocchio ns", "ratio");
  for (const ArmRows& result : results)
    for (const Row& r : result.rows)
      if (r.p_min > 0)
        std::printf("%-6s %-20s %-29s %-68s %7.1f (%7.1f) %7.1f (%7.1f) %5.2f (%5.2f)\n", result.arm.c_str(),
                    r.op.c_str(), r.chasles_call.c_str(), r.pinocchio_call.c_str(), r.c_min, r.c_med, r.p_min, r.p_med,
                    r.c_min / r.p_min, r.c_med / r.p_med);
  return 0;
}

#endif  // CHASLES_PINBENCH_LOAD_PINOCCHIO, CHASLES_PINBENCH_LOAD_CHASLES
