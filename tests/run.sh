#!/usr/bin/env bash
# Runs the tests of chasles on a fresh Debian/Ubuntu machine: installs what
# it needs (apt-get for Eigen, GoogleTest and GoogleMock, Google Benchmark,
# urdfdom for the C++ URDF loader, Ceres for chasles/ceres.hpp, clang; pip
# for the Python side), then, by stage:
#   cpp        two C++ builds. With g++ at -O3 (build/tests): the real-time
#              exercise in double (every operation) and each header alone
#              under the strict flags, the allocation test, the examples,
#              the mistakes that must not compile, find_package from an
#              installed prefix. With clang at -O0 under AddressSanitizer
#              and UndefinedBehaviorSanitizer (build/sanitize): every suite
#              of tests/cpp, the exercise again in float, double and
#              autodiff with assertions on, and the fuzz targets on their
#              seed corpus;
#   fuzz       20 s of fuzzing per target (tests/fuzz/run.sh), on the cpp
#              stage's build;
#   python     builds the Python wheel (pip wheel .: scikit-build-core,
#              pybind11 and cmeel-eigen from PyPI) with the system's Eigen
#              hidden from CMake, so that it takes Eigen from cmeel-eigen as
#              on a machine without Eigen and without root, and checks that
#              it did; installs the wheel with its test extras into a fresh
#              virtual environment with CC and CXX set to /bin/false (a
#              wheel needs no compiler), and runs pytest on it from outside
#              the source tree (with the C++ URDF loader's cross-check, whose
#              program it builds when the cpp stage has not);
#   all        (the default, what CI runs) the three, in two lanes that
#              share the machine: the g++ build first, then in the
#              background the python stage and after it the g++ build's
#              ctest (their output is printed when they end), while the
#              sanitizer build, its tests and the fuzzing run in the
#              foreground. Neither lane keeps both cores busy alone (one
#              compile at a time at the ends of a build, pytest on one
#              core), so together they finish sooner; the g++ ctest goes
#              to the lane that ends first (the python stage's ends about
#              200 s before the sanitizer's tests).
#
#   bash tests/run.sh [all|cpp|fuzz|python]   # from the repository root
#
# On 2 cores `all` took 1346 s (2596 s of CPU: the g++ build 190, its ctest
# 101, the sanitizer build 2003 beside the wheel's 720, its ctest 298 beside
# the fuzzing, pytest 241; test_ceres alone compiles in 60 s under the
# sanitizers); the same work in one lane took about 1600 s before the lanes
# and 3440 s on CI's shared machine. Building
# the wheel needs about 1.7 GB of memory. CONTRIBUTING.md has a faster loop
# for a single change.
#
# BUILD_DIR (default build/tests), VENV (default build/venv), WHEEL_DIR
# (default build/wheel), WHEEL_BUILD_DIR (default build/wheel-cmake, the
# wheel's CMake tree) and JOBS (default: nproc) can be set.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
STAGE=${1:-all}
case "$STAGE" in
  all | cpp | fuzz | python) ;;
  *)
    echo "usage: bash tests/run.sh [all|cpp|fuzz|python] (default: all)" >&2
    exit 2
    ;;
esac
BUILD_DIR=${BUILD_DIR:-$ROOT/build/tests}
SANITIZE_DIR=$ROOT/build/sanitize
VENV=${VENV:-$ROOT/build/venv}
WHEEL_DIR=${WHEEL_DIR:-$ROOT/build/wheel}
WHEEL_BUILD_DIR=${WHEEL_BUILD_DIR:-$ROOT/build/wheel-cmake}
JOBS=${JOBS:-$(nproc)}

# timed NAME COMMAND...: runs COMMAND and prints its wall time and its CPU
# time (user + sys of the processes it waited for, read from /proc: this
# shell's cutime + cstime), so that a CI log shows where the minutes go.
CLK_TCK=$(getconf CLK_TCK)
# cpu_ticks PID: the CPU ticks of the processes PID waited for. (The PID of
# the shell that calls, $BASHPID read before a $(...): the python stage of
# `all` is a subshell, whose $$ is the parent's, and a $(...) is another.)
cpu_ticks() { awk '{ print $16 + $17 }' "/proc/$1/stat"; }
# (A failure stops the script under set -e before the line is printed.)
timed() {
  local name=$1 t0=$SECONDS me=$BASHPID c0
  shift
  c0=$(cpu_ticks "$me")
  "$@"
  echo "[time] $name: $((SECONDS - t0)) s wall, $((($(cpu_ticks "$me") - c0) / CLK_TCK)) s CPU"
}
# The process groups of the python stage and of the fuzzing while `all` runs
# them in the background: a failure in the foreground stops them.
PY_PID=""
FUZZ_PID=""
on_exit() {
  if [ -n "$PY_PID" ]; then kill -- "-$PY_PID" 2>/dev/null || true; fi
  if [ -n "$FUZZ_PID" ]; then kill -- "-$FUZZ_PID" 2>/dev/null || true; fi
  local me=$BASHPID
  echo "[time] total: $SECONDS s wall, $(($(cpu_ticks "$me") / CLK_TCK)) s CPU"
}
trap on_exit EXIT

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
  apt_install libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev liburdfdom-dev libceres-dev cmake g++ "${extra[@]}"
}

