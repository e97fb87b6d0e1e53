#!/usr/bin/env bash
# Copies build/bin/tidewater and the shared libraries it loads (all but glibc's) into
# BUNDLE_DIR/{bin,lib}, so it runs on another x86-64 Linux machine without Debian's packages.
#   tools/gpu/make_bundle.sh BUILD_DIR BUNDLE_DIR
set -euo pipefail
BUILD="$1"; B="$2"
rm -rf "$B"; mkdir -p "$B/bin" "$B/lib"
cp "$BUILD/bin/tidewater" "$B/bin/"
ldd "$BUILD/bin/tidewater" | awk '/=> \//{print $3}' | while read -r so; do
  case "$(basename "$so")" in libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|ld-linux*) continue;; esac
  cp -L "$so" "$B/lib/"
done
cp -L /usr/lib/x86_64-linux-gnu/libvulkan.so.1 "$B/lib/"
du -sh "$B"
