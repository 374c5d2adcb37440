#!/usr/bin/env bash
# CI: build the .deb with `gradle package` (jlink + jpackage), install it, and run the installed
# minigolf: --version, a simulation and a render with no display. Each must exit 0 and print nothing
# on stderr. Under CI (CI=true, root) the package is installed into the system with apt-get (so its
# dependencies are checked) and removed afterwards; elsewhere it is unpacked into a scratch root.
set -uo pipefail
cd "$(dirname "$0")/.."

fail() { echo "package: FAILED: $*"; exit 1; }

need=()
command -v fakeroot >/dev/null || need+=(fakeroot)
command -v dpkg-deb >/dev/null || need+=(dpkg-dev)
[ -e /usr/lib/x86_64-linux-gnu/libEGL_mesa.so.0 ] || [ -e /usr/lib/aarch64-linux-gnu/libEGL_mesa.so.0 ] \
    || need+=(libegl1 libegl-mesa0)
sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
if [ ${#need[@]} -gt 0 ]; then
    echo "package: installing ${need[*]}"
    $sudo apt-get update -qq || fail "apt-get update"
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null 2>&1 \
        || fail "apt-get install ${need[*]}"
fi

build_log=$(mktemp)
gradle --no-daemon --console=plain package >"$build_log" 2>&1 || { tail -30 "$build_log"; rm -f "$build_log"; fail "gradle package"; }
rm -f "$build_log"
deb=$(ls build/package/minigolf_*.deb 2>/dev/null | head -1)
[ -n "$deb" ] || fail "no .deb in build/package"
echo "package: built $deb ($(du -h "$deb" | cut -f1))"
contents=$(dpkg-deb -c "$deb")
for f in ./opt/minigolf/bin/minigolf ./opt/minigolf/lib/app/desktop/minigolf.png ./opt/minigolf/lib/app/desktop/minigolf.desktop \
         ./opt/minigolf/lib/runtime/lib/libjava.so ./opt/minigolf/lib/app/courses/lake.json; do
    grep -q " $f\$" <<<"$contents" || fail "$f is not in the package"
done
# dpkg -i on a minimal Debian stopped on the missing xdg-utils (issue 29): the package needs none.
depends=$(dpkg-deb -f "$deb" Depends)
grep -q 'xdg-utils' <<<"$depends" && fail "the package depends on xdg-utils: $depends"
control=$(mktemp -d)
dpkg-deb -e "$deb" "$control"
grep -q 'usr/share/applications/minigolf.desktop' "$control/postinst" || fail "the postinst does not install the menu entry"
rm -rf "$control"
if command -v desktop-file-validate >/dev/null; then
    desktop-file-validate src/packaging/linux/minigolf.desktop || fail "the menu entry does not validate"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
installed=""
if [ "${CI:-}" = "true" ] && [ "$(id -u)" -eq 0 ]; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "./$deb" >"$work/apt.log" 2>&1 \
        || { tail -20 "$work/apt.log"; fail "apt-get install ./$deb"; }
    installed=system
    [ -f /usr/share/applications/minigolf.desktop ] && [ -f /usr/share/icons/hicolor/256x256/apps/minigolf.png ] \
        || fail "no menu entry or icon after apt-get install"
    minigolf=/usr/bin/minigolf
    courses=/opt/minigolf/lib/app/courses
else
    dpkg-deb -x "$deb" "$work/root" || fail "dpkg-deb -x"
    minigolf=$work/root/opt/minigolf/bin/minigolf
    courses=$work/root/opt/minigolf/lib/app/courses
fi
echo "package: installed into ${installed:-a scratch root ($work/root)}"

status=0
# Runs the installed minigolf with no display; it must exit 0 with an empty stderr.
check() {
    local name=$1; shift
    if ! (cd "$work" && env -u DISPLAY -u WAYLAND_DISPLAY -u XDG_RUNTIME_DIR "$minigolf" "$@" >"$work/out" 2>"$work/err"); then
        echo "package: $name: exit code not 0"; cat "$work/err"; status=1; return
    fi
    if [ -s "$work/err" ]; then
        echo "package: $name: stderr is not empty:"; cat "$work/err"; status=1; return
    fi
    echo "package: $name: ok: $(head -c 160 "$work/out" | head -1)"
}
check "minigolf --version" --version
grep -q "^minigolf " "$work/out" || { echo "package: --version printed no version"; status=1; }
check "minigolf simulate" simulate "$courses/lake.json" --velocity 3,0.9
grep -q '"outcome":"water"' "$work/out" || { echo "package: simulate gave another outcome"; status=1; }
check "minigolf render (no display)" render "$courses/lake.json" --out "$work/lake.png" --size 320x200
[ -s "$work/lake.png" ] || { echo "package: render wrote no picture"; status=1; }

if [ "$installed" = system ]; then
    DEBIAN_FRONTEND=noninteractive apt-get purge -y -qq minigolf >/dev/null 2>&1 || { echo "package: could not remove minigolf"; status=1; }
    [ ! -e /opt/minigolf ] && [ ! -e /usr/bin/minigolf ] && [ ! -e /usr/share/applications/minigolf.desktop ] \
        || { echo "package: files left after removal"; status=1; }
fi
[ "$status" -eq 0 ] || fail "the installed minigolf"
echo "package: the .deb installs and its minigolf works (--version, simulate, render without a display)"
