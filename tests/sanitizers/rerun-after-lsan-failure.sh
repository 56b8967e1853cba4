#!/usr/bin/env bash
# Test launcher of the sanitizer build (CMakePresets.json "asan", RMFX_TEST_LAUNCHER): runs the
# test command given as arguments. When it fails with LeakSanitizer's own fatal error and no
# finding ("Tracer caught signal 11" … "LeakSanitizer has encountered a fatal error": the
# exit-time scan of the process's threads crashing, now and then, beside Mesa's llvmpipe
# threads), it runs the test once more and says so. Every other failure, each sanitizer report
# included, is returned unchanged.
set -u
log=$(mktemp)
trap 'rm -f "$log"' EXIT
"$@" > >(tee "$log") 2>&1
status=$?
wait  # for tee to finish writing the log
if [ "$status" -ne 0 ] && grep -q "LeakSanitizer has encountered a fatal error" "$log" &&
   ! grep -q -E "ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:" "$log"; then
    echo "rmfx: LeakSanitizer itself failed above (no finding); running the test once more"
    "$@"
    status=$?
fi
exit "$status"
