# install_test_devices BUILD_DIR: the OpenCL implementations clrt's tests run on besides PoCL,
# installed for the tests alone, never system-wide and never as the default device:
#   - Oclgrind (Debian's oclgrind): an OpenCL interpreter that reports out-of-bounds accesses,
#     data races and API misuse inside kernels;
#   - Intel's CPU runtime (PyPI intel-opencl-rt, into BUILD_DIR/opencl/intel-venv): another
#     compiler, which vectorises work-groups as GPU drivers do;
#   - and Mitsuba 3 (PyPI mitsuba, into BUILD_DIR/mitsuba-venv), the independent renderer that
#     path mode is checked against (tools/mitsuba/).
# Each gets a folder BUILD_DIR/opencl/vendors/NAME holding its ICD file and PoCL's, which the
# tests name in OCL_ICD_VENDORS (tests/support/on_implementation.sh). One that cannot be installed (no network
# for PyPI, say) is left out with a warning, and its tests report themselves skipped.
# Sourced by tools/setup.sh --tests.
install_test_devices() {
  local build=$1 vendors=$1/opencl/vendors pocl_icd=/etc/OpenCL/vendors/pocl.icd
  install_missing oclgrind python3-venv || echo "setup: warning: Oclgrind not installed" >&2
  rm -rf "$vendors" && mkdir -p "$vendors"
  if [[ -f /usr/lib/oclgrind/liboclgrind-rt-icd.so ]]; then
    mkdir -p "$vendors/oclgrind"
    echo /usr/lib/oclgrind/liboclgrind-rt-icd.so >"$vendors/oclgrind/oclgrind.icd"
    cp "$pocl_icd" "$vendors/oclgrind/"
  fi
  local venv=$build/opencl/intel-venv
  if [[ ! -f $venv/lib/libintelocl.so ]]; then
    echo "setup: installing Intel's CPU OpenCL runtime (PyPI intel-opencl-rt) into $venv"
    rm -rf "$venv"
    if ! { python3 -m venv "$venv" &&
           "$venv/bin/pip" install -q --disable-pip-version-check intel-opencl-rt intel-cmplr-lib-rt; }; then
      echo "setup: warning: Intel's CPU OpenCL runtime not installed; its tests will be skipped" >&2
      rm -rf "$venv"
    fi
  fi
  if [[ -f $venv/lib/libintelocl.so ]]; then
    mkdir -p "$vendors/intel"
    echo "$(cd "$venv/lib" && pwd)/libintelocl.so" >"$vendors/intel/intel.icd"
    cp "$pocl_icd" "$vendors/intel/"
  fi
  bash tools/mitsuba/install.sh "$build" ||
    echo "setup: warning: Mitsuba 3 not installed; path_matches_mitsuba will be skipped" >&2
}
