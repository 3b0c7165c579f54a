#!/usr/bin/env bash
# Runs .ci/run N times on fresh clones of one commit, for issue 16's "consecutive CI passes
# with no test changing outcome".
#
#   scripts/ci-loop.sh REPO COMMIT N WORKDIR
#
# Each pass clones REPO at COMMIT into WORKDIR/run (nothing beside it: the repository
# carries its own data), runs .ci/run, and writes WORKDIR/log/pass-K.log, the per-test outcomes
# (pass-K.tests: one `test NAME ... ok|FAILED|ignored` line per Rust test, sorted) and a
# line in WORKDIR/log/summary.txt. The cargo target directories are carried from pass to
# pass as a CI cache would carry them, and every source file gets one fixed mtime so that
# cargo reuses the previous pass's build of the same commit: what is under test is the
# tests' outcome, not the compiler's. Compare passes with `diff pass-1.tests pass-K.tests`.
set -u
REPO=$1; COMMIT=$2; N=$3; W=$4
mkdir -p "$W/log"
for k in $(seq 1 "$N"); do
    rm -rf "$W/run"
    git clone -q "$REPO" "$W/run" && git -C "$W/run" checkout -q "$COMMIT"
    # The old fixed mtime is only safe when the cache was built from this same commit
    # (changed sources with an old mtime would look up to date to cargo); otherwise the
    # clone keeps today's mtimes and cargo rebuilds the workspace's crates.
    if [ "$(cat "$W/target-cache/.ci-loop-commit" 2>/dev/null)" = "$COMMIT" ]; then
        find "$W/run" -path "$W/run/.git" -prune -o -type f -exec touch -h -d "2026-01-01 00:00:00" {} +
    fi
    [ -d "$W/target-cache" ] && mv "$W/target-cache" "$W/run/target"
    [ -d "$W/py-target-cache" ] && mv "$W/py-target-cache" "$W/run/crates/hyplan-py/target"
    t0=$(date +%s)
    (cd "$W/run" && .ci/run) > "$W/log/pass-$k.log" 2>&1
    rc=$?
    t1=$(date +%s)
    grep -E "^test .* \.\.\. (ok|FAILED|ignored)" "$W/log/pass-$k.log" | sort > "$W/log/pass-$k.tests"
    echo "pass $k commit $COMMIT rc $rc $((t1 - t0)) s tests $(wc -l < "$W/log/pass-$k.tests") failed $(grep -c FAILED "$W/log/pass-$k.tests") $(date -u +%H:%M)" >> "$W/log/summary.txt"
    mv "$W/run/target" "$W/target-cache"
    echo "$COMMIT" > "$W/target-cache/.ci-loop-commit"
    [ -d "$W/run/crates/hyplan-py/target" ] && mv "$W/run/crates/hyplan-py/target" "$W/py-target-cache"
done
