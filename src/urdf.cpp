// chasles: the URDF reader behind chain_from_urdf (include/chasles/urdf.hpp),
// over urdfdom. Compiled with exceptions (urdfdom's headers throw in inline
// code), and nothing leaves it as an exception: read_urdf catches all.
//
// The same semantics as python/chasles/_urdf.py, step for step (its comments
// say why); urdfdom parses the XML and checks the tree, and reports its
// errors through console_bridge's log, captured here into the message.
#include "chasles/urdf.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

namespace chasles {
namespace detail {
namespace {

using Matrix4 = Eigen::Matrix4d;
using Matrix3 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;

/// Collects urdfdom's error messages (console_bridge's log) while one
/// description is parsed: installed for the parse and removed after it.
/// console_bridge has one global handler; a mutex serializes the loaders.
class Capture : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_ERROR) return;  // warnings are not the reason
    if (!messages.empty()) messages += "; ";
    messages += text;
  }
  std::string messages;
};

std::mutex& console_mutex() {
  static std::mutex m;
  return m;
}

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error("chain_from_urdf: " + message); }

std::string quoted(const std::string& s) { return "'" + s + "'"; }

void require_finite(std::initializer_list<double> values, const std::string& what) {
  for (double v : values)
    if (!std::isfinite(v)) fail(what + ": expected finite numbers");
}

/// The 4x4 pose of an <origin>: translation, then the rotation urdfdom keeps
/// as the unit quaternion of rpy (R = Rz(yaw) Ry(pitch) Rx(roll)).
Matrix4 pose(const urdf::Pose& p, const std::string& what) {
  const urdf::Rotation& q = p.rotation;
  require_finite({p.position.x, p.position.y, p.position.z, q.x, q.y, q.z, q.w}, what + " <origin>");
  Matrix4 T = Matrix4::Identity();
  T.topLeftCorner<3, 3>() = Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
  T.topRightCorner<3, 1>() = Vector3(p.position.x, p.position.y, p.position.z);
  return T;
}

struct Part {
  double mass;
  Vector3 com;
  Matrix3 inertia;  // about com
};

/// A link's <inertial> in the base frame at home (T_link: the link frame
/// there), if it has one.
void add_inertial(const urdf::Link& link, const Matrix4& T_link, std::vector<Part>& parts) {
  if (!link.inertial) return;
  const urdf::Inertial& in = *link.inertial;
  const std::string what = "link " + quoted(link.name);
  require_finite({in.mass}, what + " <mass>");
  require_finite({in.ixx, in.ixy, in.ixz, in.iyy, in.iyz, in.izz}, what + " <inertia>");
  const Matrix4 T = T_link * pose(in.origin, what + " <inertial>");
  Matrix3 I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  const Matrix3 R = T.topLeftCorner<3, 3>();
  parts.push_back({in.mass, T.topRightCorner<3, 1>(), R * I * R.transpose()});
}

/// One body from several, all in one frame: the total mass, the
/// mass-weighted center, each inertia moved there by the parallel-axis
/// theorem, I + m (|d|^2 1 - d d^T).
Part merge(const std::vector<Part>& parts) {
  Part out{0.0, Vector3::Zero(), Matrix3::Zero()};
  for (const Part& p : parts) out.mass += p.mass;
  if (!(out.mass > 0)) {
    out.mass = 0.0;
    for (const Part& p : parts) out.inertia += p.inertia;
    return out;
  }
  for (const Part& p : parts) out.com += p.mass * p.com;
  out.com /= out.mass;
  for (const Part& p : parts) {
    const Vector3 d = p.com - out.com;
    out.inertia += p.inertia + p.mass * (d.dot(d) * Matrix3::Identity() - d * d.transpose());
  }
  return out;
}

/// urdfdom's links hold their children by shared_ptr, so a loop in the
/// description (which urdfdom may accept: a link under the root that is the
/// child of two joints, two links each the parent of the other) is a
/// reference cycle that outlives the model. Cleared on every way out.
struct ReleaseCycles {
  const urdf::ModelInterfaceSharedPtr& model;
  ~ReleaseCycles() {
    if (!model) return;
    for (const auto& entry : model->links_) {
      entry.second->child_links.clear();
      entry.second->child_joints.clear();
    }
  }
};

