package minigolf.bot.planner;

import minigolf.bot.Shot;
import minigolf.physics.ShotResult;

/** One probe: the shot, its rest point, the miss F and the direction the ball passed the hole in. */
record Eval(Shot shot, ShotResult result, boolean penalty, boolean holed, double restX, double restY,
                    double fx, double fy, double dirX, double dirY, boolean collided) {
}
