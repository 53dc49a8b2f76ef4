#!/usr/bin/env bash
# The live view's page in a real browser: headless Chromium (Debian's `chromium`, installed by
# scripts/setup) driven by puppeteer-core from npm, installed on first use into the test's own
# folder in the build tree (nothing is vendored). Skips (exit 77), saying why, when Chromium, node
# or npm is missing or puppeteer-core cannot be installed.
#   view_browser_test.sh OBSCURA_CLI WORK_DIR
set -euo pipefail
cli=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
puppeteer_version=24.43.1

skip() {
  echo "skipped: $*"
  exit 77
}
"$cli" view --help >/dev/null 2>&1 || skip "this obscura has no view command"
chromium=${OBSCURA_CHROMIUM:-$(command -v chromium || command -v chromium-browser || true)}
[ -n "$chromium" ] || skip "no Chromium (Debian's chromium; scripts/setup installs it)"
command -v node >/dev/null || skip "no node (scripts/setup installs nodejs)"
mkdir -p "$work"
work=$(cd "$work" && pwd)
if [ ! -f "$work/node_modules/puppeteer-core/package.json" ] ||
   ! grep -q "\"version\": \"$puppeteer_version\"" "$work/node_modules/puppeteer-core/package.json"; then
  command -v npm >/dev/null || skip "no npm to install puppeteer-core with"
  echo "installing puppeteer-core $puppeteer_version into $work" >&2
  # --ignore-scripts: puppeteer-core downloads no browser, and nothing else may run.
  (cd "$work" && npm install --no-audit --no-fund --ignore-scripts --no-save \
     "puppeteer-core@$puppeteer_version" >npm-install.log 2>&1) ||
    skip "npm could not install puppeteer-core (see $work/npm-install.log)"
fi
exec node "$here/view_browser_test.mjs" "$cli" "$chromium" "$work"
