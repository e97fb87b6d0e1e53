#!/usr/bin/env bash
# Copies build/bin/tidewater and the shared libraries it loads (all but glibc's) into
# BUNDLE_DIR/{bin,lib}, so it runs on another x86-64 Linux machine without Debian's packages.
# With --tests, also the render tests and the Khronos validation layer (BUNDLE_DIR/layer).
#   tools/gpu/make_bundle.sh BUILD_DIR BUNDLE_DIR [--tests]
# A build without the inspector, calibration and editor (-DTIDEWATER_BUILD_INSPECTOR=OFF
# -DTIDEWATER_BUILD_CALIBRATION=OFF -DTIDEWATER_BUILD_EDITOR=OFF) keeps the bundle small
# enough to travel (about 50 MB with xz).
set -euo pipefail
BUILD="$1"; B="$2"; TESTS="${3:-}"
rm -rf "$B"; mkdir -p "$B/bin" "$B/lib"
bins=("$BUILD/bin/tidewater")
[ "$TESTS" = "--tests" ] && bins+=("$BUILD/bin/tidewater_render_tests")
for bin in "${bins[@]}"; do
  cp "$bin" "$B/bin/"
  ldd "$bin" | awk '/=> \//{print $3}' | while read -r so; do
    case "$(basename "$so")" in libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|ld-linux*) continue;; esac
    cp -L "$so" "$B/lib/"
  done
done
cp -L /usr/lib/x86_64-linux-gnu/libvulkan.so.1 "$B/lib/"
if [ "$TESTS" = "--tests" ]; then
  mkdir -p "$B/layer"
  cp -L /usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so "$B/layer/"
  sed 's#"library_path": *"[^"]*"#"library_path": "./libVkLayer_khronos_validation.so"#' \
    /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json >"$B/layer/VkLayer_khronos_validation.json"
fi
du -sh "$B"
