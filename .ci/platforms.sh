#!/usr/bin/env bash
# CI: resolve the complete runtime class path, natives included, from the registry for the platforms the
# game supports today (Linux x64: imgui-java has no natives elsewhere, see README "Platforms"), and for all
# five desktop platforms with the UI candidate lwjgl-nuklear, so that a native that disappears fails here.
set -uo pipefail
cd "$(dirname "$0")/.."
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! gradle --no-daemon --console=plain -q resolvePlatforms -Pplatforms=linux-x64 >"$log" 2>&1; then
    grep -v -i '^openjdk\|^OpenJDK' "$log" | tail -20
    echo "platforms: FAILED: the runtime class path for linux-x64 does not resolve"
    exit 1
fi
if ! gradle --no-daemon --console=plain -q resolvePlatforms -PuiStack=nuklear >"$log" 2>&1; then
    grep -v -i '^openjdk\|^OpenJDK' "$log" | tail -20
    echo "platforms: FAILED: with lwjgl-nuklear the class path does not resolve for every platform"
    exit 1
fi
echo "platforms: runtime class path resolves for linux-x64, and with lwjgl-nuklear for all five desktop platforms"
