#!/usr/bin/env bash
# CI: resolve the complete runtime class path, natives included (LWJGL's, lwjgl-nuklear's among them), from the
# registry for all five desktop platforms (docs/development.md, "Prerequisites and platforms"), so that a native that
# disappears, or a dependency that has no native for one of them, fails here.
set -uo pipefail
cd "$(dirname "$0")/.."
log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! gradle --no-daemon --console=plain -q resolvePlatforms >"$log" 2>&1; then
    grep -v -i '^openjdk\|^OpenJDK' "$log" | tail -20
    echo "platforms: FAILED: the runtime class path does not resolve for every desktop platform"
    exit 1
fi
echo "platforms: runtime class path resolves for windows-x64, macos-arm64, macos-x64, linux-x64 and linux-arm64"
