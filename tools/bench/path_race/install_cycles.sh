#!/usr/bin/env bash
# install.sh BUILD_DIR: Blender's Cycles as a Python module (PyPI `bpy` 4.5.x, with numpy) in
# BUILD_DIR/cycles-venv, for the race of clrt's path tracer against Cycles (race.py). A benchmark
# dependency only: a private venv, never linked into clrt and never installed system-wide.
# bpy 4.5 needs Python 3.11 (Debian 12's python3); the 5.x wheels need a newer one. A venv that
# already imports bpy 4.5 and numpy is left as it is, so a second run costs nothing.
set -euo pipefail
if [[ $# -ne 1 ]]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
venv=$1/cycles-venv
check='import bpy, numpy, sys; sys.exit(0 if bpy.app.version[:2] == (4, 5) else 1)'
if [[ -x $venv/bin/python ]] && "$venv/bin/python" -c "$check" >/dev/null 2>&1; then
  echo "cycles: $venv already has bpy $("$venv/bin/python" -c 'import bpy; print(bpy.app.version_string)' 2>/dev/null) and numpy; nothing to do"
  exit 0
fi
python=${PYTHON:-python3}
if ! "$python" -c 'import sys; sys.exit(0 if sys.version_info[:2] == (3, 11) else 1)'; then
  echo "cycles: error: bpy 4.5 needs Python 3.11; $python is $("$python" --version 2>&1)" >&2
  exit 1
fi
echo "cycles: creating $venv ($("$python" --version 2>&1)) and installing bpy==4.5.* and numpy from PyPI"
rm -rf "$venv"
# A half-made venv would look installed to the check above, so any failure removes it.
if ! { "$python" -m venv "$venv" &&
       "$venv/bin/pip" install -q --disable-pip-version-check 'bpy==4.5.*' numpy &&
       "$venv/bin/python" -c "$check" >/dev/null 2>&1; }; then
  rm -rf "$venv"
  echo "cycles: error: could not install bpy 4.5 from PyPI (no network?); the race against Cycles will be skipped" >&2
  exit 1
fi
echo "cycles: installed $("$venv/bin/pip" list --disable-pip-version-check 2>/dev/null | grep -Ei '^(bpy|numpy) ' | tr -s ' ' | paste -sd, -) into $venv ($(du -sh "$venv" | cut -f1))"
