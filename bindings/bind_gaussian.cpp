// chasles._core: Gaussians on the groups (chasles/gaussian.hpp) as numpy
// generalized ufuncs: the array functions <g>_compose_cov, <g>_between_cov
// and <g>_inverse_cov over batches of means and covariances, and the private
// gufuncs behind the class chasles.Gaussian (python/chasles/_gaussian.py).
// Each kernel makes chasles::Gaussian of one element and calls one of its
// methods: no mathematics here.
#include <deque>
#include <string>
#include <tuple>

#include <chasles/gaussian.hpp>
#include <chasles/se2.hpp>
#include <chasles/se23.hpp>
#include <chasles/se3.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so2.hpp>
#include <chasles/so3.hpp>

#include "bindings.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

using ufunc::array_doc;
using ufunc::Core;
using ufunc::def_ufunc;
using ufunc::Float64;
using ufunc::ScalarOf;
using ufunc::strided;

/// The Gaussian of the group Group over the scalar of the operands, from a
/// mean matrix (taken as given) and a covariance.
template <typename Group, typename M, typename C>
auto make(const M& mean, const C& cov) noexcept {
  using G = Rebind<Group, ScalarOf<M>>;
  return chasles::Gaussian<G>(G::from_matrix_unchecked(mean), typename G::AdjointMatrix(cov));
}

/// A Gaussian as the pair (mean matrix, covariance) a gufunc returns (an
/// SE3 mean as itself: the loop writes its parts in place, ufunc.hpp).
template <typename G>
auto pair(const chasles::Gaussian<G>& x) noexcept {
  if constexpr (ufunc::IsSE3<G>::value)
    return std::make_tuple(x.mean(), x.cov());
  else
    return std::make_tuple(chasles::detail::MatrixTypeOf<G>(x.mean().matrix()), x.cov());
}

/// "se3_compose_cov", "_se3_act_cov" (`hidden`), ...: a name numpy keeps
/// (it holds the pointer), so it lives as long as the module.
template <typename Group>
const char* name_of(const char* what, bool hidden = false) {
  static std::deque<std::string> names;  // push_back moves none of them
  names.push_back((hidden ? "_" : "") + std::string(GroupNames<Group>::prefix) + what);
  return names.back().c_str();
}

/// The docstring of a public Gaussian gufunc of the group: its title, the
/// convention, the operands (a, cov_a, and b, cov_b if `binary`) and what
/// it returns (`result`: the means' words).
template <typename Group>
std::string gaussian_doc(const std::string& title, bool binary, const std::string& result) {
  const std::string n = std::to_string(chasles::detail::matrix_size<Group>), d = std::to_string(Group::DoF);
  const auto operand = [&](const std::string& x, const std::string& which) {
    return "    " + x + ": array_like of shape (..., " + n + ", " + n + "): " + matrices_words<Group>() + ", the " +
           which + "means (taken as given).\n    cov_" + x + ": array_like of shape (..., " + d + ", " + d +
           "): their covariances.\n";
  };
  return array_doc((title +
                    "\n\nA Gaussian is X = mean exp(e), e ~ N(0, cov): the right perturbation, in the order of the "
                    "group's tangent, of chasles.Gaussian and of the Jacobians. First order: each covariance is "
                    "carried by the operation's Jacobians, J cov J^T.\n\nArgs:\n" +
                    operand("a", binary ? "first " : "") + (binary ? operand("b", "second ") : std::string()) +
                    "\nReturns:\n    tuple (mean, cov): numpy.ndarray of shapes (..., " + n + ", " + n +
                    ") and (..., " + d + ", " + d + "), " + result +
                    " and their covariances, the batch shape being the broadcast of the operands'.")
                       .c_str());
}