std::string read_source(const std::string& source) {
  const std::size_t first = source.find_first_not_of(" \t\r\n\f\v");
  if (first != std::string::npos && source[first] == '<') return source;
  std::ifstream file(source, std::ios::binary);
  if (!file) fail("cannot open the file " + quoted(source) + " (a source that does not start with '<' is a path)");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

UrdfDescription read(const std::string& source, const std::string& tip_link, const std::string& base_link_in) {
  const std::string text = read_source(source);
  urdf::ModelInterfaceSharedPtr model;
  const ReleaseCycles release{model};
  {
    const std::lock_guard<std::mutex> lock(console_mutex());
    Capture capture;
    console_bridge::useOutputHandler(&capture);
    try {
      model = urdf::parseURDF(text);
    } catch (...) {
      console_bridge::restorePreviousOutputHandler();
      throw;
    }
    console_bridge::restorePreviousOutputHandler();
    if (!model)
      fail("urdfdom refused the description: " + (capture.messages.empty() ? "no reason given" : capture.messages));
    // urdfdom logs some errors and goes on: an <inertial> without <mass>,
    // <inertia> or one of its attributes is kept with zeros in place of the
    // values it could not read. Such a description is refused.
    if (!capture.messages.empty()) fail("urdfdom reported errors in the description: " + capture.messages);
  }

  // A link that is the child of two joints: urdfdom keeps one parent, and
  // reports two roots or (when the other parent hangs below) nothing.
  std::map<std::string, std::string> parent_joint;
  for (const auto& [name, joint] : model->joints_) {
    const auto [it, inserted] = parent_joint.emplace(joint->child_link_name, name);
    if (!inserted)
      fail("link " + quoted(joint->child_link_name) + " is the child of joints " + quoted(it->second) + " and " +
           quoted(name) + ": a loop (URDF describes trees)");
  }
  if (!model->getLink(tip_link))
    throw std::runtime_error("chain_from_urdf(tip_link): no link named " + quoted(tip_link) + " in the description");
  if (!base_link_in.empty() && !model->getLink(base_link_in))
    throw std::runtime_error("chain_from_urdf(base_link): no link named " + quoted(base_link_in) +
                             " in the description");
  const std::string base_link = base_link_in.empty() ? model->getRoot()->name : base_link_in;

  // From the tip up to the base.
  std::vector<urdf::JointConstSharedPtr> path;
  std::set<std::string> seen;
  for (std::string link = tip_link; link != base_link;) {
    if (!seen.insert(link).second) fail("a loop through link " + quoted(link));
    const auto it = parent_joint.find(link);
    if (it == parent_joint.end())
      fail("tip_link " + quoted(tip_link) + " is not below base_link " + quoted(base_link));
    const urdf::JointConstSharedPtr joint = model->getJoint(it->second);
    path.push_back(joint);
    link = joint->parent_link_name;
  }
  std::reverse(path.begin(), path.end());
  std::set<std::string> on_path{base_link};
  for (const auto& joint : path) on_path.insert(joint->child_link_name);

  // Links hanging off the chain ride rigidly on the chain link they hang
  // from: fixed joints as they are, moving joints off the chain at zero.
  std::function<void(const urdf::Link&, const Matrix4&, std::vector<Part>&)> hanging;
  hanging = [&](const urdf::Link& link, const Matrix4& T_link, std::vector<Part>& parts) {
    for (const auto& joint : link.child_joints) {
      if (on_path.count(joint->child_link_name)) continue;
      const Matrix4 T_child = T_link * pose(joint->parent_to_joint_origin_transform, "joint " + quoted(joint->name));
      const urdf::LinkConstSharedPtr child = model->getLink(joint->child_link_name);
      add_inertial(*child, T_child, parts);
      hanging(*child, T_child, parts);
    }
  };

  UrdfDescription d;
  std::vector<Eigen::Matrix<double, 6, 1>> screws;
  std::vector<double> lower, upper, velocity, effort;
  std::vector<std::vector<Part>> bodies;  // per moving joint, the links it moves
  Matrix4 T = Matrix4::Identity();
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& joint : path) {
    const std::string what = "joint " + quoted(joint->name);
    const int kind = joint->type;
    if (kind == urdf::Joint::FLOATING || kind == urdf::Joint::PLANAR)
      fail(what + " is " + (kind == urdf::Joint::FLOATING ? "floating" : "planar") +
           ": a serial chain has joints of one degree of freedom");
    if (kind != urdf::Joint::REVOLUTE && kind != urdf::Joint::CONTINUOUS && kind != urdf::Joint::PRISMATIC &&
        kind != urdf::Joint::FIXED)
      fail(what + ": unknown joint type");
    if (joint->mimic) fail(what + ": <mimic> joints are not supported");
    T = T * pose(joint->parent_to_joint_origin_transform, what);
    if (kind != urdf::Joint::FIXED) {
      const Vector3 axis(joint->axis.x, joint->axis.y, joint->axis.z);
      require_finite({axis.x(), axis.y(), axis.z()}, what + " <axis xyz>");
      const double norm = axis.norm();
      if (!(norm > 0)) fail(what + ": <axis xyz> is zero");
      Vector3 w = T.topLeftCorner<3, 3>() * (axis / norm);
      w /= w.norm();
      Eigen::Matrix<double, 6, 1> s;
      if (kind == urdf::Joint::PRISMATIC)
        s << w, Vector3::Zero();
      else
        s << -w.cross(Vector3(T.topRightCorner<3, 1>())), w;
      screws.push_back(s);
      const urdf::JointLimitsSharedPtr& limit = joint->limits;
      double lo = -inf, hi = inf;
      if (kind != urdf::Joint::CONTINUOUS) {
        if (!limit) fail(what + ": a " + (kind == urdf::Joint::PRISMATIC ? "prismatic" : "revolute") +
                         " joint needs a <limit>");
        require_finite({limit->lower, limit->upper}, what + " <limit>");
        lo = limit->lower;
        hi = limit->upper;
      }
      if (limit) require_finite({limit->velocity, limit->effort}, what + " <limit>");
      d.names.push_back(joint->name);
      d.types.push_back(kind == urdf::Joint::PRISMATIC    ? JointType::prismatic
                        : kind == urdf::Joint::CONTINUOUS ? JointType::continuous
                                                          : JointType::revolute);
      lower.push_back(lo);
      upper.push_back(hi);
      velocity.push_back(limit ? limit->velocity : inf);
      effort.push_back(limit ? limit->effort : inf);
      bodies.emplace_back();
    }
    if (!bodies.empty()) {  // links before the first moving joint belong to the base
      const urdf::LinkConstSharedPtr child = model->getLink(joint->child_link_name);
      add_inertial(*child, T, bodies.back());
      hanging(*child, T, bodies.back());
    }
  }
  if (screws.empty())
    fail("no revolute, continuous or prismatic joint from " + quoted(base_link) + " to " + quoted(tip_link));

  const auto n = static_cast<Eigen::Index>(screws.size());
  d.screws.resize(6, n);
  d.lower.resize(n);
  d.upper.resize(n);
  d.velocity.resize(n);
  d.effort.resize(n);
  d.mass.resize(n);
  d.com.resize(3, n);
  d.inertia.resize(9, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    d.screws.col(i) = screws[k];
    d.lower(i) = lower[k];
    d.upper(i) = upper[k];
    d.velocity(i) = velocity[k];
    d.effort(i) = effort[k];
    const Part body = merge(bodies[k]);
    d.mass(i) = body.mass;
    d.com.col(i) = body.com;
    d.inertia.col(i) = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(body.inertia.data());
  }
  d.home = T;
  return d;
}

}  // namespace

UrdfDescription read_urdf(const std::string& xml_or_path, const std::string& tip_link,
                          const std::string& base_link) noexcept {
  try {
    return read(xml_or_path, tip_link, base_link);
  } catch (const std::exception& e) {
    UrdfDescription d;
    d.error = e.what();
    return d;
  } catch (...) {
    UrdfDescription d;
    d.error = "chain_from_urdf: an unknown exception while reading the description";
    return d;
  }
}

}  // namespace detail
}  // namespace chasles
