#!/usr/bin/env bash
# What the course needs from the system, found with pkg-config and the
# compiler's default paths (the Makefile calls this script; so do the
# Dockerfile and the Gradescope setup).
#
#   tools/build/deps.sh check [CC]        the build's libraries and tools present? If
#                                   not: as root on Debian/Ubuntu, apt-get
#                                   installs them; elsewhere the one install
#                                   command of this system, and exit 1
#   tools/build/deps.sh install           install the build's packages (apt-get, dnf,
#                                   pacman as root; brew as the user)
#   tools/build/deps.sh debs PKG...       Debian packages of the optional targets
#                                   (bench, grading, sanitizers): installed as
#                                   root, saying which and (DEBS_FOR) what for
#                                   first, else (or with DEPS_INSTALL=0) the
#                                   apt-get command; on other systems a note
#                                   naming them
#   tools/build/deps.sh config CC [STB]   the make variables of this compiler and
#                                   system ($(BUILD)/config.mk); STB=headers
#                                   uses stb as headers even where libstb is
#   tools/build/deps.sh system            apt, dnf, brew, pacman, msys2 or unknown
#
# Bash 3.2 (macOS's /bin/bash) is enough.
set -uo pipefail

# ---------------------------------------------------------------- the system
system() {
  [ -z "${DEPS_SYSTEM:-}" ] || { echo "$DEPS_SYSTEM"; return; } # to try another's messages
  case "$(uname -s 2>/dev/null)" in
    Darwin) echo brew; return ;;
    MINGW* | MSYS* | CYGWIN*) echo msys2; return ;;
  esac
  local id="" like=""
  if [ -r /etc/os-release ]; then
    id=$(. /etc/os-release && echo "${ID:-}")
    like=$(. /etc/os-release && echo "${ID_LIKE:-}")
  fi
  case " $id $like " in
    *" debian "* | *" ubuntu "*) echo apt ;;
    *" fedora "* | *" rhel "* | *" centos "*) echo dnf ;;
    *" arch "*) echo pacman ;;
    *) if command -v apt-get >/dev/null; then echo apt
       elif command -v dnf >/dev/null; then echo dnf
       elif command -v pacman >/dev/null; then echo pacman
       elif command -v brew >/dev/null; then echo brew
       else echo unknown; fi ;;
  esac
}

# The package of each thing the build needs, on each system. Things: cc make
# pkg-config cglm libpng zlib stb criterion mpfr libomp.
package() { # SYSTEM THING
  case "$1:$2" in
    apt:cc) echo gcc libc6-dev ;;
    apt:pkg-config) echo pkg-config ;;
    apt:cglm) echo libcglm-dev ;;
    apt:libpng) echo libpng-dev ;;
    apt:zlib) echo zlib1g-dev ;;
    apt:stb) echo libstb-dev ;;
    apt:criterion) echo libcriterion-dev ;;
    apt:mpfr) echo libmpfr-dev ;;
    apt:libomp) ;; # gcc's libgomp comes with gcc
    dnf:cc) echo gcc ;;
    dnf:pkg-config) echo pkgconf-pkg-config ;;
    dnf:cglm | dnf:libpng | dnf:zlib | dnf:criterion | dnf:mpfr) echo "$2-devel" ;;
    dnf:stb) echo stb_image-devel stb_image_write-devel ;;
    dnf:libomp) ;;
    brew:cc) ;; # Apple's clang: xcode-select --install
    brew:pkg-config) echo pkgconf ;;
    brew:stb) ;; # no Homebrew formula: see need_stb below
    brew:*) echo "$2" ;;
    pacman:pkg-config) echo pkgconf ;;
    pacman:cc) echo gcc ;;
    pacman:libomp) ;;
    pacman:*) echo "$2" ;;
    msys2:*)
      local p=${MINGW_PACKAGE_PREFIX:-mingw-w64-ucrt-x86_64}
      case "$2" in
        make) echo make ;;
        pkg-config) echo "$p-pkgconf" ;;
        cc) echo "$p-gcc" ;;
        libomp) ;;
        *) echo "$p-$2" ;;
      esac ;;
    *) echo "$2" ;;
  esac
}

install_command() { # SYSTEM PACKAGE...
  local sys=$1; shift
  case "$sys" in
    apt) echo "sudo apt-get update && sudo apt-get install -y $*" ;;
    dnf) echo "sudo dnf install -y $*" ;;
    brew) echo "brew install $*" ;;
    pacman) echo "sudo pacman -S --needed $*" ;;
    msys2) echo "pacman -S --needed $*" ;;
    *) echo "install with your package manager: $*" ;;
  esac
}

# ---------------------------------------------------------------- probes
tmp=""
cleanup() { [ -z "$tmp" ] || rm -rf "$tmp"; }
trap cleanup EXIT
scratch() { [ -n "$tmp" ] || tmp=$(mktemp -d "${TMPDIR:-/tmp}/deps.XXXXXX"); }

