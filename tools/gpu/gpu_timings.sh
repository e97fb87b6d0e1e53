#!/usr/bin/env bash
# Per-pass GPU times (timestamp queries) of `tidewater render --stats` at 1080p and 4K,
# for each quality tier, on a machine with a real GPU, from a bundle made by
# tools/gpu/make_bundle.sh:
#   tools/gpu/gpu_timings.sh BUNDLE_DIR OUT_DIR [FRAMES] [SECONDS]
# Renders that would start after SECONDS (default 420) are skipped, so that a lease's
# limit still leaves the summary and the files written.
# Views: the default scene's camera, the horizon from 400 m, the tug scene's camera.
# Where the bundle also holds bin/tidewater_base (an earlier build), it renders the same
# views at its own defaults first, for a before/after ratio on the same GPU; where it holds
# bin/tidewater_variant (a build with one change to try), that renders the default view.
# Writes OUT_DIR/gpu_timings.log (device, driver, medians) and OUT_DIR/gpu_stats.tar.gz
# (every frame's figures), plus stills of the default view. Run from the repository root
# (the tug view reads examples/scenes/tug.json).
set -uo pipefail
B="$(cd "$1" && pwd)"; OUT="$2"; FRAMES="${3:-20}"; DEADLINE=$(( $(date +%s) + ${4:-420} )); mkdir -p "$OUT"
export LD_LIBRARY_PATH="$B/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
for icd in /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json /usr/share/vulkan/icd.d/nvidia_icd.json \
           /etc/vulkan/icd.d/nvidia_icd.json; do
  if [ -f "$icd" ]; then export VK_DRIVER_FILES="$icd" VK_ICD_FILENAMES="$icd"; break; fi
done
LOG="$OUT/gpu_timings.log"
{
  echo "icd: ${VK_DRIVER_FILES:-none found}"; cat "${VK_DRIVER_FILES:-/dev/null}" 2>/dev/null
  nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv 2>&1
  uname -r; nproc
} >"$LOG"
W=/tmp/tw_frames; mkdir -p "$W/stats"
run() {  # binary name size args...
  local bin="$1" name="$2" size="$3"; shift 3
  if [ "$(date +%s)" -ge "$DEADLINE" ]; then echo "$name $size skipped: past the deadline" >>"$LOG"; return; fi
  local t0=$(date +%s%N)
  timeout 120 "$B/bin/$bin" render --size "$size" --time 3 --frames "$FRAMES" --out-dir "$W/$name-$size" \
      --stats "$W/stats/$name-$size.json" "$@" >>"$LOG" 2>&1
  echo "$name $size rc=$? wall_ms=$(( ($(date +%s%N) - t0) / 1000000 ))" >>"$LOG"
}
views() {  # binary prefix args...
  local bin="$1" prefix="$2"; shift 2
  run "$bin" "${prefix}default" "$size" "$@"
  run "$bin" "${prefix}horizon" "$size" --camera 1800 400 -1900 --target 0 0 0 --fov 50 "$@"
  run "$bin" "${prefix}tug" "$size" --scene examples/scenes/tug.json "$@"
}
for size in 1920x1080 3840x2160; do
  [ -x "$B/bin/tidewater_base" ] && views tidewater_base before-
  for tier in low medium high ultra; do views tidewater "$tier-" --quality "$tier"; done
  [ -x "$B/bin/tidewater_variant" ] && run tidewater_variant variant-default "$size"
done
python3 - "$W/stats" >>"$LOG" 2>&1 <<'PY'
import json, sys, glob, os, statistics as st
for f in sorted(glob.glob(sys.argv[1] + "/*.json")):
    d = json.load(open(f))
    if "frames" not in d: continue
    fr = d["frames"][len(d["frames"]) // 3:]  # past pipeline warm-up
    if not fr: print(os.path.basename(f), "no frames"); continue
    med = {k: st.median(x[k] for x in fr) for k in ("sky_and_terrain_ms", "scene_copy_ms", "water_ms", "total_ms")}
    lo, hi = min(x["total_ms"] for x in fr), max(x["total_ms"] for x in fr)
    print(f'{os.path.basename(f)[:-5]:28s} {d["device"]}: opaque {med["sky_and_terrain_ms"]:.3f} copy {med["scene_copy_ms"]:.3f} '
          f'water {med["water_ms"]:.3f} total {med["total_ms"]:.3f} ms (min {lo:.3f} max {hi:.3f}, {len(fr)} frames) '
          f'patches {d["counts"]["water_patches"]} terrain_tris {d["counts"]["terrain_triangles"]}')
PY
tar czf "$OUT/gpu_stats.tar.gz" -C "$W" stats
for v in before-default high-default low-default ultra-default; do
  cp "$W/$v-1920x1080/frame_0000.png" "$OUT/${v}_1080.png" 2>/dev/null
done
exit 0
