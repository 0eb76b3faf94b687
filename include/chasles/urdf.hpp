// chasles: a serial chain from a URDF robot description (optional: needs
// urdfdom, Debian's liburdfdom-dev, and the CMake target chasles::urdf; not
// included by chasles.hpp).
//
// The C++ counterpart of the Python Chain.from_urdf (python/chasles/_urdf.py),
// with the same semantics: the revolute, continuous and prismatic joints from
// the base link (default: the root of the tree) down to the tip link become
// the chain's joints; fixed joints are folded into the screws and the home
// pose; each joint's <origin xyz rpy> is the pose of its child link in its
// parent link at zero, R = Rz(yaw) Ry(pitch) Rx(roll); <axis> (default
// (1, 0, 0)) is in the child link frame and is normalized; <limit> gives the
// position, velocity and effort limits (continuous joints: -inf, +inf; no
// <limit>: +inf velocity and effort). Each moving joint's link inertia is the
// body it moves: its child link, the links fixed after it on the chain, and
// the links hanging off the chain there (side branches, the links below the
// tip), their own moving joints at zero (as Pinocchio's buildReducedModel at
// the neutral configuration), described in the base frame at home.
//
// The source is XML text or a file path: after an optional UTF-8 byte-order
// mark and blanks, a '<' starts XML text; anything else is a path, which
// must name a regular file ("cannot open the file 'P'", "'P' is a
// directory, not a URDF file", "'P' is not a regular file" for a device, a
// FIFO or a socket). Bounds: 64 MiB of text (a file is never read further:
// "'P' is larger than 64 MiB, ..."; text given directly: "the description is
// larger than 64 MiB, ..."), and elements nested at most 64 deep, checked
// by a linear pre-scan before the XML parser sees the document ("the XML
// nests elements more than 64 deep, ..."; a URDF nests about 6 deep;
// urdfdom's parser recurses per level and takes quadratic time: 50,000
// levels overflowed its stack), and at most 256 attributes in one element,
// checked by the same pre-scan ("an element has more than 256 attributes,
// the bound on a URDF description": the parser's time is quadratic in
// them). The text must be UTF-8 ("the description is not UTF-8 text (byte
// N of the text)"): urdfdom's parser reads a byte that starts a multi-byte
// character with the bytes after it, '<' included, and would see elements
// the pre-scan does not. The link tree is walked with an explicit stack: a
// side branch of 25,000 fixed links (3.3 MB) loads, 84% of the time in
// urdfdom's parse (tests/cpp/test_urdf.cpp and bench/bench_urdf.cpp time it).
//
// Refused, each message after "chain_from_urdf: " naming the element (the
// same text as the Python loader's after "Chain.from_urdf: "):
// - an XML declaration or processing instruction ("<?...") whose quotes the
//   XML parser could read past its first '>' (a quote that opens no value,
//   or a value holding a quote or a '>'), before urdfdom: "not well-formed
//   XML: the declaration or processing instruction at byte N has a quote
//   that opens no value, or a value that holds a quote or a '>'" (the scan
//   would not see what the parser sees after it; the Python loader's expat
//   refuses these as not well-formed too, with its own reason);
// - what urdfdom cannot read (not well-formed XML, a missing link, an
//   unknown joint type, a revolute or prismatic joint without <limit>, a
//   <limit> without effort or velocity, more than one root link), with
//   urdfdom's reason: "urdfdom refused the description: ...";
// - a number that is not finite or not a number where the loader reads one
//   (every link's <inertial>: <mass value>, the six <inertia> attributes,
//   <origin xyz rpy>; every joint's <origin xyz rpy>, <axis xyz> and
//   <limit> attributes): "joint 'J' <origin xyz>: expected finite numbers",
//   "link 'L' <mass>: expected finite numbers" (a missing <mass> or
//   <inertia>, or a missing attribute of <inertia>, too);
// - a negative mass in any link: "link 'L' <mass>: negative mass -1.5 (a
//   mass is >= 0)";
// - on the chain: "joint 'J' <limit>: lower 1 > upper 0", "... negative
//   velocity -1", "... negative effort -1", "joint 'J': <axis xyz> is
//   zero" (an axis is a direction: (1e308, 1e308, 0) is normalized without
//   overflow), a floating or planar joint, a <mimic> joint;
// - duplicate names: "duplicate link name 'L'", "duplicate joint name 'J'";
// - loops: "link 'L' is the child of joints 'J1' and 'J2': a loop (URDF
//   describes trees)", and "a loop through link 'L'" for a cycle of joints
//   (refused before urdfdom builds its tree, whose shared_ptr cycles would
//   outlive it);
// - finite numbers that overflow when combined: "joint 'J': the pose of
//   link 'C' at home is not finite (overflow)", "joint 'J': the mass
//   properties of the links it moves are not finite (overflow)" (also when
//   a value finite in double is not in Scalar = float);
// - an unknown tip or base link (these two errors keep their prefixes
//   "chain_from_urdf(tip_link): " and "chain_from_urdf(base_link): "), a tip
//   not below the base, no moving joint, more moving joints than MaxJoints;
// - last, a chain whose Chain::validate() fails: "joint 'J': " and the reason.
// Not refused (the decision shared with the Python loader): physically
// impossible inertias (not positive semidefinite, or violating the
// triangle inequality). 48 of the 1,985 link inertias of example-robot-data
// are (tiago's antenna links have an eigenvalue at -39% of the trace,
// anymal's "hatch" is diag(0, 0, 0.003), icub's legs have entries of 1e-18
// with negative eigenvalues), and those robots load.
// SpatialInertia::is_physical() tells; the dynamics then report a mass
// matrix that is not positive definite.
//
// Why a compiled part (chasles_urdf, linked by the target chasles::urdf):
// urdfdom's headers throw in inline code (urdf_model/pose.h), so they do not
// compile with -fno-exceptions. They are included only by src/urdf.cpp,
// compiled with exceptions, which catches everything: this header includes
// no urdfdom header and compiles, and chain_from_urdf runs, in a
// -fno-exceptions build. Loading allocates (strings, the parsed tree): it is
// for start-up, not for a real-time loop; the Chain it returns is
// allocation-free as always.
//
// Thread safety: loads may run on several threads. The verdict never
// depends on console_bridge (urdfdom's log): not on its level (NONE
// included), nor on what other threads log. urdfdom's messages are captured
// for the text of its refusals only: console_bridge has one global output
// handler, which the loader replaces while urdfdom parses (a mutex
// serializes that part of concurrent loads); meanwhile the messages of
// other threads pass on to the handler it replaced. An application that
// changes console_bridge's handler from another thread during a load may
// find its change undone when the load ends.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "chasles/kinematics.hpp"
#include "chasles/se3.hpp"
#include "chasles/so3.hpp"
#include "chasles/spatial_inertia.hpp"