# The g++ build: what needs the optimizer of the compiler that builds the
# wheel, and no test suite: the real-time exercise in double compiled at -O3
# -DNDEBUG under the strict flags (the optimizer's warnings) and run by
# chasles_strict_compile and the allocation test (the counting operator new,
# malloc and realloc), each header alone under g++'s strict flags, the
# examples, the compile-fail snippets, the install test, and the C++ URDF
# loader's dump for the Python cross-check. The suites run once, in the
# sanitizer build below: the Python suite runs the same headers compiled by
# g++ -O3, over the same hard inputs. (The exercise's float and autodiff
# files are the sanitizer build's: g++ spends 100 to 170 CPU-s on each,
# in template instantiation, at any -O.)
configure_cpp() {
  cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DCHASLES_BUILD_TESTS=ON -DCHASLES_BUILD_BENCH=OFF \
    -DCHASLES_BUILD_EXAMPLES=ON -DCHASLES_TEST_SUITES=none -DCHASLES_EXERCISE_SCALARS=double
}

# The clang build under AddressSanitizer and UndefinedBehaviorSanitizer
# (-O0: test_group_laws takes 44 s of CPU there against 70 s with g++ at
# -O3; gcc took 7 CPU minutes to build the memory suites at -O0, 11 at -O1
# and 28 at -O2 -g; -g0: line tables cost a quarter more CPU, 58 s against
# 42 for test_bspline, so a sanitizer's report here names the functions,
# and a rebuild with -g1 gives the lines): every suite (the URDF loader
# over urdfdom's heap, where LeakSanitizer found its shared_ptr cycles;
# arms of a run-time joint count, splines over caller storage, means over
# iterators, Eigen maps of any stride, non-finite and huge inputs, and the
# typed suites of fixed-size math), the real-time exercise in float, double
# and autodiff with assertions on (Eigen's no-malloc check is an assertion:
# it runs here), every header under clang's strict flags
# (chasles_strict_compile), and the libFuzzer targets of tests/fuzz on their
# seed corpus (their fuzzing is the fuzz stage; tests/fuzz/README.md builds
# them optimized for long runs). The benchmarks are not built here:
# bench/report.py builds and runs them (a smoke run at -O0 cost 2 CPU
# minutes of build for what a timing run shows at once).
configure_sanitize() {
  CXX=clang++ cmake -S "$ROOT" -B "$SANITIZE_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O0 -g0" \
    -DCHASLES_BUILD_TESTS=ON -DCHASLES_SANITIZE=ON -DCHASLES_BUILD_BENCH=OFF -DCHASLES_BUILD_FUZZ=ON
}

gxx_build() {
  echo "== C++ with g++ -O3: configure, build"
  timed "g++ configure" configure_cpp
  timed "g++ build" cmake --build "$BUILD_DIR" -j "$JOBS"
}
gxx_tests() {
  echo "== C++ with g++ -O3: ctest"
  timed "g++ ctest" ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS"
}
sanitizer_build() {
  echo "== C++ with clang under AddressSanitizer + UndefinedBehaviorSanitizer: configure, build"
  timed "sanitizer configure" configure_sanitize
  timed "sanitizer build" cmake --build "$SANITIZE_DIR" -j "$JOBS"
}
sanitizer_tests() {
  echo "== C++ with clang under AddressSanitizer + UndefinedBehaviorSanitizer: ctest"
  timed "sanitizer ctest" ctest --test-dir "$SANITIZE_DIR" --output-on-failure -j "$JOBS"
}
apt_all() {
  apt_cpp
  apt_install clang libclang-rt-14-dev
}
stage_cpp() {
  apt_all
  gxx_build
  gxx_tests
  sanitizer_build
  sanitizer_tests
}
stage_fuzz() {
  echo "== C++ fuzzing: 20 s per target (tests/fuzz/run.sh), on the cpp stage's build"
  bash "$ROOT/tests/fuzz/run.sh" "$SANITIZE_DIR" 20
}

run_pytest() {
  (cd "$VENV" && OPENBLAS_NUM_THREADS=1 CHASLES_REQUIRE_URDF_DUMP=1 \
    CHASLES_URDF_DUMP="$BUILD_DIR/tests/cpp/chasles_urdf_dump" \
    CHASLES_POSE_GRAPH_EXAMPLE="$BUILD_DIR/examples/example_pose_graph" \
    "$VENV/bin/python" -m pytest "$ROOT/tests/python" -p no:cacheprovider)
}

