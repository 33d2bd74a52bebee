# Sourced by tools/grading/one.sh: a submission's files, whatever its form
# (docs/grading.md, "Handing out, collecting"). Archives and repositories are opened by
# sandbox_run, so a hostile archive (paths outside, links, a bomb) meets the
# same limits and walls as the submission's code.

# submission_name PATH: the student's name, from the entry's name without its
# extension, reduced to letters, digits, '.', '_' and '-'.
submission_name() {
  local n=${1%/}
  n=${n##*/}
  n=${n%.tar.gz}; n=${n%.tgz}; n=${n%.zip}; n=${n%.bundle}; n=${n%.git}
  n=$(printf '%s' "$n" | tr -c 'A-Za-z0-9._-' _)
  printf '%s\n' "${n:-unnamed}"
}

# submission_kind PATH: folder, git repository (bare), git bundle, tar.gz, zip,
# or unknown.
submission_kind() {
  local p=$1
  if [ -d "$p" ]; then
    if [ -f "$p/HEAD" ] && [ -d "$p/objects" ] && [ -d "$p/refs" ]; then echo "git repository"
    else echo folder; fi
    return
  fi
  case $p in
    *.tar.gz|*.tgz) echo tar.gz ;;
    *.zip) echo zip ;;
    *.bundle) echo "git bundle" ;;
    *) if head -c 16 "$p" 2>/dev/null | grep -q '^# v[23] git bundle'; then echo "git bundle"; else echo unknown; fi ;;
  esac
}

# submission_open PATH KIND DEST LOG: DEST/files holds the submission's files
# (a folder is read where it is: DEST/files is a link to it). Returns 1, with
# the reason in LOG, when it cannot be opened.
submission_open() {
  local src dest=$3 log=$4 st
  src=$(realpath -e -- "$1") || { echo "cannot read $1" >"$log"; return 1; }
  mkdir -p "$dest/files"
  if [ "$2" = folder ]; then
    rmdir "$dest/files" && ln -s "$src" "$dest/files"
    return 0
  fi
  sandbox_own "$dest"
  local cmd
  case $2 in
    tar.gz) cmd=(tar -xzf "$src" -C "$dest/files" --no-same-owner --no-same-permissions) ;;
    zip) cmd=(unzip -q -o "$src" -d "$dest/files") ;;
    "git repository")
      cmd=(sh -c 'git -c safe.directory="*" --git-dir="$1" archive HEAD | tar -x -C "$2/files"' sh "$src" "$dest") ;;
    "git bundle")
      cmd=(sh -c 'git clone -q "$1" "$2/clone" && git -C "$2/clone" archive HEAD | tar -x -C "$2/files" &&
                  rm -rf "$2/clone"' sh "$src" "$dest") ;;
    *) echo "not a folder, .tar.gz, .zip, git repository or git bundle" >"$log"; return 1 ;;
  esac
  SANDBOX_RO="$src" sandbox_run "${GRADE_UNPACK_WALL:-60}" "${GRADE_UNPACK_WALL:-60}" "$log" "$dest" -- "${cmd[@]}"
  st=$?
  [ $st = 0 ] || { echo "$2: $(sandbox_status_text $st "${GRADE_UNPACK_WALL:-60}" "${GRADE_UNPACK_WALL:-60}")" >>"$log"; return 1; }
}

# submission_root DIR: the folder of the tree inside DIR: DIR itself, or the
# single folder an archive wraps it in (a/, a/b/, ...), down to the first
# folder holding steps/ or common/.
submission_root() {
  local d=$1 entries
  while [ ! -d "$d/steps" ] && [ ! -d "$d/common" ]; do
    entries=$(ls -A "$d" 2>/dev/null)
    [ "$(printf '%s\n' "$entries" | grep -c .)" = 1 ] && [ -d "$d/$entries" ] && [ ! -L "$d/$entries" ] || break
    d=$d/$entries
  done
  realpath -e -- "$d"
}
