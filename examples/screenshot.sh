#!/usr/bin/env bash
# Renders an SVG to PNG with headless Chromium, to look at a picture as a person would
# (not part of the tests). Needs Debian's chromium: apt-get install chromium.
#   examples/screenshot.sh picture.svg picture.png [WIDTHxHEIGHT]
set -euo pipefail
svg=$(realpath "$1"); png=$(realpath -m "$2"); size=${3:-900x640}
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$profile" --hide-scrollbars --window-size="${size/x/,}" \
  --screenshot="$png" "file://$svg" 2>/dev/null
echo "wrote $png"