namespace chasles {

namespace detail {

/// What src/urdf.cpp reads, in double: n moving joints from base to tip.
/// Standard containers of doubles only, no Eigen type: src/urdf.cpp and the
/// code that includes this header may be compiled with different flags
/// (-march=native with AVX-512 aligns an Eigen::Matrix4d to 64 bytes and
/// moves the members after it, and Eigen's dynamic matrices then allocate
/// with Eigen's aligned allocator), and this struct crosses between them.
struct UrdfDescription {
  /// One moving joint and the body it moves.
  struct Joint {
    std::array<double, 6> screw;           ///< (v, w), base frame at home
    double lower, upper, velocity, effort;  ///< limits
    double mass;                            ///< of the links it moves
    std::array<double, 3> com;              ///< their center of mass (base frame)
    std::array<double, 9> inertia;          ///< their rotational inertia about com (column-major 3x3)
  };
  std::string error;                     ///< empty on success
  std::vector<std::string> names;        ///< n joint names
  std::vector<JointType> types;          ///< n joint types
  std::vector<Joint> joints;             ///< n joints
  std::array<double, 16> home{};         ///< the tip link frame at home (row-major 4x4)
};

/// Reads the description (compiled in src/urdf.cpp; never throws: every
/// exception of urdfdom or of an allocation becomes `error`).
UrdfDescription read_urdf(const std::string& xml_or_path, const std::string& tip_link,
                          const std::string& base_link) noexcept;

/// What Chain::validate() found, in words (the joint is named by the caller).
inline const char* urdf_check_reason(ChainStatus status) noexcept {
  switch (status) {
    case ChainStatus::revolute_axis_not_unit: return "its axis is not a unit vector (not finite in this scalar type?)";
    case ChainStatus::revolute_pitch_not_zero: return "its screw has a pitch (not finite in this scalar type?)";
    case ChainStatus::prismatic_rotates: return "a prismatic joint whose screw rotates";
    case ChainStatus::prismatic_axis_not_unit: return "its axis is not a unit vector (not finite in this scalar type?)";
    case ChainStatus::position_limits_invalid: return "its position limits are invalid (lower > upper or NaN)";
    case ChainStatus::velocity_or_effort_limit_invalid: return "its velocity or effort limit is negative or NaN";
    case ChainStatus::gravity_not_finite: return "gravity is not finite";
    case ChainStatus::link_inertia_invalid:
      return "the mass properties of the links it moves are not finite (overflow)";
    default: return "the chain does not validate";
  }
}

/// Whether x is finite (false for NaN).
template <typename Scalar>
bool urdf_finite(const Scalar& x) noexcept {
  using std::abs;
  return abs(x) <= Scalar(std::numeric_limits<RealOf<Scalar>>::max());
}

}  // namespace detail

/// The outcome of chain_from_urdf: the chain, its joint names and its link
/// inertias, or an error.
template <typename Scalar, int MaxJoints>
struct UrdfChain {
  using ChainType = Chain<Scalar, Eigen::Dynamic, MaxJoints>;
  /// The chain (identity base and tool, default gravity) with its link
  /// inertias (`chain->link_inertias()`: per moving joint, the body it moves,
  /// in the base frame at home); empty on failure.
  std::optional<ChainType> chain;
  /// The n joint names, base to tip.
  std::vector<std::string> joint_names;
  /// Empty on success; otherwise what is wrong, naming the element.
  std::string error;

