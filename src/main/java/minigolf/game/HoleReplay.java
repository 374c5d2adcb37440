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
 * {@link #matchesPlay()} checks that. What strokes change on the course (bricks) is rebuilt the
 * same way: each stroke is played on the course as the ones before it left it.
 */
public final class HoleReplay {
    private final World world;
    private final SimulationSettings settings;
    private final List<ShotRecord> shots;
    private int next;
    /** The course as the strokes handed out so far leave it (bricks broken), for the next one. */
    private World now;
    private Stroke last;

    public HoleReplay(World world, SimulationSettings settings, List<ShotRecord> shots) {
        this.world = world;
        this.settings = settings;
        this.shots = List.copyOf(shots);
        this.now = world;
    }

    /** The replay of a game's hole so far. */
    public static HoleReplay of(Game game) {
        return new HoleReplay(game.startWorld(), game.settings(), game.history());
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
        if (last != null) now = now.withState(last.runOrEndOutOfPlay().state());
        last = new Stroke(now, settings, r.startX(), r.startY(), r.vx(), r.vy(), r.vz(), r.clock(), listener, false);
        return last;
    }

    /** The course as the replay stands: the state the next stroke is played on (after the last one handed out ends). */
    public World courseNow() {
        return last == null ? now : now.withState(last.isFinished() ? last.result().state() : last.state());
    }

    /** Replays every stroke to its end; true if each ends with the outcome and at the very point recorded in play. */
    public boolean matchesPlay() {
        World w = world;
        for (ShotRecord r : shots) {
            ShotResult res = new Stroke(w, settings, r.startX(), r.startY(), r.vx(), r.vy(), r.vz(), r.clock(), null, false).run();
            if (!matches(r, res)) return false;
            w = w.withState(res.state());
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
