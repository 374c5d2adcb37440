package minigolf.bot.planner;

import minigolf.bot.Shot;
import minigolf.physics.World;

/** A look-ahead's holing shot from a lay-up's rest point (the engine is deterministic). */
record Solved(World world, double x, double y, Shot shot) {
}
