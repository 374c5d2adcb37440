package minigolf.game;

import java.util.List;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Stroke;
import minigolf.physics.TrajectoryListener;
import minigolf.physics.World;

/**
 * A hole played again from its shot history: every stroke starts where it started in play with the
 * velocity it was hit with, on the same course with the same integrator and step. The engine is
 * deterministic, so each replayed stroke ends exactly (to the bit) where it ended in play;
 * {@link #matchesPlay()} checks that.
 */
public final class HoleReplay {
    private final World world;
    private final SimulationSettings settings;
    private final List<ShotRecord> shots;
    private int next;

    public HoleReplay(World world, SimulationSettings settings, List<ShotRecord> shots) {
        this.world = world;
        this.settings = settings;
        this.shots = List.copyOf(shots);
    }

    /** The replay of a game's hole so far. */
    public static HoleReplay of(Game game) {
        return new HoleReplay(game.world(), game.settings(), game.history());
    }

    /** The course the hole was played on. */
    public World world() {
        return world;
    }

    public List<ShotRecord> shots() {
        return shots;
    }

    /** Index of the stroke {@link #nextStroke} hands out next. */
    public int position() {
        return next;
    }

    public boolean hasNext() {
        return next < shots.size();
    }

    /** The next stroke, ready to be stepped (or run). */
    public Stroke nextStroke(TrajectoryListener listener) {
        ShotRecord r = shots.get(next++);
        return new Stroke(world, settings, r.startX(), r.startY(), r.vx(), r.vy(), r.vz(), r.clock(), listener, false);
    }

    /** Replays every stroke to its end; true if each ends with the outcome and at the very point recorded in play. */
    public boolean matchesPlay() {
        for (ShotRecord r : shots) {
            ShotResult res = new Stroke(world, settings, r.startX(), r.startY(), r.vx(), r.vy(), r.vz(), r.clock(), null, false).run();
            if (!matches(r, res)) return false;
        }
        return true;
    }

    static boolean matches(ShotRecord r, ShotResult res) {
        return res.outcome() == r.outcome()
                && Double.doubleToLongBits(res.endX()) == Double.doubleToLongBits(r.endX())
                && Double.doubleToLongBits(res.endY()) == Double.doubleToLongBits(r.endY());
    }

    /** True if the replayed stroke (run to its end) ended where play ended it. */
    public static boolean sameEnd(ShotRecord r, Stroke replayed) {
        return replayed.isFinished() && matches(r, replayed.result());
    }

    @Override
    public String toString() {
        return "replay of " + shots.size() + " strokes on " + world.course().name() + (next > 0 ? ", at " + next : "");
    }

    /** Whether a recorded stroke was holed (for the replay's captions). */
    public static boolean holed(ShotRecord r) {
        return r.outcome() == Outcome.HOLED;
    }
}
