#!/usr/bin/env bash
# install.sh BUILD_DIR: Mitsuba 3 (PyPI `mitsuba`, with numpy) in BUILD_DIR/mitsuba-venv, the
# independent reference that clrt's path tracer is checked against. It is a test dependency
# only: a private venv, never linked into clrt and never installed system-wide. A venv that
# already imports mitsuba is left as it is, so running this again costs nothing.
set -euo pipefail
if [[ $# -ne 1 ]]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
venv=$1/mitsuba-venv
if [[ -x $venv/bin/python ]] && "$venv/bin/python" -c 'import mitsuba, numpy' 2>/dev/null; then
  exit 0
fi
echo "mitsuba: installing Mitsuba 3 (PyPI mitsuba, numpy) into $venv"
rm -rf "$venv"
# A half-made venv would look installed to the check above, so any failure removes it.
if ! { python3 -m venv "$venv" &&
       "$venv/bin/pip" install -q --disable-pip-version-check mitsuba numpy &&
       "$venv/bin/python" -c 'import mitsuba as mi; mi.set_variant("scalar_rgb")'; }; then
  rm -rf "$venv"
  echo "mitsuba: error: could not install Mitsuba 3 from PyPI (no network?); the comparison with Mitsuba will be skipped" >&2
  exit 1
fi
