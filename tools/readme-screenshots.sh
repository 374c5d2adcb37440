#!/usr/bin/env bash
# The README's game screenshots, through the real game loop (minigolf play --frames ... --screenshot):
# the start of a three-player hot-seat hole, a computer opponent's turn, and the final card of an
# 18-hole round between two computer opponents, and the New game screen with the opponents' levels.
# Needs a display (or Xvfb, as below) and `gradle installDist compileTestJava`. A scratch config folder keeps your settings, names and scores out of them.
# Usage: tools/readme-screenshots.sh [OUT_DIR [NAME...]]   (default docs/screenshots, every picture;
# NAMEs take only those: hot-seat bot-turn new-game bot-thinking final-card-18)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-docs/screenshots}"
shift || true
wanted=" ${*:-hot-seat bot-turn new-game bot-thinking final-card-18} "
want() { [[ "$wanted" == *" $1 "* ]]; }
mkdir -p "$out"
config="$(mktemp -d)"
trap 'rm -rf "$config"' EXIT
export JAVA_OPTS="-Dminigolf.configDir=$config -Dminigolf.noSound=true ${JAVA_OPTS:-}"
mg=build/install/minigolf/bin/minigolf
run() {
    if [ -n "${DISPLAY:-}" ]; then "$mg" "$@"; else xvfb-run -a -s "-screen 0 1600x1000x24" "$mg" "$@"; fi
}
# 1. Hot seat: three balls side by side at the tee of the windmill hole, Ann's ringed, name tags.
want hot-seat && run play courses/holes/03-windmill.json --players Ann,Bob,Cy --frames 90 --screenshot "$out/hot-seat.png" > /dev/null
# 2. A computer opponent's turn: Hard has teed off on the volcano, its ball rolling with its trail
#    (a bot's turn shows "... is thinking" for at least 0.8 s, then it strokes).
want bot-turn && run play courses/holes/07-volcano.json --players Bot:hard,Ann --frames 16 --screenshot "$out/bot-turn.png" > /dev/null
# 2b. New game: Meadowbrook's 18 holes, Ann and Bob, and a computer opponent with its four levels.
run_java() {
    if [ -n "${DISPLAY:-}" ]; then java $JAVA_OPTS "$@"; else xvfb-run -a -s "-screen 0 1600x1000x24" java $JAVA_OPTS "$@"; fi
}
want new-game && run_java -cp "build/classes/java/test:build/classes/java/main:build/resources/main:build/install/minigolf/lib/*" \
    minigolf.app.NewGameScreenshot "$out/new-game.png" > /dev/null
# 2c. A computer opponent thinking: Ann has putted on the first tee, Hard's turn (docs/playing.md).
want bot-thinking && run_java -cp "build/classes/java/test:build/classes/java/main:build/resources/main:build/install/minigolf/lib/*" \
    minigolf.app.BotThinkingScreenshot "$out/bot-thinking.png" > /dev/null
# 3. The final card of Meadowbrook's 18 holes, Hard against Medium (the run ends at the card).
want final-card-18 && run play --round courses/rounds/meadowbrook-18.json --players Bot:hard,Bot:medium --frames 200000 --time-scale 40 \
    --screenshot "$out/final-card-18.png"
exit 0
