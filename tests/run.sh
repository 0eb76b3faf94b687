#!/usr/bin/env bash
# Runs the tests of chasles on a fresh Debian/Ubuntu machine: installs what
# it needs (apt-get for Eigen, GoogleTest, Google Benchmark, urdfdom for the
# C++ URDF loader; pip for the Python side), then, by stage:
#   cpp        configures and builds the C++ tests, examples and benchmarks
#              (portable only: bench/report.py builds the -march=native
#              ones), and runs ctest (the tests, the examples, and a
#              millisecond smoke run of every benchmark);
#   hardening  the suites that reach memory under the sanitizers, and the
#              fuzz targets (their seed corpus replayed, then 20 s of
#              fuzzing per target);
#   python     builds the Python wheel (pip wheel .: scikit-build-core,
#              pybind11 and cmeel-eigen from PyPI) with the system's Eigen
#              hidden from CMake, so that it takes Eigen from cmeel-eigen as
#              on a machine without Eigen and without root, and checks that
#              it did; installs the wheel with its test extras into a fresh
#              virtual environment with CC and CXX set to /bin/false (a
#              wheel needs no compiler), and runs pytest on it from outside
#              the source tree (with the C++ URDF loader's cross-check, whose
#              program it builds when the cpp stage has not);
#   all        (the default, what CI runs) the three, in that order, the
#              fuzzing of the hardening stage beside pytest.
#
#   bash tests/run.sh [all|cpp|hardening|python]   # from the repository root
#
# In CI (2 cores) `all` took 36 to 41 minutes; building the wheel needs about
# 1.7 GB of memory. CONTRIBUTING.md has a faster loop for a single change.
#
# BUILD_DIR (default build/tests), VENV (default build/venv), WHEEL_DIR
# (default build/wheel), WHEEL_BUILD_DIR (default build/wheel-cmake, the
# wheel's CMake tree) and JOBS (default: nproc) can be set.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
STAGE=${1:-all}
case "$STAGE" in
  all | cpp | hardening | python) ;;
  *)
    echo "usage: bash tests/run.sh [all|cpp|hardening|python] (default: all)" >&2
    exit 2
    ;;
esac
BUILD_DIR=${BUILD_DIR:-$ROOT/build/tests}
VENV=${VENV:-$ROOT/build/venv}
WHEEL_DIR=${WHEEL_DIR:-$ROOT/build/wheel}
WHEEL_BUILD_DIR=${WHEEL_BUILD_DIR:-$ROOT/build/wheel-cmake}
JOBS=${JOBS:-$(nproc)}

# apt_install PACKAGE...: installs those not installed yet.
apt_install() {
  local need=() pkg SUDO=""
  for pkg in "$@"; do
    dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
  done
  if [ ${#need[@]} -gt 0 ]; then
    [ "$(id -u)" -ne 0 ] && SUDO=sudo
    $SUDO apt-get update
    $SUDO apt-get install -y --no-install-recommends "${need[@]}"
  fi
}

# The packages of the C++ build (and of the venv, for the python stage).
apt_cpp() {
  local extra=()
  python3 -c "import venv, ensurepip" >/dev/null 2>&1 || extra+=(python3-venv)
  apt_install libeigen3-dev libgtest-dev libbenchmark-dev liburdfdom-dev cmake g++ "${extra[@]}"
}

# Each C++ suite (tests/cpp/test_*.cpp) is built and run once: the suites
# that reach memory beyond fixed-size values under the sanitizers (the
# hardening stage below says which and why), every other one in the cpp
# stage, with g++ at -O3. Building every suite in both builds cost the suite
# 4.5 more CPU minutes for no further check: the optimized compile of every
# operation is the real-time exercise's (chasles_realtime_exercise, which
# chasles_strict_compile and the allocation test link, here), and the
# Python suite runs the same headers compiled by g++ -O3.
SANITIZED_SUITES="test_urdf;test_io;test_kinematics;test_inverse_kinematics;test_dynamics;test_spline;test_bspline"
SANITIZED_SUITES+=";test_mean;test_arguments;test_random;test_finite;test_fuzz_regressions"
OPTIMIZED_SUITES=""
for source in "$ROOT"/tests/cpp/test_*.cpp; do
  suite=$(basename "$source" .cpp)
  case ";$SANITIZED_SUITES;" in
    *";$suite;"*) ;;
    *) OPTIMIZED_SUITES+="${OPTIMIZED_SUITES:+;}$suite" ;;
  esac
