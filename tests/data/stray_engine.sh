#!/bin/sh
# An external engine that leaves processes behind, one way per MODE, for the process-boundary
# tests (tests/process_boundary_test.sh). Every process it starts appends its pid to
# $STRAY_PIDS, so the test can check that none is left once springcheck returns.
#   stray_engine.sh MODE
mode=$1
case "$mode" in
  child-left)       # a background child, then a failure
    sleep 60 & echo $! >> "$STRAY_PIDS"; exit 1 ;;
  grandchild-left)  # a grandchild whose parent exits at once: re-parented
    ( sleep 60 & echo $! >> "$STRAY_PIDS" ); exit 1 ;;
  setsid-left)      # a child in a session of its own: out of the engine's process group
    setsid sleep 60 & echo $! >> "$STRAY_PIDS"; exit 1 ;;
  setsid-timeout)   # the same, and the engine itself runs past its 2 s limit
    setsid sleep 60 & echo $! >> "$STRAY_PIDS"; echo $$ >> "$STRAY_PIDS"; sleep 60 ;;
  joins-group)      # the engine moves into springcheck's own process group, past its 2 s limit
    exec python3 -c 'import os, time
os.setpgid(0, os.getpgid(os.getppid()))
open(os.environ["STRAY_PIDS"], "a").write("%d\n" % os.getpid())
time.sleep(60)' ;;
  exit-1)           # fails at once (for a parent that ignores SIGCHLD)
    exit 1 ;;
  sleeper)          # runs until stopped, with a child (for the signal tests)
    echo $$ >> "$STRAY_PIDS"; sleep 60 & echo $! >> "$STRAY_PIDS"; wait ;;
esac
