#!/usr/bin/env bash
# The web build's end-to-end tests (tests/web/page_test.mjs, then classroom_test.mjs: touch,
# tooltips, the browser's keys, a phone; then phone_test.mjs: a phone's UI scale, its pinned
# close button, finger-sized targets, the typing field) or its benchmark (bench.mjs) in headless
# Chromium, against build/web/ served on localhost. playwright-core comes from the npm registry,
# at the version package-lock.json pins, installed into build/web-test/.
#   tests/web/run.sh                 the tests; screenshots in build/web-test/shots/
#   tests/web/run.sh FILE.mjs        one of them
#   tests/web/run.sh bench N...      the page's ?bench=N for each N
# scripts/web.sh test and bench build the page first.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
work=$root/build/web-test
mkdir -p "$work"
# npm ci again only when the pinned versions change.
if ! cmp -s tests/web/package-lock.json "$work/package-lock.json" || [[ ! -d $work/node_modules ]]; then
  cp tests/web/package.json tests/web/package-lock.json "$work/"
  (cd "$work" && npm ci --no-audit --no-fund --loglevel=error)
fi

log=$work/serve.log
python3 scripts/web/serve.py build/web 0 >"$log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
for _ in $(seq 300); do
  grep -q '^Serving ' "$log" && break
  sleep 0.1
done
url=$(sed -n 's/^Serving //p' "$log")
[[ -n $url ]] || { echo "error: the server did not start: $(cat "$log")" >&2; exit 1; }

export NODE_PATH=$work/node_modules
export PSB_WEB_URL=$url PSB_WEB_SHOTS=$work/shots PSB_ROOT=$root
if [[ ${1:-} == bench ]]; then
  shift
  node tests/web/bench.mjs "$@"
elif [[ -n ${1:-} ]]; then
  # One test file alone: tests/web/run.sh tests/web/phone_test.mjs
  node "$1"
else
  # All of them, whatever the first ones found.
  status=0
  node tests/web/page_test.mjs || status=1
  node tests/web/classroom_test.mjs || status=1
  node tests/web/phone_test.mjs || status=1
  exit $status
fi