done

configure_cpp() {
  cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DCHASLES_BUILD_TESTS=ON -DCHASLES_BUILD_BENCH=ON \
    -DCHASLES_BENCH_NATIVE=OFF -DCHASLES_BUILD_EXAMPLES=ON "-DCHASLES_TEST_SUITES=$OPTIMIZED_SUITES"
}

stage_cpp() {
  apt_cpp
  echo "== C++: configure, build, ctest"
  configure_cpp
  cmake --build "$BUILD_DIR" -j "$JOBS"
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"
}

# ---- Hardening (C++): under AddressSanitizer and UndefinedBehaviorSanitizer
# (clang, build/sanitize, -O0 -g1: gcc took 7 CPU minutes to build the
# suites at -O0, 11 at -O1 and 28 at -O2 -g; clang takes 4.7 at -O0) the
# suites that reach memory beyond fixed-size values (SANITIZED_SUITES
# above): the URDF loader over
# urdfdom's heap (LeakSanitizer found its shared_ptr cycles), printing,
# arms of a run-time joint count, inverse kinematics and dynamics, splines
# over caller storage, means over iterators, Eigen maps of any stride
# (test_arguments), generators, non-finite and huge inputs (test_finite),
# and the fuzzers' findings; with them the real-time exercise, compiled with
# assertions on under the strict flags (chasles_realtime_exercise) and run
# by chasles_strict_compile and by the allocation test (Eigen's no-malloc
# check is an assertion: it runs here; the counting operator new, malloc
# and realloc run in both builds), and each header alone under clang's strict flags. The typed
# suites of fixed-size math (group laws, accuracy, Jacobians, autodiff, ...)
# run in the optimized g++ build above; their raw-input surface is the fuzz
# targets', which run under the same sanitizers: building them here too cost
# the suite 4 more CPU minutes. Then the libFuzzer targets of tests/fuzz
# (clang, build/fuzz): their seed corpus replayed by ctest, and 20 s of
# fuzzing per target (tests/fuzz/README.md); in `all`, in the background
# while pytest runs (on one core most of the time) at the end.
# Self-contained: its own packages and build directories.
stage_hardening_builds() {
  apt_cpp
  apt_install clang libclang-rt-14-dev
  echo "== C++ under AddressSanitizer + UndefinedBehaviorSanitizer: configure, build, ctest"
  CXX=clang++ cmake -S "$ROOT" -B "$ROOT/build/sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O0 -g1" \
    -DCHASLES_BUILD_TESTS=ON -DCHASLES_BUILD_BENCH=OFF -DCHASLES_SANITIZE=ON "-DCHASLES_TEST_SUITES=$SANITIZED_SUITES"
  cmake --build "$ROOT/build/sanitize" -j "$JOBS"
  ctest --test-dir "$ROOT/build/sanitize" --output-on-failure -j "$JOBS"
  echo "== C++ fuzzing (libFuzzer, clang): build, seed corpus replay (20 s per target run beside pytest)"
  CXX=clang++ cmake -S "$ROOT" -B "$ROOT/build/fuzz" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCHASLES_BUILD_FUZZ=ON
  cmake --build "$ROOT/build/fuzz" -j "$JOBS"
  ctest --test-dir "$ROOT/build/fuzz" --output-on-failure
}

FUZZ_LOG="$ROOT/build/fuzz/run.log"
FUZZ_PID=""
start_fuzzing() {
  bash "$ROOT/tests/fuzz/run.sh" "$ROOT/build/fuzz" 20 > "$FUZZ_LOG" 2>&1 &
  FUZZ_PID=$!
  trap 'kill "$FUZZ_PID" 2>/dev/null || true' EXIT
}
finish_fuzzing() {
  echo "== C++ fuzzing: what it ran (tests/fuzz/run.sh, started above)"
  local status=0
  wait "$FUZZ_PID" || status=$?
  cat "$FUZZ_LOG"
  if [ "$status" -ne 0 ]; then
    echo "error: fuzzing failed (exit $status); see above" >&2
    exit "$status"
  fi
}
# ---- end of the hardening stage (in `all`, its fuzzing runs beside pytest, below)