# try CC SOURCE FLAGS...: does SOURCE compile and link with FLAGS, warnings
# made errors (so that a flag the compiler only warns about counts as absent)?
try() {
  local cc=$1 src=$2; shift 2
  scratch
  printf '%s\n' "$src" > "$tmp/t.c"
  # shellcheck disable=SC2086
  $cc -Werror "$tmp/t.c" "$@" -o "$tmp/t" >/dev/null 2>&1
}

pc() { command -v pkg-config >/dev/null && pkg-config "$@" 2>/dev/null; }

MAIN='int main(void) { return 0; }'
OMP_SRC='#include <omp.h>
int main(void) { return omp_get_max_threads() > 0 ? 0 : 1; }'
MPFR_SRC='#include <mpfr.h>
int main(void) { mpfr_t x; mpfr_init2(x, 64); mpfr_clear(x); return 0; }'
Z_SRC='#include <zlib.h>
int main(void) { return zlibVersion() ? 0 : 1; }'
STB_SRC='#include <stb_image.h>
#include <stb_image_write.h>
int main(void) { return stbi_failure_reason() ? 1 : 0; }'
STB_HDR='#include <stb_image.h>
#include <stb_image_write.h>
int main(void) { return 0; }'

# Where header-only stb may lie, besides the compiler's default paths.
stb_dirs() {
  local p
  for p in /usr/include /usr/local/include /opt/homebrew/include /opt/local/include \
           ${MINGW_PREFIX:+$MINGW_PREFIX/include}; do
    echo "$p/stb"
  done
}

# stb_flags CC [headers]: "CFLAGS|LIBS|IMPL" of stb, or nothing when absent.
# Debian's libstb (pkg-config stb, -lstb) links the compiled library; header-
# only stb gets IMPL=1 (common/app/stb_impl.c compiles it in).
stb_flags() {
  local cc=$1 mode=${2:-} cf libs d
  if pc --exists stb; then
    cf=$(pc --cflags stb); libs=$(pc --libs stb)
    # shellcheck disable=SC2086
    if [ "$mode" != headers ] && [[ " $libs " == *" -lstb "* ]] && try "$cc" "$STB_SRC" $cf $libs; then
      echo "$cf|$libs|"; return
    fi
    # shellcheck disable=SC2086
    if try "$cc" "$STB_HDR" $cf; then echo "$cf||1"; return; fi
  fi
  if try "$cc" "$STB_HDR"; then echo "||1"; return; fi
  for d in $(stb_dirs); do
    if [ -f "$d/stb_image.h" ] && try "$cc" "$STB_HDR" "-I$d"; then echo "-I$d||1"; return; fi
  done
}

# omp_flags CC: "CFLAGS|LIBS" that build OpenMP code, or nothing.
omp_flags() {
  local cc=$1 prefix
  if try "$cc" "$OMP_SRC" -fopenmp; then echo "-fopenmp|-fopenmp"; return; fi
  # Apple's clang: the driver takes -Xpreprocessor -fopenmp, Homebrew's libomp
  # the runtime.
  for prefix in $(command -v brew >/dev/null && brew --prefix libomp 2>/dev/null) \
                /opt/homebrew/opt/libomp /usr/local/opt/libomp; do
    if [ -f "$prefix/include/omp.h" ] &&
       try "$cc" "$OMP_SRC" -Xpreprocessor -fopenmp "-I$prefix/include" "-L$prefix/lib" -lomp; then
      echo "-Xpreprocessor -fopenmp -I$prefix/include|-L$prefix/lib -lomp"; return
    fi
  done
}

# missing CC: the things the build lacks, one a line.
missing() {
  local cc=${1:-cc} m
  command -v "${cc%% *}" >/dev/null || echo cc
  command -v make >/dev/null || echo make
  command -v pkg-config >/dev/null || echo pkg-config
  for m in cglm libpng criterion; do pc --exists "$m" || echo "$m"; done
  pc --exists zlib || try "$cc" "$Z_SRC" -lz || echo zlib
  # shellcheck disable=SC2046
  { pc --exists mpfr && try "$cc" "$MPFR_SRC" $(pc --cflags --libs mpfr) -lgmp; } ||
    try "$cc" "$MPFR_SRC" -lmpfr -lgmp || echo mpfr
  [ -n "$(stb_flags "$cc")" ] || echo stb
}

# ---------------------------------------------------------------- commands
check() {
  local cc=${1:-cc} sys things pkgs t
  sys=$(system)
  things=$(missing "$cc")
  [ -z "$things" ] && return 0
  pkgs=""
  for t in $things; do pkgs="$pkgs $(package "$sys" "$t")"; done
  pkgs=$(echo $pkgs) # one space between names
  if [ "$sys" = apt ] && [ "$(id -u)" = 0 ] && [ -n "$pkgs" ]; then
    echo "make: installing Debian packages: $pkgs"
    apt_install $pkgs || { echo "make: apt-get install failed"; return 1; }
    things=$(missing "$cc")
    [ -z "$things" ] && return 0
  fi
  echo "make: missing: $(echo $things)."
  [ -z "$pkgs" ] || { echo "Install them with:"; echo "  $(install_command "$sys" $pkgs)"; }
  case " $things " in
    *" cc "*) [ "$sys" = brew ] && echo "  xcode-select --install    (Apple's compiler: cc, clang)" ;;
  esac
  case " $things " in
    *" stb "*) [ "$sys" = brew ] || [ "$sys" = unknown ] &&
      echo "  stb (stb_image.h, stb_image_write.h) has no Homebrew formula: use the container" \
           "(README, \"Set up\"), or point make at a folder holding those two headers:" \
           "make STB_CFLAGS=-I/that/folder" ;;
  esac
  return 1
}

