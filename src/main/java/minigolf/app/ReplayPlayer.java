package minigolf.app;

import java.util.List;
import java.util.function.Supplier;
import minigolf.game.HoleReplay;
import minigolf.game.Player;
import minigolf.game.ShotRecord;
import minigolf.game.StrokeAnimator;
import minigolf.physics.TrajectoryListener;

/**
 * Watching a hole again: its strokes animated one after another, each from where it was hit with
 * the velocity it was hit with, and each checked against where it ended in play (the engine is
 * deterministic, so a mismatch is a bug).
 */
final class ReplayPlayer {
    /** What a frame of the replay did. */
    enum Step { ROLLING, STROKE_STARTED, OVER }

    private HoleReplay replay;
    private StrokeAnimator animator;
    /** The course clock the last frame of the replay showed. */
    private double lastClock;
    private ShotRecord shot;
    private int replayed, mismatches;

    /** The bricks standing as the replay stands (null when none is running). */
    minigolf.physics.CourseState courseNow() {
        return replay == null ? null : replay.courseNow().state();
    }

    void start(HoleReplay r) {
        replay = r;
        animator = null;
        shot = null;
        replayed = 0;
        mismatches = 0;
    }

    void stop() {
        replay = null;
        animator = null;
    }

    /** Advances the rolling stroke by {@code elapsed} seconds; starts the next when it has ended. */
    Step advance(double elapsed, double timeScale, double dt, Supplier<TrajectoryListener> listener) {
        if (animator != null) {
            animator.advance(elapsed, timeScale);
            lastClock = animator.clock();
            if (!animator.isFinished()) return Step.ROLLING;
            replayed++;
            if (!HoleReplay.sameEnd(shot, animator.stroke())) mismatches++;
            animator = null;
        }
        if (!replay.hasNext()) return Step.OVER;
        shot = replay.shots().get(replay.position());
        animator = new StrokeAnimator(replay.nextStroke(listener.get()), dt);
        return Step.STROKE_STARTED;
    }

    /** The rolling stroke's animation, or null between strokes and when no replay runs. */
    double lastClock() {
        return lastClock;
    }

    StrokeAnimator animator() {
        return animator;
    }

    /** The stroke being replayed (its player, its velocity), or null before the first. */
    ShotRecord shot() {
        return shot;
    }

    /** Strokes replayed and how many ended elsewhere than in play. */
    int[] counts() {
        return new int[]{replayed, mismatches};
    }

    /** "Replay: stroke 2 of 3 - Ann", or null when nothing is replayed yet. */
    String caption(List<Player> players) {
        if (replay == null || shot == null) return null;
        return "Replay: stroke " + replay.position() + " of " + replay.shots().size() + " - " + players.get(shot.player()).name();
    }
}
