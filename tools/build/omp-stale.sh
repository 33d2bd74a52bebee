#!/bin/sh
# Removes the registration files LLVM's OpenMP runtime (libomp: make
# sanitize-clang, make fuzz) left empty in /dev/shm. Each program it starts
# creates /dev/shm/__KMP_REGISTERED_LIB_PID_UID, sizes it to 1 KB and removes
# it at exit; a program that dies between the creation and the sizing (a
# file-size limit, a kill) leaves it empty, and a later program that gets the
# same PID maps it and dies of SIGBUS before main ("AddressSanitizer: BUS ...
# in internal_strlen"). Only this user's empty files of processes that are
# gone are removed. docs/reliability.md, "Sanitizers". Usage: tools/build/omp-stale.sh
uid=$(id -u)
for f in /dev/shm/__KMP_REGISTERED_LIB_*_"$uid"; do
  if [ ! -f "$f" ] || [ -s "$f" ] || [ ! -O "$f" ]; then continue; fi
  pid=${f#/dev/shm/__KMP_REGISTERED_LIB_}
  pid=${pid%_"$uid"}
  case $pid in '' | *[!0-9]*) continue ;; esac
  [ -d "/proc/$pid" ] && continue
  rm -f "$f" && echo "omp-stale: removed $f (empty, left by a process that is gone)"
done
exit 0
