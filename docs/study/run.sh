#!/bin/bash
# The study's experiments (docs/bots-study.md), from the repository root after gradle installDist.
M=build/install/minigolf/bin/minigolf
rm -rf /tmp/study-suite /tmp/st-*
mkdir -p /tmp/study-suite && cp courses/bench/{flat-7m,lake-bowl,pond,water-bank,maze-c,two-putt}.json /tmp/study-suite/
$M experiment --suite /tmp/study-suite --bots planner,robust,astar-newton,local,graph --seeds 6 --noise-velocity 0,0.02,0.05,0.1 --threads 2 --out /tmp/st-noise > /dev/null 2>&1
$M experiment --suite /tmp/study-suite --bots planner,robust --seeds 6 --noise-position 0,0.01,0.05 --threads 2 --out /tmp/st-position > /dev/null 2>&1
$M experiment --suite courses/bench --bots planner,robust --seeds 10 --noise-velocity 0.05 --threads 2 --out /tmp/st-robust > /dev/null 2>&1
$M experiment --suite docs/study/putts --bots planner --seeds 200 --max-strokes 1 --noise-velocity 0.02,0.05,0.1 --threads 2 --out /tmp/st-putts > /dev/null 2>&1
$M experiment --suite courses/friction --bots planner --seeds 3 --threads 2 --out /tmp/st-known > /dev/null 2>&1
$M experiment --suite courses/friction --bots planner --seeds 3 --hide-friction --threads 2 --out /tmp/st-hidden > /dev/null 2>&1
echo study done
