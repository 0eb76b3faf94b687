// SE3d(M, p) with M a 3x3 matrix: the rotation part is an SO3, built explicitly.
// expect: SO3::from_matrix\(M\)
#include <chasles/se3.hpp>

int main() {
  const Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d p(1, 2, 3);
  const chasles::SE3d ok(chasles::SO3d::from_matrix_projected(M), p);
#if CHASLES_COMPILE_FAIL == 1
  const chasles::SE3d g(M, p);
  static_cast<void>(g);
#endif
  return ok.translation() == p ? 0 : 1;
}
