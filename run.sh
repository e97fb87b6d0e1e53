#!/usr/bin/env bash
# Tidewater's entry points on a Debian 12 machine with nothing installed:
#   ./run.sh demo    install missing packages, build, run the demo on the default scene
#   ./run.sh test    install missing packages, build, run the whole test suite
#   ./run.sh bench   build, then run the query benchmark (not part of the test suite)
#   ./run.sh fuzz [SECONDS]   build the fuzz targets, run each for SECONDS (default 60)
#   ./run.sh tsan    build with ThreadSanitizer, run the threaded tests (part of test)
# Each step is skipped when already done, so a second run is quick.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BUILD="${TIDEWATER_BUILD_DIR:-$ROOT/build}"
JOBS="$(nproc 2>/dev/null || echo 2)"

# Debian packages the build and tests need (DESIGN.md lists why each is here).
PACKAGES=(
  cmake ninja-build g++ pkg-config ccache git libtbb-dev
  libglm-dev nlohmann-json3-dev libfmt-dev libcli11-dev libxsimd-dev
  libgtest-dev libbenchmark-dev libstb-dev libpng-dev libgdal-dev libcgal-dev libboost-dev libceres-dev libnetcdf-dev libeigen3-dev libvtk9-dev libglfw3-dev libimgui-dev xvfb xauth
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools glslang-tools glslang-dev
  clang-format clang libclang-rt-dev
  slurmctld slurmd slurm-client munge openmpi-bin libopenmpi-dev
)

log() { printf '==> %s\n' "$*"; }

# ccache (when installed) sees paths relative to the checkout, so that another clone of the
# same sources hits the cache.
export CCACHE_BASEDIR="$ROOT" CCACHE_NOHASHDIR=1

install_packages() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing Debian packages: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

configure() {
  local dir="$1"; shift
  if [ -f "$dir/CMakeCache.txt" ] && [ -f "$dir/build.ninja" ]; then return 0; fi
  local launcher=()
  if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
  log "configuring $dir"
  cmake -S "$ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DTIDEWATER_WARNINGS_AS_ERRORS=ON "${launcher[@]}" "$@"
}

build() {
  local dir="$1"; shift
  log "building $dir"
  cmake --build "$dir" --parallel "$JOBS" "$@"
}

# The C++ sources in the one format of .clang-format (GLSL under shaders/ is not C++).
check_format() {
  log "checking the C++ format (clang-format $(clang-format --version | grep -o '[0-9][0-9.]*' | head -1))"
  (cd "$ROOT" && find runtime tools tests examples calibration \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print0 |
    xargs -0 clang-format --dry-run --Werror)
}

# The sanitizer build: Clang with ASan + UBSan, every target instrumented for libFuzzer,
# so the unit tests under the sanitizers and the fuzz targets share one build.
SANITIZE_BUILD="$BUILD-sanitize"
configure_sanitize() {
  CC=clang CXX=clang++ configure "$SANITIZE_BUILD" -DTIDEWATER_SANITIZE=ON -DTIDEWATER_FUZZ=ON \
    -DTIDEWATER_BUILD_BENCHMARKS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
}

# The ThreadSanitizer build: Clang, the core, bake and render libraries, the tests with
# threads and a command line without the calibration and the inspector; it runs the
# threaded tests (ctest -L threads), the renderer's on lavapipe.
TSAN_BUILD="$BUILD-tsan"
configure_tsan() {
  CC=clang CXX=clang++ configure "$TSAN_BUILD" -DTIDEWATER_SANITIZE=thread -DTIDEWATER_BUILD_BENCHMARKS=OFF \
    -DTIDEWATER_BUILD_RENDER=ON -DTIDEWATER_BUILD_CALIBRATION=OFF -DTIDEWATER_BUILD_INSPECTOR=OFF \
    -DTIDEWATER_BUILD_EDITOR=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
}
run_threads_under_tsan() {
  configure_tsan
  build "$TSAN_BUILD" --target tidewater_core_tests tidewater tidewater_render_thread_tests
  log "running the threaded tests under ThreadSanitizer"
  ctest --test-dir "$TSAN_BUILD" --output-on-failure --parallel "$JOBS" --timeout 1200 --no-tests=error -L threads
}

