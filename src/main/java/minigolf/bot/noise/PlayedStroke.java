package minigolf.bot.noise;

import minigolf.bot.Shot;

/** A stroke as it is really played: where it starts and the velocity the ball leaves with. */
public record PlayedStroke(double x, double y, Shot shot) {
}
