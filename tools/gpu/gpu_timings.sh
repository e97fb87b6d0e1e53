#!/usr/bin/env bash
# Per-pass GPU times (timestamp queries) of `tidewater render --stats` at 1080p and 4K
# on a machine with a real GPU, from a bundle made by tools/gpu/make_bundle.sh:
#   tools/gpu/gpu_timings.sh BUNDLE_DIR OUT_DIR
# Writes OUT_DIR/gpu_timings.log (device, driver, medians) and OUT_DIR/gpu_stats.tar.gz
# (every frame's figures), plus stills of the default view. Run from the repository root
# (the Hilo Bay view reads examples/scenes/hilo_bay.json).
set -uo pipefail
B="$(cd "$1" && pwd)"; OUT="$2"; mkdir -p "$OUT"
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
run() {  # name size args...
  local name="$1" size="$2"; shift 2
  local t0=$(date +%s%N)
  "$B/bin/tidewater" render --size "$size" --time 3 --frames 30 --out-dir "$W/$name-$size" \
      --stats "$W/stats/$name-$size.json" "$@" >>"$LOG" 2>&1
  echo "$name $size rc=$? wall_ms=$(( ($(date +%s%N) - t0) / 1000000 ))" >>"$LOG"
}
for size in 1920x1080 3840x2160; do
  run default "$size"
  run horizon "$size" --camera 1800 400 -1900 --target 0 0 0 --fov 50
  run grazing "$size" --camera 2500 6 0 --target 3500 -20 0 --fov 50 --sun 1 0.35 0.1
  run surf "$size" --camera 500 20 -700 --target 200 5 -450 --fov 50
  run hilo "$size" --scene examples/scenes/hilo_bay.json
done
run default_msaa4 1920x1080 --samples 4
# The driver's own statistics of each stage (where it exposes them) and the cost model's
# estimate beside the measured times (its invocations counted on this GPU).
"$B/bin/tidewater" shader-stats --json "$W/stats/shader_stats.json" >>"$LOG" 2>&1
echo "shader-stats rc=$?" >>"$LOG"
if [ -f /usr/share/vulkan/icd.d/radeon_icd.x86_64.json ]; then
  "$B/bin/tidewater" gpu-cost --json "$W/stats/gpu_cost.json" >>"$LOG" 2>&1
  echo "gpu-cost rc=$?" >>"$LOG"
fi
python3 - "$W/stats" >>"$LOG" 2>&1 <<'PY'
import json, sys, glob, os, statistics as st
for f in sorted(glob.glob(sys.argv[1] + "/*.json")):
    d = json.load(open(f))
    if "frames" not in d: continue  # shader-stats and gpu-cost outputs, kept as they are
    fr = d["frames"][10:]  # frames 10-29: past pipeline warm-up
    if not fr: print(os.path.basename(f), "no frames"); continue
    med = {k: st.median(x[k] for x in fr) for k in ("sky_and_terrain_ms", "scene_copy_ms", "water_ms", "total_ms")}
    lo, hi = min(x["total_ms"] for x in fr), max(x["total_ms"] for x in fr)
    print(f'{os.path.basename(f)[:-5]:24s} {d["device"]}: opaque {med["sky_and_terrain_ms"]:.3f} copy {med["scene_copy_ms"]:.3f} '
          f'water {med["water_ms"]:.3f} total {med["total_ms"]:.3f} ms (min {lo:.3f} max {hi:.3f}, {len(fr)} frames) '
          f'patches {d["counts"]["water_patches"]} terrain_tris {d["counts"]["terrain_triangles"]} '
          f'resident terrain {d["counts"]["terrain_bytes"] / 2**20:.1f} MiB shore {d["counts"]["shore_bytes"] / 2**20:.1f} MiB')
PY
tar czf "$OUT/gpu_stats.tar.gz" -C "$W" stats
cp "$W/default-1920x1080/frame_0000.png" "$OUT/default_1080.png" 2>/dev/null
cp "$W/default-3840x2160/frame_0000.png" "$OUT/default_4k.png" 2>/dev/null
cp "$W/hilo-1920x1080/frame_0000.png" "$OUT/hilo_1080.png" 2>/dev/null
exit 0