stage_python() {
  apt_cpp
  echo "== Python: pip wheel . (scikit-build-core, pybind11, cmeel-eigen from PyPI) with the system's"
  echo "   Eigen hidden, installed into a fresh virtual environment with no compiler reachable,"
  echo "   pytest from outside the source tree"
  rm -rf "$VENV" "$WHEEL_DIR" "$WHEEL_BUILD_DIR"
  python3 -m venv "$VENV"
  # A venv gets the pip its Python bundles (Debian 12: pip 23.0, which has no
  # -C, the short form of --config-settings used below, added in pip 23.1).
  "$VENV/bin/python" -m pip install --quiet --upgrade pip
  # The system's Eigen (installed above for the C++ tests) is hidden from the
  # wheel's CMake: CMAKE_IGNORE_PATH makes find_package skip an Eigen3Config.cmake
  # in those directories, and only there, so CMakeLists.txt falls back on the
  # cmeel-eigen build requirement as it does on a machine with no Eigen. The
  # CMake tree is kept (build-dir) so that its cache shows which Eigen was used.
  "$VENV/bin/python" -m pip wheel --quiet --no-deps -w "$WHEEL_DIR" -C "build-dir=$WHEEL_BUILD_DIR" \
    -C "cmake.define.CMAKE_IGNORE_PATH=/usr/share/eigen3/cmake;/usr/lib/cmake/eigen3;/usr/include/eigen3" "$ROOT"
  EIGEN_DIR=$(sed -n 's/^Eigen3_DIR:PATH=//p' "$WHEEL_BUILD_DIR/CMakeCache.txt")
  echo "   the wheel was built with Eigen3_DIR=$EIGEN_DIR"
  case "$EIGEN_DIR" in
    */cmeel.prefix/share/eigen3/cmake) ;;
    *) echo "error: the wheel's Eigen is not cmeel-eigen's (the system's was not hidden?)" >&2; exit 1 ;;
  esac
  WHEEL=$(ls "$WHEEL_DIR"/chasles-*.whl)
  CC=/bin/false CXX=/bin/false "$VENV/bin/python" -m pip install --quiet --only-binary=chasles "$WHEEL[test]"
  # CHASLES_URDF_DUMP: the C++ URDF loader's JSON dump (tests/cpp/urdf_dump.cpp,
  # built by the cpp stage, or here alone), which tests/python/test_urdf_cpp.py
  # compares with Chain.from_urdf on the arms of example-robot-data (a Python
  # package); CHASLES_REQUIRE_URDF_DUMP=1 makes that cross-check fail, not skip,
  # when anything it needs is missing.
  if [ "$STAGE" = python ]; then
    echo "== the C++ URDF loader's dump program, for the cross-check"
    configure_cpp
    cmake --build "$BUILD_DIR" -j "$JOBS" --target chasles_urdf_dump
  fi
  # One BLAS thread: the tests' small scipy/numpy products gain nothing from
  # more, and OpenBLAS threads spinning on a loaded 2-core machine made the
  # suite several times slower (116 s against 17 s for the same tests).
  # In `all`, the fuzzing of the hardening stage runs meanwhile, on the core
  # pytest leaves idle; its outcome is read after pytest.
  if [ "$STAGE" = all ]; then start_fuzzing; fi
  (cd "$VENV" && OPENBLAS_NUM_THREADS=1 CHASLES_REQUIRE_URDF_DUMP=1 \
    CHASLES_URDF_DUMP="$BUILD_DIR/tests/cpp/chasles_urdf_dump" \
    "$VENV/bin/python" -m pytest "$ROOT/tests/python" -p no:cacheprovider)
  if [ "$STAGE" = all ]; then finish_fuzzing; fi
}

case "$STAGE" in
  cpp) stage_cpp ;;
  hardening)
    stage_hardening_builds
    echo "== C++ fuzzing: 20 s per target (tests/fuzz/run.sh)"
    bash "$ROOT/tests/fuzz/run.sh" "$ROOT/build/fuzz" 20
    ;;
  python) stage_python ;;
  all)
    stage_cpp
    stage_hardening_builds
    stage_python
    ;;
esac
