// chasles: a group seen part by part: a rotation (an SO2 or an SO3) and
// Euclidean coordinates, for what is defined part by part rather than from
// exp and log: the chordal mean (mean.hpp), elements uniform in a box
// (random.hpp) and the distances of the parts (distance.hpp).
//
// GroupParts<G> describes G by
//   Rotation                 the rotation group of G (G itself for SO2, SO3)
//   K                        the number of Euclidean coordinates, Vector = K-vector
//   B                        the number of blocks the distance measures apart
//   rotation(g), vector(g)   g's parts;  make(R, v) the element of the parts
//   block_norms(d)           the Euclidean norm of each of the B blocks of d (a K-vector)
// so that make(rotation(g), vector(g)) == g.
//
// Two families are described from the group's interface alone, so that a
// new group of either joins with no line of its own:
// - rotation groups (SO2, SO3): no member type Rotation, and a matrix of
//   size n with DoF = n (n - 1) / 2. K = B = 0.
// - matrix semidirect products of a rotation group and vectors (SE2, SE3,
//   SE_2(3)): a member type Rotation (r x r), a matrix of size n = r + m of
//   the form [[R, c_1 .. c_m], [0, I]] and DoF = r (r - 1) / 2 + r m. The
//   vector is (c_1, .., c_m) (K = r m, the columns stacked), B = m blocks
//   (|c_j| each); the parts are read from matrix() and made by
//   from_matrix_unchecked, so the layout is the only assumption: a group of
//   this size whose matrix is laid out otherwise must specialize GroupParts.
// Groups of other shapes specialize GroupParts; without it, the part-wise
// functions do not compile for them (exp/log-based ones, the geodesic mean,
// the Gaussian samples, the splines, do). Sim(3) is specialized below.
#pragma once

#include <cmath>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "chasles/lie_group.hpp"
#include "chasles/sim3.hpp"
#include "chasles/so3.hpp"

namespace chasles {

namespace detail {

/// The type of g.matrix() (n x n).
template <typename G>
using MatrixTypeOf = std::decay_t<decltype(std::declval<const G&>().matrix())>;
template <typename G>
constexpr int matrix_size = MatrixTypeOf<G>::RowsAtCompileTime;

template <typename G, typename = void>
struct HasRotation : std::false_type {};
template <typename G>
struct HasRotation<G, std::void_t<typename G::Rotation>> : std::true_type {};

/// A rotation group: no Rotation member, DoF = n (n - 1) / 2.
template <typename G, typename = void>
struct IsRotationGroup : std::false_type {};
template <typename G>
struct IsRotationGroup<G, std::enable_if_t<IsLieGroup<G>::value && !HasRotation<G>::value>>
    : std::bool_constant<G::DoF == matrix_size<G>*(matrix_size<G> - 1) / 2> {};

/// A matrix semidirect product [[R, c_1 .. c_m], [0, I]]: DoF = r (r - 1) / 2 + r m, n = r + m.
template <typename G, typename = void>
struct IsSemidirectProduct : std::false_type {};
template <typename G>
struct IsSemidirectProduct<G, std::enable_if_t<IsLieGroup<G>::value && HasRotation<G>::value>> {
  static constexpr int r = matrix_size<typename G::Rotation>, m = matrix_size<G> - r;
  static constexpr bool value = m > 0 && G::DoF == r*(r - 1) / 2 + r* m;
};

}  // namespace detail

/// The parts of a group (see the file comment); undefined for groups that
/// are not described.
template <typename G, typename = void>
struct GroupParts;

/// A rotation group is its own rotation; no Euclidean part.
template <typename G>
struct GroupParts<G, std::enable_if_t<detail::IsRotationGroup<G>::value>> {
  using Scalar = typename G::Scalar;
  using Rotation = G;
  static constexpr int K = 0, B = 0;
  using Vector = Eigen::Matrix<Scalar, 0, 1>;
  static const G& rotation(const G& g) noexcept { return g; }
  static Vector vector(const G& /*g*/) noexcept { return Vector(); }
  static G make(const Rotation& R, const Vector& /*v*/) noexcept { return R; }
  static Eigen::Matrix<Scalar, 0, 1> block_norms(const Vector& /*d*/) noexcept { return {}; }
};

/// [[R, c_1 .. c_m], [0, I]]: the rotation R and the columns c_j stacked.
template <typename G>
struct GroupParts<G, std::enable_if_t<detail::IsSemidirectProduct<G>::value>> {
  using Scalar = typename G::Scalar;
  using Rotation = typename G::Rotation;
  static constexpr int r = detail::IsSemidirectProduct<G>::r, m = detail::IsSemidirectProduct<G>::m;
  static constexpr int K = r * m, B = m;
  using Vector = Eigen::Matrix<Scalar, K, 1>;
  using Matrix = detail::MatrixTypeOf<G>;
  static Rotation rotation(const G& g) noexcept {
    return Rotation::from_matrix_unchecked(g.matrix().template topLeftCorner<r, r>());
  }
  static Vector vector(const G& g) noexcept {
    const Matrix M = g.matrix();
    Vector v;
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < r; ++i) v[j * r + i] = M(i, r + j);
    return v;
  }
  static G make(const Rotation& R, const Vector& v) noexcept {
    Matrix M = Matrix::Identity();
    M.template topLeftCorner<r, r>() = R.matrix();
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < r; ++i) M(i, r + j) = v[j * r + i];
    return G::from_matrix_unchecked(M);
  }
  /// |d_j| for each column block j.
  static Eigen::Matrix<Scalar, B, 1> block_norms(const Vector& d) noexcept {
    Eigen::Matrix<Scalar, B, 1> n;
    for (int j = 0; j < m; ++j) n[j] = d.template segment<r>(j * r).norm();
    return n;
  }
};

/// Sim(3) (R, t, s): the rotation R and (t, sigma), sigma = log s, so that
/// what is uniform or averaged in the Euclidean part is the scale's
/// logarithm (a mean of the vectors is the geometric mean of the scales);
/// two blocks: |t| and |sigma|.
template <typename S>
struct GroupParts<Sim3<S>> {
  using Scalar = S;
  using Rotation = SO3<S>;
  static constexpr int K = 4, B = 2;
  using Vector = Eigen::Matrix<S, 4, 1>;
  static const Rotation& rotation(const Sim3<S>& g) noexcept { return g.rotation(); }
  static Vector vector(const Sim3<S>& g) noexcept {
    using std::log;
    const Eigen::Matrix<S, 3, 1>& t = g.translation();
    return Vector(t[0], t[1], t[2], log(g.scale()));
  }
  static Sim3<S> make(const Rotation& R, const Vector& v) noexcept {
    using std::exp;
    return Sim3<S>(R, Eigen::Matrix<S, 3, 1>(v[0], v[1], v[2]), exp(v[3]));
  }
  static Eigen::Matrix<S, 2, 1> block_norms(const Vector& d) noexcept {
    using std::abs;
    return Eigen::Matrix<S, 2, 1>(d.template head<3>().norm(), abs(d[3]));
  }
};

namespace detail {

/// Whether GroupParts<G> is defined.
template <typename G, typename = void>
struct HasParts : std::false_type {};
template <typename G>
struct HasParts<G, std::void_t<decltype(GroupParts<G>::K)>> : std::true_type {};

}  // namespace detail

}  // namespace chasles
