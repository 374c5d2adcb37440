#!/usr/bin/env bash
# Two game windows play an online hole against each other through a local server, each under its
# own Xvfb display, and save a screenshot of each at the end (docs/online.md, "Two windows").
#   tools/online-two-windows.sh OUT_DIR [DISPLAY_A DISPLAY_B] [PORT]
# Ann hosts a room on Flat and holes her first putt (the closed form v = sqrt(2 mu g d) aimed at the
# hole); Bob joins with the code, putts short, then holes his second. Needs build/install (gradle installDist).
# MIDHOLE=1: the windmill course instead (windmill-push: blades turning on the room's clock); each putts once,
# short, and both windows save their screenshot mid-hole after FRAMES frames (default 700).
set -euo pipefail
out=${1:?usage: tools/online-two-windows.sh OUT_DIR [DISPLAY_A DISPLAY_B] [PORT]}
da=${2:-96}; db=${3:-86}; port=${4:-18627}
cd "$(dirname "$0")/.."
bin=$PWD/build/install/minigolf/bin/minigolf
mkdir -p "$out"
course=flat; ann_shots=3.425:0.2854; bob_shots=2.5:0.2,2.3497:0.2046; frames=6000
if [ "${MIDHOLE:-0}" = 1 ]; then course=windmill-push; ann_shots=1.3:0; bob_shots=1.1:0.1; frames=${FRAMES:-700}; fi
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}; chmod 700 "$XDG_RUNTIME_DIR"; unset WAYLAND_DISPLAY
"$bin" server --port "$port" --host 127.0.0.1 --db "$out/server.db" > "$out/server.out" 2> "$out/server.err" &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
for _ in $(seq 60); do [ -s "$out/server.out" ] && break; sleep 1; done
# Each window keeps its settings, high scores and remembered seat in a config folder of its own.
XDG_CONFIG_HOME="$out/ann-config" xvfb-run -n "$da" -s "-screen 0 1600x1000x24" "$bin" play --online "127.0.0.1:$port" --create "$course" \
    --seats 2 --name Ann --shots "$ann_shots" --frames "$frames" --screenshot "$out/ann.png" > "$out/ann.out" 2> "$out/ann.err" &
ann=$!
for _ in $(seq 120); do [ -s "$out/ann.out" ] && break; sleep 1; done
code=$(head -1 "$out/ann.out" | sed 's/.*"room": "\([A-Z0-9]*\)".*/\1/')
echo "room $code"
XDG_CONFIG_HOME="$out/bob-config" xvfb-run -n "$db" -s "-screen 0 1600x1000x24" "$bin" play --online "127.0.0.1:$port" --room "$code" \
    --name Bob --shots "$bob_shots" --frames "$frames" --screenshot "$out/bob.png" > "$out/bob.out" 2> "$out/bob.err" &
bob=$!
wait $ann $bob
cat "$out/ann.out" "$out/bob.out"