stage_python() {
  apt_cpp
  echo "== Python: pip wheel . (scikit-build-core, pybind11, cmeel-eigen from PyPI) with the system's"
  echo "   Eigen hidden, installed into a fresh virtual environment with no compiler reachable,"
  echo "   pytest from outside the source tree"
  rm -rf "$VENV" "$WHEEL_DIR" "$WHEEL_BUILD_DIR"
  timed "venv" python3 -m venv "$VENV"
  # A venv gets the pip its Python bundles (Debian 12: pip 23.0, which has no
  # -C, the short form of --config-settings used below, added in pip 23.1).
  timed "pip upgrade" "$VENV/bin/python" -m pip install --quiet --upgrade pip
  # The system's Eigen (installed above for the C++ tests) is hidden from the
  # wheel's CMake: CMAKE_IGNORE_PATH makes find_package skip an Eigen3Config.cmake
  # in those directories, and only there, so CMakeLists.txt falls back on the
  # cmeel-eigen build requirement as it does on a machine with no Eigen. The
  # CMake tree is kept (build-dir) so that its cache shows which Eigen was used.
  timed "wheel" "$VENV/bin/python" -m pip wheel --quiet --no-deps -w "$WHEEL_DIR" -C "build-dir=$WHEEL_BUILD_DIR" \
    -C "cmake.define.CMAKE_IGNORE_PATH=/usr/share/eigen3/cmake;/usr/lib/cmake/eigen3;/usr/include/eigen3" "$ROOT"
  EIGEN_DIR=$(sed -n 's/^Eigen3_DIR:PATH=//p' "$WHEEL_BUILD_DIR/CMakeCache.txt")
  echo "   the wheel was built with Eigen3_DIR=$EIGEN_DIR"
  case "$EIGEN_DIR" in
    */cmeel.prefix/share/eigen3/cmake) ;;
    *) echo "error: the wheel's Eigen is not cmeel-eigen's (the system's was not hidden?)" >&2; exit 1 ;;
  esac
  WHEEL=$(ls "$WHEEL_DIR"/chasles-*.whl)
  CC=/bin/false CXX=/bin/false timed "wheel install" "$VENV/bin/python" -m pip install --quiet --only-binary=chasles \
    "$WHEEL[test]"
  # CHASLES_URDF_DUMP: the C++ URDF loader's JSON dump (tests/cpp/urdf_dump.cpp,
  # built by the cpp stage, or here alone), which tests/python/test_urdf_cpp.py
  # compares with Chain.from_urdf on the arms of example-robot-data (a Python
  # package); CHASLES_REQUIRE_URDF_DUMP=1 makes that cross-check fail, not skip,
  # when anything it needs is missing.
  # CHASLES_POSE_GRAPH_EXAMPLE: the C++ pose-graph solve over Ceres
  # (examples/cpp/pose_graph.cpp), which tests/python/test_pose_graph.py runs
  # on the benchmark graphs beside the Python solve.
  if [ "$STAGE" = python ]; then
    echo "== the C++ URDF loader's dump program and the C++ pose-graph example, for the cross-checks"
    configure_cpp
    cmake --build "$BUILD_DIR" -j "$JOBS" --target chasles_urdf_dump example_pose_graph
  fi
  # One BLAS thread: the tests' small scipy/numpy products gain nothing from
  # more, and OpenBLAS threads spinning on a loaded 2-core machine made the
  # suite several times slower (116 s against 17 s for the same tests).
  timed "pytest" run_pytest
}

# `all`: the g++ build (the URDF dump that pytest needs is in it), then the
# python stage in the background, in a process group of its own (set -m) so
# that a failure of the foreground can stop all of it, with its output kept
# in a file and printed when it ends.
# in_background LOG FUNCTION: runs FUNCTION in the background, in a process
# group of its own (set -m: on_exit stops all of it), its output into LOG;
# its process group is then BG_PID.
in_background() {
  set -m
  ("$2") > "$1" 2>&1 < /dev/null &
  BG_PID=$!
  set +m
}
# finish_background NAME PID LOG: waits for it, prints its output, and stops
# the script with its status if it failed.
finish_background() {
  local status=0
  wait "$2" || status=$?
  cat "$3"
  if [ "$status" -ne 0 ]; then
    echo "error: $1 failed (exit $status); its output is above" >&2
    exit "$status"
  fi
}
# The background lane of `all`: the python stage, then the g++ build's ctest.
python_then_gxx_tests() {
  stage_python
  gxx_tests
}
stage_all() {
  apt_all
  gxx_build
  local log="$ROOT/build/python-stage.log" fuzz_log="$SANITIZE_DIR/fuzz-run.log"
  echo "== the python stage and then the g++ ctest run in the background from here on; their output"
  echo "   follows the fuzzing's"
  in_background "$log" python_then_gxx_tests
  PY_PID=$BG_PID
  sanitizer_build
  # The fuzzing (one process) beside the sanitizer's ctest, its output
  # printed after; then the python stage's.
  in_background "$fuzz_log" stage_fuzz
  FUZZ_PID=$BG_PID
  sanitizer_tests
  finish_background "the fuzzing" "$FUZZ_PID" "$fuzz_log"
  FUZZ_PID=""
  finish_background "the python stage and the g++ ctest" "$PY_PID" "$log"
  PY_PID=""
}

case "$STAGE" in
  cpp) stage_cpp ;;
  fuzz) stage_fuzz ;;
  python) stage_python ;;
  all) stage_all ;;
esac
