#!/usr/bin/env bash
# Fuzzes each libFuzzer target of tests/fuzz for a bounded time, starting
# from its seed corpus (tests/fuzz/corpus/<target>/, only read), and prints
# what it ran: executions, executions per second, corpus size, and the worst
# error each property saw. What a run adds to the corpus is kept in
# BUILD_DIR/fuzz-work/<target>/ (reused by the next run); an input that
# breaks a property is written to BUILD_DIR/fuzz-artifacts/ and the script
# fails, printing the command that replays it.
#
#   bash tests/fuzz/run.sh BUILD_DIR [SECONDS_PER_TARGET [TARGET...]]
#
# BUILD_DIR is a build configured with -DCHASLES_BUILD_FUZZ=ON (clang).
set -euo pipefail
BUILD_DIR=$(cd "$1" && pwd)
cd "$(dirname "$0")"
FUZZ_DIR=$PWD
SECONDS_PER_TARGET=${2:-20}
shift $(( $# >= 2 ? 2 : 1 ))
TARGETS=("$@")
if [ ${#TARGETS[@]} -eq 0 ]; then
  TARGETS=(fuzz_so3 fuzz_se3 fuzz_matrix fuzz_robot)
  # fuzz_urdf is built when urdfdom is (tests/fuzz/CMakeLists.txt)
  [ -x "$BUILD_DIR/tests/fuzz/fuzz_urdf" ] && TARGETS+=(fuzz_urdf)
fi

mkdir -p "$BUILD_DIR/fuzz-artifacts"
for target in "${TARGETS[@]}"; do
  binary="$BUILD_DIR/tests/fuzz/$target"
  work="$BUILD_DIR/fuzz-work/$target"
  log="$BUILD_DIR/fuzz-work/$target.log"
  mkdir -p "$work"
  echo "-- $target: ${SECONDS_PER_TARGET} s from $(ls "$FUZZ_DIR/corpus/$target" | wc -l) seeds and $(ls "$work" | wc -l) inputs of earlier runs"
  # Inputs are at most 2 + 29 doubles (fuzz_robot; 1 + 22 for the others):
  # longer ones only repeat what the targets ignore. fuzz_urdf reads URDF
  # text: its seeds are up to a few kB.
  max_len=256
  [ "$target" = fuzz_urdf ] && max_len=8192
  if ! "$binary" -max_total_time="$SECONDS_PER_TARGET" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$BUILD_DIR/fuzz-artifacts/$target-" \
      "$work" "$FUZZ_DIR/corpus/$target" > "$log" 2>&1; then
    grep -v -E '^#[0-9]+' "$log" | tail -n 40  # without libFuzzer's progress lines
    echo "$target FAILED: replay with  $binary $BUILD_DIR/fuzz-artifacts/$target-<crash file>  (log: $log)"
    exit 1
  fi
  grep -E '^#[0-9]+[[:space:]]+DONE' "$log" || true
  grep -E '^stat::(number_of_executed_units|average_exec_per_sec|new_units_added)' "$log"
  echo "corpus: $(ls "$work" | wc -l) inputs found by fuzzing (all runs) + $(ls "$FUZZ_DIR/corpus/$target" | wc -l) seeds"
  grep -E '^\[ worst \]' "$log" | sort || true  # (fuzz_urdf has no error to report)
done
