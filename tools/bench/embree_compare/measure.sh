#!/bin/sh
# Re-runs the measurement of docs/races.md: the SPD scenes, then the large scenes of
# clrt-make-scenes (written first if missing). Extra arguments go to clrt-embree-compare,
# e.g. --robust or --runs 9. Run from the repository's root.
#   tools/bench/embree_compare/measure.sh BUILD_DIR [OPTIONS...]
set -eu
build=$1
shift
spd=${SPD_DIR:-../shared/scenes/spd-ray}
large=${LARGE_DIR:-build/scenes-large}
[ -f "$large/inst-100k.ray" ] || "$build/tools/make_scenes/clrt-make-scenes" "$large" >/dev/null
exec "$build/tools/bench/embree_compare/clrt-embree-compare" \
  "$spd/teapot-12.ray" "$spd/gears-4.ray" "$spd/balls-4.ray" "$spd/tetra-6.ray" \
  "$spd/mount-6.ray" "$spd/sombrero-3.ray" "$spd/shells-5.ray" "$spd/nurbtst-1.ray" \
  "$spd/rings-7.ray" "$spd/tree-11.ray" "$spd/lattice-12.ray" "$spd/jacks-1.ray" \
  "$large/spheres-100k.ray" "$large/mesh-1m-x100.ray" \
  "$large/tri-1k.ray" "$large/tri-10k.ray" "$large/tri-100k.ray" "$large/tri-1m.ray" \
  "$large/inst-10.ray" "$large/inst-100.ray" "$large/inst-1k.ray" "$large/inst-10k.ray" \
  "$large/inst-100k.ray" "$@"
