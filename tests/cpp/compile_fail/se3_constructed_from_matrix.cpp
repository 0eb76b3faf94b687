// A raw 4x4 matrix is not a rigid motion until it is checked, projected or
// vouched for: SE3d g(M), SE3d g = M and g = M do not compile, and the
// message names the three explicit forms.
// cases: 3
// expect: SE3::from_matrix\(M\)
// expect: from_matrix_projected
// expect: from_matrix_unchecked
#include <chasles/se3.hpp>

int main() {
  const Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  chasles::SE3d g = chasles::SE3d::from_matrix(M).value_or(chasles::SE3d());
#if CHASLES_COMPILE_FAIL == 1
  const chasles::SE3d g1(Eigen::Matrix4d::Identity());
  g = g1;
#elif CHASLES_COMPILE_FAIL == 2
  const chasles::SE3d g2 = M;
  g = g2;
#elif CHASLES_COMPILE_FAIL == 3
  g = M;
#endif
  return g.matrix()(0, 0) > 0.0 ? 0 : 1;
}
