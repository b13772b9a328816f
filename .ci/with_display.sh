#!/usr/bin/env bash
# Runs a command where it has a display: the current one, or Xvfb (GL through Mesa's llvmpipe)
# when there is none (CI, headless machines). Used by .ci/test.sh, .ci/sanitize.sh and .ci/main.sh.
# -noreset: by default Xvfb resets when its last client disconnects, and a GL test that connects
# during that reset fails with "Failed to open display" (seen once in CI with two tests in flight).
set -euo pipefail
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" "$@"
fi
exec "$@"
