# Sourced by tools/check/check-regions.sh and tools/check/mutants.sh: a scratch copy of
# the tree (the tracked files, git ls-files, with the working tree's content)
# that one build directory serves from one change to the next.
# docs/testing-the-tests.md.

# scratch_top NAME: top= the checkout's top folder, and cd there (NAME: the
# tool, for the error).
scratch_top() {
  top=$(git -C "$(dirname "$0")" rev-parse --show-toplevel 2>/dev/null) || {
    echo "$1: not inside a git checkout (the scratch tree is made from git ls-files)" >&2; exit 1; }
  cd "$top" || exit 1
}

# scratch_sync TOP TREE: make TREE hold exactly the tracked files of TOP.
# Only files whose content differs are copied, without keeping their times,
# so make rebuilds exactly what changed since the last build in TREE.
scratch_sync() {
  local top=$1 tree=$2 f
  mkdir -p "$tree"
  while IFS= read -r -d '' f; do
    [ -e "$top/$f" ] || continue                 # deleted in the working tree
    if ! cmp -s "$top/$f" "$tree/$f"; then
      mkdir -p "$tree/$(dirname "$f")"
      rm -f "$tree/$f"
      cp "$top/$f" "$tree/$f"
    fi
  done < <(git -C "$top" ls-files -z)
  # Files TOP no longer has (outside TREE's own build/): removed, or a
  # Makefile's wildcard would still compile them.
  comm -23 <(cd "$tree" && find . -path ./build -prune -o -type f -print | sed 's|^\./||' | LC_ALL=C sort) \
           <(cd "$top" && git ls-files | while IFS= read -r f; do [ -e "$f" ] && echo "$f"; done | LC_ALL=C sort) |
    while IFS= read -r f; do rm -f "$tree/$f"; done
}

# scratch_restore TOP TREE FILE...: put the tracked content back.
scratch_restore() {
  local top=$1 tree=$2 f
  shift 2
  for f in "$@"; do
    cmp -s "$top/$f" "$tree/$f" || cp "$top/$f" "$tree/$f"
  done
}

# Fast build flags for the scratch tree: -O1 without LTO, and what a stub leaves
# unused (parameters, helpers) stays a warning, as in the starter's Makefile.
SCRATCH_OPT="-O1 -Wno-error=unused-parameter -Wno-error=unused-variable \
-Wno-error=unused-function -Wno-error=unused-but-set-variable"

# scratch_make TREE ARGS...: make in TREE with the fast flags, quietly; the
# output goes to TREE/build/make.log.
scratch_make() {
  local tree=$1
  shift
  mkdir -p "$tree/build"
  make -C "$tree" --no-print-directory -j"${JOBS:-2}" OPT="$SCRATCH_OPT" "$@" \
    >"$tree/build/make.log" 2>&1
}

# The step folders of TREE that have a manifest (step.mk): 01-film ..., in order.
scratch_steps() { (cd "$1/steps" && ls -d [0-9][0-9]-*/step.mk | sed "s|/step.mk||" | sort); }

# The name of the step numbered NN in TREE (01 -> 01-film).
scratch_step_name() { (cd "$1/steps" && ls -d "$2"-* 2>/dev/null | head -n 1); }

# png_size FILE: "W H" of a PNG, from its IHDR chunk.
png_size() {
  od -An -tu1 -j16 -N8 "$1" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4, $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }'
}

# tap_tests FILE "ok"|"not ok": the tests (suite::name) a Criterion TAP report
# marks passed or failed, one a line.
tap_tests() { sed -n "s/^$2 - \([^ ]*\).*/\1/p" "$1" 2>/dev/null; }
