#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz (Clang 15, ASan + UBSan) in build-fuzz/ and runs each
# for SECONDS, one after the other, from its checked-in seeds plus the corpus of earlier runs.
# Usage: bash tools/fuzz.sh SECONDS [TARGET...]     (default: every target)
# With FUZZ_KEEP_GOING=1 a target goes on after a finding (libFuzzer's fork mode), to look past
# one that is known and not fixed yet.
# Per target, build-fuzz/fuzz/TARGET/ keeps the growing corpus (corpus/), the log (log.txt) and
# any crashing input (crash-*, leak-*, oom-*, timeout-*). Prints one line per target with its
# executions and findings; exits 1 when any target found something.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

if [[ $# -lt 1 || ! $1 =~ ^[0-9]+$ ]]; then
  echo "usage: bash tools/fuzz.sh SECONDS [TARGET...]" >&2
  exit 2
fi
seconds=$1
shift

source tools/lib/install_missing.sh
# Debian 12's clang-15 takes libFuzzer's runtime (libclang_rt.fuzzer) and the sanitizers' from
# libclang-common-15-dev; the normal build needs neither.
install_missing clang-15 libclang-common-15-dev

if [[ ! -f build-fuzz/CMakeCache.txt ]]; then
  CC=clang-15 CXX=clang++-15 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCLRT_FUZZ=ON -DCLRT_BUILD_TESTS=OFF
else
  cmake build-fuzz >/dev/null  # picks up targets added since
fi
targets=("$@")
((${#targets[@]})) || mapfile -t targets < build-fuzz/fuzz_targets.txt
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"

# Scenes and meshes are text of a few KiB; images are kept small so that runs stay fast.
max_len() { case $1 in fuzz_image_*) echo 16384 ;; *) echo 8192 ;; esac; }

# Findings are the crash-*, leak-*, oom-* and timeout-* inputs libFuzzer writes into a folder.
count_findings() {
  find "$1" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'oom-*' -o -name 'timeout-*' \) | wc -l
}

found=0
for target in "${targets[@]}"; do
  work=build-fuzz/fuzz/$target
  mkdir -p "$work/corpus"
  earlier=$(count_findings "$work")
  dict=tests/fuzz/dictionaries/$target.dict
  # Path-mode renders read the same scenes as the reader's own target.
  [[ $target == fuzz_path_render ]] && dict=tests/fuzz/dictionaries/fuzz_ray_scene.dict
  # Leaks are reported too: the harnesses but one load no OpenCL, so none is PoCL's or LLVM's.
  # fuzz_path_render renders on PoCL, whose compiler keeps what it allocates until exit, and
  # takes longer per input.
  extra=()
  [[ $target == fuzz_path_render ]] && extra=(-detect_leaks=0)
  # The harness writes each input under $TMPDIR; a crashed run cannot remove it, so keep it here.
  mkdir -p "$work/tmp"
  status=0
  keep_going=()
  [[ ${FUZZ_KEEP_GOING:-0} == 1 ]] && keep_going=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  TMPDIR=$work/tmp "build-fuzz/tests/fuzz/$target" "${keep_going[@]}" "${extra[@]}" "$work/corpus" "tests/fuzz/seeds/$target" \
    -dict="$dict" -max_total_time="$seconds" -max_len="$(max_len "$target")" \
    -rss_limit_mb=2048 -malloc_limit_mb=1024 -timeout=20 -print_final_stats=1 \
    -artifact_prefix="$work/" >"$work/log.txt" 2>&1 || status=$?
  # Fork mode prints no final statistics: its last progress line counts the runs.
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log.txt" | tail -1)
  [[ -n $runs ]] || runs=$(sed -n 's/^#\([0-9]*\):.*/\1/p' "$work/log.txt" | tail -1)
  findings=$(($(count_findings "$work") - earlier))
  echo "$target: ${runs:-?} executions in ${seconds} s, corpus $(ls "$work/corpus" | wc -l) inputs, findings $findings (exit $status)"
  if ((status != 0 || findings != 0)); then found=1; fi
done
exit $found
