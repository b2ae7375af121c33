#!/usr/bin/env bash
# install_mitsuba.sh BUILD_DIR: what the race against Mitsuba 3 needs (race.py --peer
# mitsuba-llvm or mitsuba-scalar): Mitsuba itself in BUILD_DIR/mitsuba-venv (tools/mitsuba/install.sh,
# the venv the test suite's Mitsuba comparison uses), and for the LLVM variant an LLVM of version 16
# or newer, Debian 12's `libllvm19` (Dr.Jit aborts with Debian's default LLVM 14 and 15). A
# benchmark dependency only: clrt never links either. What is already there is left as it is.
set -euo pipefail
if [[ $# -ne 1 ]]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
bash "$here/../../mitsuba/install.sh" "$1"
if ! compgen -G '/usr/lib/*/libLLVM-1[6-9].so' >/dev/null && ! compgen -G '/usr/lib/*/libLLVM-[2-9][0-9].so' >/dev/null; then
  if [[ $(id -u) -ne 0 ]]; then
    echo "mitsuba: error: Mitsuba's LLVM variant needs libllvm19; as root: apt-get install libllvm19" >&2
    exit 1
  fi
  echo "mitsuba: installing libllvm19 (Debian) for Mitsuba's LLVM variant"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q libllvm19 >/dev/null
fi
echo "mitsuba: $1/mitsuba-venv has Mitsuba $("$1/mitsuba-venv/bin/python" -c 'import mitsuba; print(mitsuba.__version__)'); LLVM: $(ls /usr/lib/*/libLLVM-*.so | tail -1)"
