#!/usr/bin/env bash
# The same pictures on every platform (docs/accuracy.md, "What the code does,
# and why"): the course built and tested in fresh Debian trees, cross-built
# for arm64 and run under qemu-user, built with clang beside gcc. Each
# platform renders every step's reference scene with the image test's options
# (tools/figures/images.sh) and steps 07 and 08 with every sampler, and each
# render is compared with images/ at the image test's tolerance and with this
# machine's gcc render, float for float: a float that differs fails.
#
# Usage (root, on Debian or Ubuntu, the Debian mirror reachable; host alone
# needs neither, and is make check-compilers):
#   tools/build/platforms.sh [PLATFORM...]    (make platforms; default: all four)
#     host      this machine: clang (BUILD/clang), gcc without OpenMP
#               (BUILD/no-openmp) and gcc -march=native (BUILD/native)
#               beside the default gcc build
#     bookworm  Debian 12 from debootstrap: the README's make, then
#               make test-step 1 .. 8 (FULL=1: make test)
#     trixie    Debian 13 from debootstrap: the same
#     arm64     in the Debian 13 tree: the steps cross-built with
#               aarch64-linux-gnu-gcc and run under qemu-aarch64 (Criterion's
#               forked tests do not run under qemu-user; the renders do)
#   tools/build/platforms.sh renders BUILD OUT [RUNNER...]   the renders alone
# Environment: BUILD (default build), PLATFORMS_ROOT (the Debian trees, kept
# between runs; default /var/tmp/rt-platforms), MIRROR (default: the first
# deb.debian.org-style URI of this host's apt sources), FULL=1,
# PLATFORMS_RESULTS (default BUILD/platforms).
# The trees get a fresh clone of HEAD (what a student has: git and .git):
# commit what you want tried.
# Writes PLATFORMS_RESULTS: PLATFORM.log (every command's output),
# PLATFORM/*.pfm (the renders) and summary.txt (one line per check, also
# printed). Exit 1 when a check fails.
set -uo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
cd "$top" || exit 2
BUILD=${BUILD:-build}
STEPS=$(cd steps && ls -d [0-9][0-9]-* 2>/dev/null)

# The reference image's size and Phong terms: the step's manifest.
size() { local wh; wh=$(tools/build/manifest.sh get "$1" IMAGE_SIZE); echo "--width ${wh% *} --height ${wh#* }"; }
terms() { tools/build/manifest.sh get "$1" IMAGE_TERMS; }

# renders BUILD OUT [RUNNER...]: every step's reference render (and its Phong
# terms) as OUT/NAME.pfm; steps 07 and 08 at 160x120 with each sampler
# (OUT/sampler-STEP-NAME.pfm: the samplers draw their points, and step 08 its
# light samples, from integer hashes that no compiler may reorder); and step
# 04's canonical scene lit by its directional light alone, along
# (0, -1, -0.5) and along the same times 1e-8 (OUT/light-unit.pfm,
# OUT/light-1e-8.pfm).
renders() {
  local b=$1 out=$2 s term args d tag
  shift 2
  mkdir -p "$out"
  for s in $STEPS; do
    args=$(tools/build/manifest.sh get "$s" IMAGE_ARGS)
    for term in "" $(terms "$s"); do
      # shellcheck disable=SC2046,SC2086  # options and their values, split on spaces
      "$@" "$b/bin/$s" $(size "$s") --threads 2 --quiet $args ${term:+--aov $term} \
        -o "$out/$s${term:+.$term}.pfm" 2>>"$out/stderr" || { echo "renders: $s failed"; return 1; }
    done
  done
  for s in $STEPS; do
    case $(tools/build/manifest.sh get "$s" FEATURES) in *SCENE_SAMPLES*) ;; *) continue ;; esac
    for term in center grid random jitter sobol; do
      "$@" "$b/bin/$s" --width 160 --height 120 --samples 4 --sampler "$term" --threads 2 --quiet \
        -o "$out/sampler-$s-$term.pfm" 2>>"$out/stderr" || { echo "renders: $s --sampler $term failed"; return 1; }
    done
  done
  [ -x "$b/bin/04-phong" ] || return 0
  for d in "unit:0 -1 -0.5" "1e-8:0 -1e-8 -0.5e-8"; do
    tag=${d%%:*}
    sed -e '/^light point/d' -e "s/^light directional direction .* irradiance/light directional direction ${d#*:} irradiance/" \
      scenes/spheres.scene > "$out/light-$tag.scene"
    "$@" "$b/bin/04-phong" --scene "$out/light-$tag.scene" --width 320 --height 240 --threads 2 \
      --quiet -o "$out/light-$tag.pfm" 2>>"$out/stderr" || { echo "renders: light-$tag failed"; return 1; }
  done
}

