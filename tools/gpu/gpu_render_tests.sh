#!/usr/bin/env bash
# The render tests on a machine with a real GPU, under the Khronos validation layer carried
# in the bundle (tools/gpu/make_bundle.sh BUILD BUNDLE --tests):
#   tools/gpu/gpu_render_tests.sh BUNDLE_DIR OUT_DIR SECONDS [GTEST_FILTER]
# The tests read examples/ and shaders/ from the path they were built in: run from a
# checkout at that path (or a link to it). Writes OUT_DIR/gpu_render_tests.log.
set -uo pipefail
B="$(cd "$1" && pwd)"; OUT="$2"; SECONDS_LIMIT="$3"; FILTER="${4:-*}"; mkdir -p "$OUT"
export LD_LIBRARY_PATH="$B/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" VK_LAYER_PATH="$B/layer"
for icd in /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json /usr/share/vulkan/icd.d/nvidia_icd.json \
           /etc/vulkan/icd.d/nvidia_icd.json; do
  if [ -f "$icd" ]; then export VK_DRIVER_FILES="$icd" VK_ICD_FILENAMES="$icd"; break; fi
done
LOG="$OUT/gpu_render_tests.log"
echo "icd: ${VK_DRIVER_FILES:-none found}; layer: $(grep -o '"api_version"[^,]*' "$B/layer/"*.json)" >"$LOG"
timeout "$SECONDS_LIMIT" "$B/bin/tidewater_render_tests" --gtest_filter="$FILTER" >>"$LOG" 2>&1
echo "rc=$?" >>"$LOG"
exit 0