template <typename Group>
void def_gaussian(py::module_& m) {
  constexpr int N = chasles::detail::matrix_size<Group>, D = Group::DoF, P = point_size<Group>();
  using M = Core<N, N>;
  using C = Core<D, D>;
  using Pair = std::tuple<M, C>;
  const std::string cls = GroupNames<Group>::cls;
  const std::string compose_doc = gaussian_doc<Group>(
      "Composition of independent Gaussians on " + cls + ": (a b, Ad_{b^-1} cov_a Ad_{b^-1}^T + cov_b).", true,
      "the means a b");
  const std::string between_doc = gaussian_doc<Group>(
      "Relative motion of independent Gaussians on " + cls + ": (a^-1 b, Ad_{b^-1 a} cov_a Ad_{b^-1 a}^T + cov_b).",
      true, "the means a^-1 b");
  const std::string inverse_doc =
      gaussian_doc<Group>("Inverse of Gaussians on " + cls + ": (a^-1, Ad_a cov_a Ad_a^T).", false, "the means a^-1");
  def_ufunc<Pair(M, C, M, C)>(m, name_of<Group>("_compose_cov"), "a, cov_a, b, cov_b", compose_doc,
                              strided([](const auto& a, const auto& ca, const auto& b, const auto& cb) noexcept {
                                return pair(make<Group>(a, ca).compose(make<Group>(b, cb)));
                              }));
  def_ufunc<Pair(M, C, M, C)>(m, name_of<Group>("_between_cov"), "a, cov_a, b, cov_b", between_doc,
                              strided([](const auto& a, const auto& ca, const auto& b, const auto& cb) noexcept {
                                return pair(make<Group>(a, ca).between(make<Group>(b, cb)));
                              }));
  def_ufunc<Pair(M, C)>(
      m, name_of<Group>("_inverse_cov"), "a, cov_a", inverse_doc,
      strided([](const auto& a, const auto& ca) noexcept { return pair(make<Group>(a, ca).inverse()); }));

  // The private gufuncs of chasles.Gaussian (float64).
  const std::string doc = "private: the kernel of chasles.Gaussian's methods on " + cls + ".";
  def_ufunc<Pair(M, C, M, C, C), Float64>(
      m, name_of<Group>("_compose_cov_cross", true), "a, cov_a, b, cov_b, cross", doc,
      strided([](const auto& a, const auto& ca, const auto& b, const auto& cb, const auto& cross) noexcept {
        return pair(make<Group>(a, ca).compose(make<Group>(b, cb), typename Group::AdjointMatrix(cross)));
      }));
  def_ufunc<Pair(M, C, M, C, C), Float64>(
      m, name_of<Group>("_between_cov_cross", true), "a, cov_a, b, cov_b, cross", doc,
      strided([](const auto& a, const auto& ca, const auto& b, const auto& cb, const auto& cross) noexcept {
        return pair(make<Group>(a, ca).between(make<Group>(b, cb), typename Group::AdjointMatrix(cross)));
      }));
  def_ufunc<Pair(M, C, M, C, Core<>), Float64>(
      m, name_of<Group>("_interpolate_cov", true), "a, cov_a, b, cov_b, t", doc,
      strided([](const auto& a, const auto& ca, const auto& b, const auto& cb, double t) noexcept {
        return pair(make<Group>(a, ca).interpolate(make<Group>(b, cb), t));
      }));
  def_ufunc<std::tuple<Core<P>, Core<P, P>>(M, C, Core<P>, Core<P, P>), Float64>(
      m, name_of<Group>("_act_cov", true), "g, cov, p, cov_p", doc,
      strided([](const auto& g, const auto& c, const auto& p, const auto& cp) noexcept {
        const auto q = make<Group>(g, c).act(p, cp);
        return std::make_tuple(q.mean, q.cov);
      }));
  def_ufunc<std::tuple<Core<D>, C>(M, C), Float64>(m, name_of<Group>("_log_cov", true), "g, cov", doc,
                                                   strided([](const auto& g, const auto& c) noexcept {
                                                     const auto x = make<Group>(g, c).log();
                                                     return std::make_tuple(x.mean, x.cov);
                                                   }));
  def_ufunc<C(M, C), Float64>(
      m, name_of<Group>("_left_cov", true), "g, cov", doc,
      strided([](const auto& g, const auto& c) noexcept { return make<Group>(g, c).left_covariance(); }));
  def_ufunc<Core<>(M, C, M), Float64>(m, name_of<Group>("_mahalanobis", true), "mean, cov, x", doc,
                                      strided([](const auto& g, const auto& c, const auto& x) noexcept {
                                        return make<Group>(g, c).mahalanobis(Group::from_matrix_unchecked(x));
                                      }));
  if constexpr (ufunc::IsSE3<Group>::value) {
    def_ufunc<Pair(M, C, M, C), Float64>(
        m, "_se3_compose_cov4", "a, cov_a, b, cov_b", doc,
        strided([](const auto& a, const auto& ca, const auto& b, const auto& cb) noexcept {
          return pair(chasles::compose_fourth_order(make<Group>(a, ca), make<Group>(b, cb)));
        }));
    def_ufunc<C(M, C), Float64>(m, "_se3_cov_to_ros", "g, cov", doc, strided([](const auto& g, const auto& c) noexcept {
                                  return chasles::to_ros_covariance(make<Group>(g, c));
                                }));
    def_ufunc<C(M, C), Float64>(
        m, "_se3_cov_from_ros", "g, ros_cov", doc, strided([](const auto& g, const auto& c) noexcept {
          return chasles::from_ros_covariance(Group::from_matrix_unchecked(g), typename Group::AdjointMatrix(c)).cov();
        }));
  }
}

}  // namespace

void bind_gaussian(py::module_& m) {
  def_gaussian<chasles::SO2d>(m);
  def_gaussian<chasles::SE2d>(m);
  def_gaussian<chasles::SO3d>(m);
  def_gaussian<chasles::SE3d>(m);
  def_gaussian<chasles::Sim3d>(m);
  def_gaussian<chasles::SE23d>(m);
}

}  // namespace chasles_py