if [ "${1:-}" = renders ]; then
  shift
  renders "$@"
  exit
fi

for platform in "$@"; do
  [ "$platform" = host ] || [ "$(id -u)" = 0 ] ||
    { echo "platforms: $platform: run as root (debootstrap, chroot, apt-get); host alone needs no root"; exit 2; }
done
RESULTS=${PLATFORMS_RESULTS:-$BUILD/platforms}
ROOT=${PLATFORMS_ROOT:-/var/tmp/rt-platforms}
MIRROR=${MIRROR:-$(grep -rhoE 'https?://deb\.debian\.org/debian/?' /etc/apt/sources.list /etc/apt/sources.list.d 2>/dev/null | head -n 1)}
MIRROR=${MIRROR:-http://deb.debian.org/debian}
mkdir -p "$RESULTS"
: > "$RESULTS/summary.txt"
failed=0

say() { echo "$*" | tee -a "$RESULTS/summary.txt"; }
# verdict RC LINE: a comparison's line, in the summary; printed too when it
# failed (RC not 0). Counts them.
compared=0 differed=0
verdict() {
  compared=$((compared + 1))
  if [ "$1" = 0 ]; then
    echo "$2" >> "$RESULTS/summary.txt"
  else
    differed=$((differed + 1)) failed=1
    say "$2"
  fi
}
# check NAME CMD...: run CMD, its output in the platform's log; one summary line.
check() {
  local name=$1 t0=$SECONDS
  shift
  if "$@" >>"$log" 2>&1; then
    say "$platform: $name: ok ($((SECONDS - t0)) s)"
  else
    say "$platform: $name: FAILED ($((SECONDS - t0)) s; see $log)"
    failed=1
    return 1
  fi
}

# compare DIR: each render of DIR against images/ (the image test's tolerance)
# and against this machine's gcc render; the light of length 1e-8 against its
# unit twin (no float may differ).
compare() {
  local dir=$1 f name step tol frac max line ref=$RESULTS/host-gcc
  for f in "$dir"/*.pfm; do
    name=$(basename "$f" .pfm)
    case $name in light-*) continue ;; esac
    if [ "${name#sampler-}" = "$name" ]; then
      step=${name%%.*}
      read -r tol frac max < <(tools/build/manifest.sh get "$step" IMAGE_TOL)
      line=$("$BUILD/bin/pfmdiff" "$f" "images/$name.png" "$tol" "$frac" "${max:-16}")
      verdict $? "$platform: $name against images/: $line"
    fi
    if [ "$dir" != "$ref" ] && [ -f "$ref/$name.pfm" ]; then
      line=$("$BUILD/bin/pfmdiff" "$f" "$ref/$name.pfm" 0 0 0)
      verdict $? "$platform: $name against this machine's gcc render: $line"
    fi
  done
  if [ -f "$dir/light-unit.pfm" ]; then
    line=$("$BUILD/bin/pfmdiff" "$dir/light-1e-8.pfm" "$dir/light-unit.pfm" 0 0 0)
    verdict $? "$platform: directional light (0, -1e-8, -0.5e-8) against (0, -1, -0.5): $line"
  fi
}

# The Debian tree SUITE, made with debootstrap the first time, with /proc,
# /sys and /dev mounted and a fresh clone of HEAD in /root/rt.
tree=
tree_open() {
  tree=$ROOT/$1
  if [ ! -x "$tree/bin/bash" ]; then
    command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap >>"$log" 2>&1
    check "debootstrap --variant=minbase $1" debootstrap --variant=minbase "$1" "$tree" "$MIRROR" || return 1
  fi
  cp /etc/resolv.conf "$tree/etc/resolv.conf"
  mountpoint -q "$tree/proc" || mount -t proc proc "$tree/proc"
  mountpoint -q "$tree/sys" || mount -t sysfs sysfs "$tree/sys"
  mountpoint -q "$tree/dev" || { mount --rbind /dev "$tree/dev" && mount --make-rslave "$tree/dev"; }
  rm -rf "$tree/root/rt"
  mkdir -p "$tree/root/rt"
  git clone -q --no-checkout "$top" "$tree/root/rt" &&
    git -C "$tree/root/rt" checkout -q "$(git rev-parse HEAD)"
}
tree_close() {
  [ -n "$tree" ] || return 0
  # Lazily when busy (a process the tests left, e.g. bubblewrap's, just ending).
  umount -R "$tree/dev" 2>/dev/null || umount -R -l "$tree/dev"
  umount "$tree/sys" "$tree/proc" 2>/dev/null || umount -l "$tree/sys" "$tree/proc"
  tree=
}
trap tree_close EXIT
# in_tree CMD: CMD (bash) as root in the tree's /root/rt, a clean environment.
in_tree() {
  chroot "$tree" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    LANG=C.UTF-8 TERM=dumb DEBIAN_FRONTEND=noninteractive bash -c "cd /root/rt && $1"
}

debian() { # SUITE: the README's two commands (make installs the packages)
  tree_open "$1" || return
  check "apt-get install make git" in_tree "apt-get update -qq && apt-get install -y -qq make git" || return
  check "make" in_tree "make" || return
  say "$platform: $(in_tree "gcc --version | head -n 1; dpkg-query -W libcglm-dev" | tr '\n\t' '; ')"
  if [ -n "${FULL:-}" ]; then
    check "make test" in_tree "make test"
  else
    for n in 1 2 3 4 5 6 7 8; do
      check "make test-step $n" in_tree "make test-step $n"
    done
  fi
  check "renders" in_tree "tools/build/platforms.sh renders build build/platform-renders" || return
  rm -rf "${RESULTS:?}/$platform"
  cp -r "$tree/root/rt/build/platform-renders" "$RESULTS/$platform"
  compare "$RESULTS/$platform"
}

arm64() {
  tree_open trixie || return
  # make's dependency check asks the compiler it builds with for every
  # library, Criterion and MPFR included.
  local pkgs="make gcc-aarch64-linux-gnu qemu-user pkg-config libc6-dev:arm64 libcglm-dev:arm64"
  pkgs+=" libstb-dev:arm64 libpng-dev:arm64 zlib1g-dev:arm64 libgomp1:arm64"
  pkgs+=" libcriterion-dev:arm64 libmpfr-dev:arm64"
  check "the arm64 cross tools and libraries" in_tree "dpkg --add-architecture arm64 &&
    apt-get update -qq && apt-get install -y -qq --no-install-recommends $pkgs" || return
  check "make build, cross-compiled" in_tree "PKG_CONFIG_LIBDIR=/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig \
    make BUILD=build/arm64 CC=aarch64-linux-gnu-gcc AR=aarch64-linux-gnu-ar ${ARM64_MAKE_ARGS:-} build &&
    aarch64-linux-gnu-readelf -h build/arm64/bin/04-phong | grep Machine" || return
  check "renders under qemu-aarch64" in_tree "tools/build/platforms.sh renders build/arm64 build/platform-renders-arm64 qemu-aarch64" || return
  rm -rf "${RESULTS:?}/$platform"
  cp -r "$tree/root/rt/build/platform-renders-arm64" "$RESULTS/$platform"
  compare "$RESULTS/$platform"
}

host() {
  platform=host-gcc compare "$RESULTS/host-gcc"
  command -v clang >/dev/null || { say "$platform: no clang on this machine"; return; }
  # shellcheck disable=SC2086  # CLANG_MAKE_ARGS: make arguments, split on spaces
  check "make CC=clang" make --no-print-directory BUILD="$BUILD/clang" CC=clang ${CLANG_MAKE_ARGS:-} build || return
  check "renders (clang)" renders "$BUILD/clang" "$RESULTS/host-clang" || return
  platform=host-clang compare "$RESULTS/host-clang"
  check "make OPENMP=0" make --no-print-directory BUILD="$BUILD/no-openmp" OPENMP=0 build || return
  check "renders (gcc, no OpenMP)" renders "$BUILD/no-openmp" "$RESULTS/host-no-openmp" || return
  platform=host-no-openmp compare "$RESULTS/host-no-openmp"
  check "make NATIVE=1" make --no-print-directory BUILD="$BUILD/native" NATIVE=1 build || return
  check "renders (gcc -march=native)" renders "$BUILD/native" "$RESULTS/host-native" || return
  platform=host-native compare "$RESULTS/host-native"
}

[ $# -gt 0 ] || set -- host bookworm trixie arm64
# This machine's gcc renders: what every other platform's are compared with.
make --no-print-directory build "$BUILD/bin/pfmdiff" >/dev/null || exit 2
renders "$BUILD" "$RESULTS/host-gcc" || exit 2
for platform in "$@"; do
  log=$RESULTS/$platform.log
  : > "$log"
  case $platform in
    host) host ;;
    bookworm | trixie) debian "$platform" ;;
    arm64) arm64 ;;
    *) say "platforms: no platform '$platform' (host, bookworm, trixie, arm64)"; failed=1 ;;
  esac
  tree_close
done
say "platforms: $compared renders compared, $differed differ (every line: $RESULTS/summary.txt)"
exit $failed
