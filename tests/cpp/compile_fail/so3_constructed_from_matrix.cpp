// A raw 3x3 matrix is not a rotation until it is checked, projected or
// vouched for: SO3d R(M), SO3d R = M and R = M do not compile, and the
// message names the three explicit forms.
// cases: 4
// expect: SO3::from_matrix\(M\)
// expect: from_matrix_projected
// expect: from_matrix_unchecked
#include <chasles/so3.hpp>

int main() {
  const Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
  chasles::SO3d R = chasles::SO3d::from_matrix_unchecked(M);
#if CHASLES_COMPILE_FAIL == 1
  const chasles::SO3d R1(Eigen::Matrix3d::Identity());
  R = R1;
#elif CHASLES_COMPILE_FAIL == 2
  const chasles::SO3d R2 = M;
  R = R2;
#elif CHASLES_COMPILE_FAIL == 3
  R = 2.0 * M;
#elif CHASLES_COMPILE_FAIL == 4
  R = chasles::SO3d(M.transpose());
#endif
  return R.matrix()(0, 0) > 0.0 ? 0 : 1;
}
