#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-serve turns bad flags and files into one line on stderr with the documented
# exit status, and a running server stops cleanly (status 0) on SIGTERM.
# Usage: serve_cli_errors_test.sh STRIELAD_CONVERT WORK_DIR (strielad-serve is found
# next to strielad-convert in the build tree).
set -uo pipefail
convert=$1
sample="$(dirname "$convert")/../strielad-sample/strielad-sample"
work=$2
serve="$(dirname "$convert")/../strielad-serve/strielad-serve"
rm -rf "$work" && mkdir -p "$work"

# shellcheck source=../support/expect_cli_error.sh
source "$(dirname "$0")/../support/expect_cli_error.sh"
# expect STATUS "SUBSTRING" -- ARGS...
expect() { expect_cli_error "$serve" "$work" "$@"; }

"$sample" -o "$work/data" --dims 12x10x5 --steps 1 --vars clw,ta -q
mkdir -p "$work/root"
"$convert" "$work"/data/*.nc -o "$work/root/store" --brick 4 -q
echo '{"subvolumes": [{"id": 1, "limits": [{"var": "clw", "min": 1e-6}]}]}' > "$work/scene.json"
: > "$work/empty-token"
chmod 600 "$work/empty-token"
echo "s3cret" > "$work/open-token"
chmod 644 "$work/open-token"

expect 2 "--frame metric" -- extract --store "$work/root/store" --scene "$work/scene.json" \
  -o "$work/out.vdb" --frame metric
expect 3 "dataset root is not a directory" -- --root "$work/no-such-root"
expect 2 "--listen" -- --root "$work/root" --listen nonsense
expect 2 "--handshake-timeout" -- --root "$work/root" --handshake-timeout 0
expect 2 "--max-handshakes" -- --root "$work/root" --max-handshakes 0
expect 2 "--max-send-queue-mib" -- --root "$work/root" --max-send-queue-mib 0
expect 3 "cannot read the token file" -- --root "$work/root" --token-file "$work/no-token"
expect 4 "token file is empty" -- --root "$work/root" --token-file "$work/empty-token"
# A secret others can read protects nothing: refused, as ssh refuses such a key.
expect 4 "open-token: the token file has mode 0644" -- --root "$work/root" --token-file "$work/open-token"

# A running server stops cleanly on SIGTERM.
"$serve" --root "$work/root" --listen 127.0.0.1:0 --json -q >"$work/endpoint" 2>"$work/serve.err" &
pid=$!
for _ in $(seq 100); do [[ -s "$work/endpoint" ]] && break; sleep 0.1; done
if ! grep -q '"port"' "$work/endpoint"; then
  echo "FAIL: no endpoint line"; cat "$work/serve.err"; failures=$((failures + 1))
fi
kill -TERM "$pid"
wait "$pid"
status=$?
if [[ $status -ne 0 ]]; then
  echo "FAIL: SIGTERM -> status $status"; cat "$work/serve.err"; failures=$((failures + 1))
else
  echo "ok: SIGTERM -> status 0"
fi

if [[ $failures -ne 0 ]]; then
  echo "$failures failure(s)"
  exit 1
fi
rm -rf "$work"