apt_install() {
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -qq --no-install-recommends "$@" >/dev/null
}

install() {
  local sys pkgs="" t
  sys=$(system)
  for t in cc make pkg-config cglm libpng zlib stb criterion mpfr libomp; do
    pkgs="$pkgs $(package "$sys" "$t")"
  done
  pkgs=$(echo $pkgs)
  echo "deps: installing: $pkgs"
  case "$sys" in
    apt) apt_install $pkgs ;;
    dnf) dnf install -y $pkgs ;;
    pacman | msys2) pacman -S --needed --noconfirm $pkgs ;;
    brew) brew install $pkgs ;;
    *) echo "deps: unknown system: install $pkgs yourself" >&2; return 1 ;;
  esac
}

# The Debian packages of an optional target (need_debs in the Makefile).
debs() {
  local missing="" p
  if ! command -v dpkg-query >/dev/null; then
    echo "make: this target uses Debian's $*; on this system install their equivalents" \
         "yourself (or use the container, README \"Set up\")"
    return 0
  fi
  for p in "$@"; do
    dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q 'install ok installed' ||
      missing="$missing $p"
  done
  [ -z "$missing" ] && return 0
  if [ "$(id -u)" = 0 ] && [ "${DEPS_INSTALL:-1}" != 0 ]; then
    echo "make: installing Debian packages${DEBS_FOR:+ for $DEBS_FOR}:$missing" \
         "(apt-get install, as root; DEPS_INSTALL=0 only names them)"
    # shellcheck disable=SC2086
    apt_install $missing || { echo "make: apt-get install failed"; return 1; }
    echo "make: installed:$missing"
  else
    echo "make: missing Debian packages${DEBS_FOR:+ for $DEBS_FOR}. Install them with:"
    echo "  sudo apt-get update && sudo apt-get install -y$missing"
    return 1
  fi
}

# config CC [STB]: the make variables for this compiler and system.
config() {
  local cc=${1:-cc} stbmode=${2:-} kind=gcc version omp stb lto="" pkgs
  version=$($cc --version 2>/dev/null | head -n 1)
  case "$version" in *clang*) kind=clang ;; esac
  # gcc's link-time optimisation with fat objects (the tests and tools link
  # the same objects without it). clang's LTO objects are bitcode that plain
  # links cannot read: clang builds without LTO.
  if [ "$kind" = gcc ] && try "$cc" "$MAIN" -flto=auto -ffat-lto-objects; then
    lto="-flto=auto -ffat-lto-objects"
  fi
  omp=$(omp_flags "$cc")
  stb=$(stb_flags "$cc" "$stbmode")
  pkgs="libpng"
  pc --exists zlib && pkgs="$pkgs zlib"
  echo "# tools/build/deps.sh config '$cc': $version"
  echo "CONFIG_CC := $cc"
  echo "CONFIG_STB := $stbmode"
  echo "CC_KIND := $kind"
  echo "CC_MACHINE := $($cc -dumpmachine 2>/dev/null)"
  # macOS hides madvise and memmem under _POSIX_C_SOURCE unless asked.
  [ "$(uname -s)" = Darwin ] && echo "SYS_CFLAGS := -D_DARWIN_C_SOURCE"
  echo "CC_LTO := $lto"
  echo "OMP_CFLAGS := ${omp%%|*}"
  echo "OMP_LIBS := ${omp#*|}"
  # cglm's struct API is header-only: its flags, not its library.
  echo "LIB_CFLAGS := $(pc --cflags cglm $pkgs)"
  echo "LIB_LIBS := $(pc --libs $pkgs) $(pc --exists zlib || echo -lz)"
  if [ -n "$stb" ]; then
    echo "STB_CFLAGS_FOUND := ${stb%%|*}"
    stb=${stb#*|}
    echo "STB_LIBS_FOUND := ${stb%%|*}"
    echo "STB_IMPL_FOUND := ${stb#*|}"
  fi
  echo "TEST_CFLAGS := $(pc --cflags criterion) $(pc --cflags mpfr)"
  if pc --exists mpfr; then
    echo "TEST_LIBS := $(pc --libs criterion) $(pc --libs mpfr)"
  else
    echo "TEST_LIBS := $(pc --libs criterion) -lmpfr -lgmp"
  fi
}

cmd=${1:-check}
[ $# -gt 0 ] && shift
case "$cmd" in
  check) check "$@" ;;
  install) install ;;
  debs) debs "$@" ;;
  config) config "$@" ;;
  system) system ;;
  *) echo "usage: tools/build/deps.sh check [CC] | install | debs PKG... | config CC [headers] | system" >&2
     exit 2 ;;
esac
