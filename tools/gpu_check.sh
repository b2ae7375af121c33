#!/usr/bin/env bash
# The GPU check a maintainer runs on a machine with an OpenCL GPU (about ten minutes):
#   1. builds clrt (tools/setup.sh) and lists the OpenCL devices;
#   2. runs the device tests on the GPU (CLRT_TEST_DEVICE): the kernel unit tests, the driver-fault
#      reproducer and the same-bytes renders, as CTest runs them on Intel's runtime and Oclgrind;
#   3. renders every scene of scenes/ (and ../shared/scenes/spd-ray/ when present) on the GPU
#      and on PoCL and compares the images: identical bytes, or clrt-img diff's PSNR;
#   4. measures primary-ray throughput through the intersect kernel alone (clrt-bench bvh);
#   5. runs clrt-experiment on both devices, both integrators.
# Everything lands in gpu-check/ (summary.md first). The GPU's vendor ICD must be installed
# (e.g. Debian's nvidia-opencl-icd); CLRT_GPU picks the device (default `gpu`).
# Usage: bash tools/gpu_check.sh            exit 0 when every step ran, 1 otherwise
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

gpu=${CLRT_GPU:-gpu}
cpu=${CLRT_CPU:-cpu}
out=gpu-check
rm -rf "$out" && mkdir -p "$out/images"
summary="$out/summary.md"
failures=0
note() { echo "$*" | tee -a "$summary"; }
step() { note ""; note "## $*"; }
fail() { note "FAILED: $*"; failures=$((failures + 1)); }

step "Build"
bash tools/setup.sh >"$out/build.log" 2>&1 || { fail "build (see $out/build.log)"; exit 1; }
./build/clrt --version | tee -a "$summary"

step "Devices"
./build/clrt --list-devices | tee -a "$summary"
./build/clrt --list-devices | grep -q . || fail "no OpenCL device"

step "Device tests on $gpu"
# The programs CTest also runs on Intel's runtime and Oclgrind (build/device-tests.txt, written by
# tests/CMakeLists.txt): kernel unit tests, the driver-fault reproducer, the same-bytes renders.
while read -r t; do
  [[ -x $t ]] || { fail "$t missing"; continue; }
  if CLRT_TEST_DEVICE=$gpu "$t" >"$out/$(basename "$t").log" 2>&1; then
    note "- $(basename "$t"): passed"
  else
    fail "$(basename "$t") (see $out/$(basename "$t").log)"
  fi
done <build/device-tests.txt
grep -h "float3 arguments" "$out"/test_vector_calls.log | tee -a "$summary"

step "Every scene on $gpu and on $cpu"
note "| scene | $gpu s | $cpu s | images |"
note "|---|---:|---:|---|"
scenes=(scenes/*.ray scenes/*/*.ray)
[[ -d ../shared/scenes/spd-ray ]] && scenes+=(../shared/scenes/spd-ray/*.ray)
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .ray)
  times=()
  for dev in "$gpu" "$cpu"; do
    start=$(date +%s%N)
    if ! ./build/clrt -q "$scene" --device "$dev" -o "$out/images/$name-$dev.pfm" \
        2>>"$out/render.log"; then
      fail "$scene on $dev (see $out/render.log)"
      continue 2
    fi
    times+=("$(awk -v a="$start" -v b="$(date +%s%N)" 'BEGIN { printf "%.2f", (b - a) / 1e9 }')")
  done
  if cmp -s "$out/images/$name-$gpu.pfm" "$out/images/$name-$cpu.pfm"; then
    verdict="identical"
  else
    verdict=$(./build/tools/img/clrt-img diff "$out/images/$name-$gpu.pfm" \
              "$out/images/$name-$cpu.pfm" 2>&1 | tr '\n' ' ')
  fi
  note "| $name | ${times[0]} | ${times[1]} | $verdict |"
done

step "Primary rays through the intersect kernel alone on $gpu"
./build/tools/bench/scene/clrt-bench bvh --device "$gpu" --rays 4000000 \
  scenes/reflect.ray scenes/mesh.ray scenes/large/spheres-100k.ray 2>&1 | tee -a "$summary" ||
  fail "clrt-bench bvh"

step "clrt-experiment on $gpu and $cpu"
# The runner exits 1 when an image differs from its scene's first, which devices with different
# math libraries may do in the last bits: that is reported in its table, not counted as a failure.
./build/tools/experiment/clrt-experiment scenes/reflect.ray scenes/refraction.ray \
  scenes/mesh.ray scenes/large/spheres-100k.ray --device "$gpu" --device "$cpu" \
  --integrator wavefront,megakernel --repeats 2 --resolution 1920x1080 \
  --out "$out/experiment" >>"$summary" 2>"$out/experiment.log"
if [[ -f $out/experiment/results.json ]]; then
  note "(plots in $out/experiment/)"
else
  fail "clrt-experiment (see $out/experiment.log)"
fi

note ""
note "$failures step(s) failed"
[[ $failures -eq 0 ]]
