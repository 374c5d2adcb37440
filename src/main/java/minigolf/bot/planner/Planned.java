package minigolf.bot.planner;

import minigolf.bot.Shot;

/**
 * The stroke plan's lay-up; verified when the look-ahead holed out from its rest point;
 * strokesLeft: the plan's strokes from there.
 */
record Planned(Shot shot, boolean verified, int strokesLeft) {
}
