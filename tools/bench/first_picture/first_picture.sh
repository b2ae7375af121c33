#!/usr/bin/env bash
# Times the README's first command on a fresh Debian 12: a minimal system made by debootstrap,
# a clone of this repository inside it, then `bash tools/setup.sh && ./build/clrt
# scenes/reflect.ray -o build/reflect.png` timed from start to image, split into packages and
# configure, the build of clrt, and the first render (its kernels compiled from empty caches).
#
# Usage (as root, on Debian; needs the debootstrap package and Debian's mirror):
#   bash tools/bench/first_picture/first_picture.sh [--runs N] [--work DIR] [--mirror URL]
# Each run starts from a copy of one debootstrap'd base (made once in DIR, the slow part that is
# not timed), so the runs measure the same thing. What the script made in DIR is removed at the
# end unless --keep (a base kept there is reused).
set -euo pipefail

runs=3
work=/tmp/clrt-first-picture
mirror=http://deb.debian.org/debian
keep=0
while (($#)); do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --mirror) mirror=$2; shift 2 ;;
    --keep) keep=1; shift ;;
    *) echo "usage: first_picture.sh [--runs N] [--work DIR] [--mirror URL] [--keep]" >&2; exit 2 ;;
  esac
done
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "first_picture.sh: --runs takes a whole number from 1" >&2; exit 2; }
((EUID == 0)) || { echo "first_picture.sh: run as root (debootstrap and chroot)" >&2; exit 2; }
command -v debootstrap > /dev/null || { echo "first_picture.sh: apt-get install debootstrap" >&2; exit 2; }

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)
base=$work/base
root=$work/run

# Mounts inside the run's tree are undone on every exit, so a failed run leaves no mount behind.
unmount_run() {
  for m in sys dev proc; do
    mountpoint -q "$root/$m" 2> /dev/null && umount -l "$root/$m"
  done
  return 0
}
cleanup() {
  unmount_run
  if ! ((keep)); then
    rm -rf "$root" "$base" "$work/debootstrap.log"
    rmdir "$work" 2> /dev/null || true
  fi
}
trap cleanup EXIT

mkdir -p "$work"
if [[ ! -x $base/bin/bash ]]; then
  echo "first_picture: debootstrap --variant=minbase bookworm (once, not timed)" >&2
  rm -rf "$base"
  debootstrap --variant=minbase bookworm "$base" "$mirror" > "$work/debootstrap.log" 2>&1
fi

# What runs inside: the README's first command, with a clock on each line setup.sh prints, so
# the packages, the configure and the build can be told apart afterwards.
read -r -d '' inside << 'EOF' || true
set -euo pipefail
cd /root/clrt
ms() { echo $(( $(date +%s%N) / 1000000 )); }
start=$(ms)
bash tools/setup.sh 2>&1 | while IFS= read -r line; do echo "$(( $(ms) - start )) $line"; done > /root/setup.log
built=$(ms)
./build/clrt scenes/reflect.ray -o build/reflect.png -q
done=$(ms)
test -s build/reflect.png
configure=$(grep -m1 -- '-- The CXX compiler identification' /root/setup.log | cut -d' ' -f1)
echo "$configure $((built - start)) $((done - start))"
EOF

printf '%-4s %12s %12s %14s %12s\n' run "packages s" "build s" "first render s" "total s"
for ((i = 1; i <= runs; ++i)); do
  unmount_run
  rm -rf "$root"
  cp -a "$base" "$root"
  cp /etc/resolv.conf "$root/etc/resolv.conf"
  mount -t proc proc "$root/proc"
  mount --rbind /dev "$root/dev"
  mount --make-rslave "$root/dev"
  mount -t sysfs sys "$root/sys"
  git clone -q "$repo" "$root/root/clrt"
  read -r configure built total < <(chroot "$root" /bin/bash -c "$inside")
  awk -v i="$i" -v c="$configure" -v b="$built" -v t="$total" \
    'BEGIN { printf "%-4d %12.1f %12.1f %14.1f %12.1f\n", i, c / 1000, (b - c) / 1000, (t - b) / 1000, t / 1000 }'
done