  /// Whether the description was loaded.
  explicit operator bool() const noexcept { return chain.has_value(); }
};

/// The serial chain from the base link (empty: the root of the tree) to the
/// tip link of a URDF, given as its XML text (starts with '<' after an
/// optional byte-order mark and blanks) or as a file path. See the top of
/// this header. Never throws (an
/// allocation failure ends the program, as anything noexcept).
template <typename Scalar, int MaxJoints>
UrdfChain<Scalar, MaxJoints> chain_from_urdf(const std::string& xml_or_path, const std::string& tip_link,
                                             const std::string& base_link = "") noexcept {
  using Result = UrdfChain<Scalar, MaxJoints>;
  using ChainType = typename Result::ChainType;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  Result out;
  detail::UrdfDescription d = detail::read_urdf(xml_or_path, tip_link, base_link);
  if (!d.error.empty()) {
    out.error = std::move(d.error);
    return out;
  }
  const auto n = static_cast<Eigen::Index>(d.joints.size());
  if (n > MaxJoints) {
    out.error = "chain_from_urdf: the chain from the base to '" + tip_link + "' has " + std::to_string(n) +
                " moving joints, more than MaxJoints = " + std::to_string(MaxJoints);
    return out;
  }
  typename ChainType::Screws S(6, n);
  typename ChainType::JointTypes types{};
  typename ChainType::JointVector lower(n), upper(n), velocity(n), effort(n);
  typename ChainType::Inertias inertias{};
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const detail::UrdfDescription::Joint& joint = d.joints[k];
    for (std::size_t r = 0; r < 6; ++r) S(static_cast<Eigen::Index>(r), i) = Scalar(joint.screw[r]);
    types[k] = d.types[k];
    lower(i) = Scalar(joint.lower);
    upper(i) = Scalar(joint.upper);
    velocity(i) = Scalar(joint.velocity);
    effort(i) = Scalar(joint.effort);
    Vector3 c;
    Matrix3 I;
    for (std::size_t r = 0; r < 3; ++r) c(static_cast<Eigen::Index>(r)) = Scalar(joint.com[r]);
    for (std::size_t r = 0; r < 9; ++r)
      I(static_cast<Eigen::Index>(r % 3), static_cast<Eigen::Index>(r / 3)) = Scalar(joint.inertia[r]);
    inertias[k] = SpatialInertia<Scalar>(Scalar(joint.mass), c, I);
  }
  Matrix3 R;
  Vector3 p;
  for (std::size_t r = 0; r < 3; ++r) {
    p(static_cast<Eigen::Index>(r)) = Scalar(d.home[4 * r + 3]);
    for (std::size_t c = 0; c < 3; ++c)
      R(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = Scalar(d.home[4 * r + c]);
  }
  const std::string last = "chain_from_urdf: joint '" + d.names[static_cast<std::size_t>(n - 1)] + "'";
  // Finite in double, the home pose may overflow Scalar (float).
  bool finite = true;
  for (Eigen::Index r = 0; r < 3; ++r) {
    finite = finite && detail::urdf_finite(p(r));
    for (Eigen::Index c = 0; c < 3; ++c) finite = finite && detail::urdf_finite(R(r, c));
  }
  if (!finite) {
    out.error = last + ": the pose of link '" + tip_link + "' at home is not finite (overflow)";
    return out;
  }
  // The full constructor projects the home pose onto SE(3) (a product of
  // URDF transforms is a rigid motion up to a few eps).
  ChainType chain(S, SE3<Scalar>(SO3<Scalar>::from_matrix_unchecked(R), p), types, lower, upper, velocity, effort,
                  SE3<Scalar>(), SE3<Scalar>(), ChainType::default_gravity(), inertias);
  // Last, the chain's own validation (what read_urdf checked in double,
  // and what does not survive the conversion to Scalar).
  const ChainCheck check = chain.validate();
  if (!check) {
    out.error = check.joint >= 0 ? "chain_from_urdf: joint '" + d.names[static_cast<std::size_t>(check.joint)] + "': "
                                 : std::string("chain_from_urdf: ");
    out.error += detail::urdf_check_reason(check.status);
    return out;
  }
  out.chain.emplace(chain);
  out.joint_names = std::move(d.names);
  return out;
}

}  // namespace chasles