# Runs every fuzz target for $1 seconds from its seeds (tests/fuzz/corpus, examples/), in a
# corpus kept in the build folder between runs. A crash, leak, timeout, sanitizer report
# or an allocation over 512 MiB fails the step; the input is kept under fuzz/artifacts.
run_fuzzers() {
  local seconds="$1" failed=()
  local bin="$SANITIZE_BUILD/bin" work="$SANITIZE_BUILD/fuzz"
  for target in scene_json images rasters points_csv records obj_mesh bake_folder editor_script tiled_bake_files; do
    local corpus="$work/corpus/$target" artifacts="$work/artifacts/$target/"
    mkdir -p "$corpus" "$artifacts"
    local seeds=() dict=()
    [ -d "$ROOT/tests/fuzz/corpus/$target" ] && seeds+=("$ROOT/tests/fuzz/corpus/$target")
    case "$target" in
      scene_json) seeds+=("$ROOT/examples/scenes" "$ROOT/examples/presets"); dict=(-dict="$ROOT/tests/fuzz/fuzz.dict") ;;
      bake_folder) dict=(-dict="$ROOT/tests/fuzz/fuzz.dict") ;;
    esac
    log "fuzzing $target for ${seconds} s"
    if ! "$bin/fuzz_$target" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -malloc_limit_mb=512 \
        -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts" "${dict[@]}" "$corpus" "${seeds[@]}" \
        >"$work/$target.log" 2>&1; then
      tail -n 60 "$work/$target.log" >&2
      failed+=("$target")
    fi
    grep -h "stat::number_of_executed_units\|stat::peak_rss_mb" "$work/$target.log" | tr '\n' ' ' | sed 's/^/    /'
    echo
  done
  if [ ${#failed[@]} -ne 0 ]; then
    echo "fuzzing found a fault in: ${failed[*]} (inputs under $work/artifacts)" >&2
    return 1
  fi
}

cmd="${1:-}"
case "$cmd" in
  demo)
    install_packages
    configure "$BUILD"
    build "$BUILD"
    log "running the demo on the bundled default scene"
    "$BUILD/bin/tidewater" demo --out-dir "$BUILD/demo"
    ;;
  test)
    install_packages
    check_format
    configure "$BUILD"
    build "$BUILD"
    log "running the test suite"
    ctest --test-dir "$BUILD" --output-on-failure --parallel "$JOBS" --timeout 900
    # The unit tests again under AddressSanitizer + UndefinedBehaviorSanitizer, then every
    # fuzz target for a bounded time (TIDEWATER_FUZZ_SECONDS each).
    configure_sanitize
    build "$SANITIZE_BUILD" --target tidewater_core_tests tidewater_calibration_tests tidewater_fuzz_targets \
      tidewater_vulkan_fault_tests
    log "running the unit tests and the Vulkan fault tests under ASan + UBSan"
    ctest --test-dir "$SANITIZE_BUILD" --output-on-failure --parallel "$JOBS" --timeout 1500 --no-tests=error -L 'unit|vulkan_faults'
    run_fuzzers "${TIDEWATER_FUZZ_SECONDS:-30}"
    run_threads_under_tsan
    ;;
  tsan)
    install_packages
    run_threads_under_tsan
    ;;
  fuzz)
    install_packages
    configure_sanitize
    build "$SANITIZE_BUILD" --target tidewater_fuzz_targets
    run_fuzzers "${2:-60}"
    ;;
  bench)
    install_packages
    configure "$BUILD"
    build "$BUILD"
    "$BUILD/bin/tidewater" bench --out "$BUILD/bench/query_bench.json" --markdown "$BUILD/bench/query_bench.md"
    ;;
  *)
    echo "usage: ./run.sh demo|test|bench|tsan|fuzz [SECONDS]" >&2
    exit 2
    ;;
esac
