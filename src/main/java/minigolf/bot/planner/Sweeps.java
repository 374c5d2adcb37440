package minigolf.bot.planner;

import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import minigolf.physics.ShotResult;

/** What the planner's sweeps of bare shots share ({@link CountingSimulator#simulateInOrder}). */
final class Sweeps {
    private Sweeps() {
    }

    /** Shots tried in order until one holes out (that one ends the sweep). */
    static CountingSimulator.InOrder<Shot> untilHoled() {
        return new CountingSimulator.InOrder<>() {
            @Override
            public Shot shot(Shot shot) {
                return shot;
            }

            @Override
            public boolean stopsAt(Shot shot, ShotResult result) {
                return CountingSimulator.holed(result);
            }
        };
    }
}
