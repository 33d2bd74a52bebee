# Sourced by tools/grading/one.sh: run a submission's build and programs under
# limits (wall time, CPU time, memory, file and output size, processes) and,
# where possible, in a sandbox (docs/grading.md, "The sandbox").
#
# Modes, chosen once by sandbox_init (GRADE_SANDBOX forces one):
#   root  bubblewrap as root: no network, a private /tmp, only /usr and /etc
#         (read-only) and the folders given to sandbox_run (read-write) visible,
#         a new PID namespace (nothing outlives the command), run as nobody
#   user  bubblewrap in an unprivileged user namespace: the same, as yourself
#   none  limits only (bubblewrap missing or not allowed to start): the code
#         runs as you, with your network and your files

SANDBOX_NOBODY=65534

# sandbox_init: set SANDBOX_MODE and SANDBOX_WHY (one line for the report).
sandbox_init() {
  local want=${GRADE_SANDBOX:-auto}
  SANDBOX_MODE=none
  SANDBOX_WHY="no sandbox: limits only, the code runs as $(id -un) with the network"
  if [ "$want" = none ]; then SANDBOX_WHY="$SANDBOX_WHY (GRADE_SANDBOX=none)"; return; fi
  if ! command -v bwrap >/dev/null; then SANDBOX_WHY="$SANDBOX_WHY (bwrap is not installed)"; return; fi
  if [ "$(id -u)" = 0 ] && [ "$want" != user ] &&
     bwrap $(sandbox_base_args) true 2>/dev/null; then
    SANDBOX_MODE=root
    SANDBOX_WHY="bubblewrap: no network, only /usr, /etc and the scratch tree visible, run as nobody"
  elif bwrap --unshare-user $(sandbox_base_args) true 2>/dev/null; then
    SANDBOX_MODE=user
    SANDBOX_WHY="bubblewrap (user namespace): no network, only /usr, /etc and the scratch tree visible, run as $(id -un)"
  else
    SANDBOX_WHY="$SANDBOX_WHY (bwrap cannot create namespaces here)"
  fi
}

# The mounts and namespaces every sandboxed command gets.
sandbox_base_args() {
  local d
  echo --ro-bind /usr /usr --ro-bind /etc /etc --dev /dev --proc /proc --perms 1777 --tmpfs /tmp \
    --perms 1777 --tmpfs /dev/shm
  for d in bin sbin lib lib64 lib32 libx32; do
    if [ -L /$d ]; then echo --symlink "$(readlink /$d)" /$d
    elif [ -d /$d ]; then echo --ro-bind /$d /$d; fi
  done
  echo --unshare-net --unshare-pid --unshare-ipc --unshare-uts --new-session --die-with-parent
  echo --clearenv --setenv PATH /usr/bin:/bin --setenv HOME /tmp --setenv LC_ALL C
}

# sandbox_run WALL CPU LOG DIR -- CMD...: run CMD with DIR as its working
# directory and its only writable folder (besides a private /tmp), stdout and
# stderr to LOG; SANDBOX_RO lists more paths it may read (no spaces in them).
# Limits: WALL seconds of wall time, CPU seconds per process, GRADE_MEM_MB of
# address space, GRADE_OUT_MB per file written (LOG included), GRADE_NPROC
# processes. Prints nothing; returns CMD's status, 124 when the wall limit
# struck, 128+N when killed by signal N (24: CPU limit, 25: file or output
# size limit).
sandbox_run() {
  sandbox_start "$@"
  wait "$SANDBOX_PID"
}

# sandbox_start ...: the same in the background; SANDBOX_PID is the process
# to wait for (or to stop with SIGTERM, which ends everything inside).
sandbox_start() {
  local wall=$1 cpu=$2 log=$3 dir=$4
  shift 5
  local limits=(prlimit --cpu="$cpu:$((cpu + 1))" --as=$((${GRADE_MEM_MB:-4096} << 20))
                --fsize=$((${GRADE_OUT_MB:-64} << 20)) --core=0 --nproc="${GRADE_NPROC:-1024}" --)
  local box=() ro=() d
  for d in ${SANDBOX_RO:-}; do ro+=($(sandbox_parents "$d") --ro-bind "$d" "$d"); done
  ro+=($(sandbox_parents "$dir"))
  case $SANDBOX_MODE in
    root) box=(bwrap $(sandbox_base_args) "${ro[@]}" --bind "$dir" "$dir" --chdir "$dir" --
               setpriv --reuid=$SANDBOX_NOBODY --regid=$SANDBOX_NOBODY --clear-groups --inh-caps=-all) ;;
    user) box=(bwrap --unshare-user $(sandbox_base_args) "${ro[@]}" --bind "$dir" "$dir" --chdir "$dir" --) ;;
  esac
  ( cd "$dir" && exec timeout -k 2 "$wall" "${box[@]}" "${limits[@]}" "$@" ) >"$log" 2>&1 </dev/null &
  SANDBOX_PID=$!
}

# The folders above PATH, made traversable (bubblewrap makes them 0700).
sandbox_parents() {
  local p=${1%/*}
  while [ -n "$p" ]; do echo "--perms 0755 --dir $p"; p=${p%/*}; done | tac
}

# sandbox_own DIR: let the sandboxed user write DIR (root mode: chown to nobody).
sandbox_own() {
  [ "$SANDBOX_MODE" = root ] && chown -R "$SANDBOX_NOBODY:$SANDBOX_NOBODY" "$1"
  return 0
}

# sandbox_status_text STATUS WALL CPU: the status of sandbox_run in words.
sandbox_status_text() {
  case $1 in
    0) echo "finished" ;;
    124|137) echo "stopped at the wall-time limit (${2} s)" ;;
    152) echo "stopped at the CPU-time limit (${3} s)" ;;
    153) echo "stopped at the output limit (${GRADE_OUT_MB:-64} MiB per file)" ;;
    13[0-9]|14[0-9]|15[0-9]) echo "killed by signal $(( $1 - 128 )) ($(kill -l $(( $1 - 128 )) 2>/dev/null))" ;;
    *) echo "exited with status $1" ;;
  esac
}

# safe_file PATH: PATH (absolute, canonical) is a regular file and no part of
# it is a symbolic link, so reading it reads what the sandbox wrote and
# nothing it points at outside.
safe_file() {
  [ -f "$1" ] && [ "$(realpath -e -- "$1" 2>/dev/null)" = "$1" ]
}
