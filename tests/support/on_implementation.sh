#!/usr/bin/env bash
# Runs a test program on one OpenCL implementation besides PoCL, as CTest's NAME@IMPLEMENTATION
# entries do: OCL_ICD_VENDORS names BUILD/opencl/vendors/IMPLEMENTATION (its ICD file and
# PoCL's, made by tools/setup.sh --tests) and CLRT_TEST_DEVICE picks its device. An
# implementation that is not installed exits 77, which CTest reports as skipped. Under Oclgrind,
# every error it reports (out-of-bounds access, data race, API misuse) fails the run.
# Usage: on_implementation.sh IMPLEMENTATION BUILD PROGRAM [ARGUMENTS...]
set -uo pipefail
implementation=$1 build=$2
shift 2
vendors=$build/opencl/vendors/$implementation
if [[ ! -f $vendors/$implementation.icd ]]; then
  echo "$implementation is not installed (bash tools/setup.sh --tests installs it): skipped"
  exit 77
fi
export OCL_ICD_VENDORS=$vendors
case $implementation in
  intel) export CLRT_TEST_DEVICE="Intel(R) OpenCL" ;;
  oclgrind) export CLRT_TEST_DEVICE=Oclgrind OCLGRIND_CHECK_API=1 OCLGRIND_DATA_RACES=1 ;;
  *) echo "on_implementation.sh: unknown implementation $implementation" >&2; exit 2 ;;
esac
errors=$(mktemp)
trap 'rm -f "$errors"' EXIT
"$@" 2>"$errors"
status=$?
cat "$errors" >&2
if [[ $implementation == oclgrind ]] && grep -q -E "Invalid (read|write)|data race|divergence|Oclgrind|OCLGRIND" "$errors"; then
  echo "on_implementation.sh: Oclgrind reported errors in the kernels (above)" >&2
  ((status == 0)) && status=1
fi
exit "$status"
