package minigolf.physics;

/** Runs whole strokes on one world with one set of settings. Cheap to create; not shared across threads. */
public final class Simulator {
    private final World world;
    private final SimulationSettings settings;

    public Simulator(World world, SimulationSettings settings) {
        this.world = world;
        this.settings = settings;
    }

    public World world() {
        return world;
    }

    public SimulationSettings settings() {
        return settings;
    }

    public ShotResult simulate(double x0, double y0, double vx, double vy) {
        return new Stroke(world, settings, x0, y0, vx, vy, null).run();
    }

    public ShotResult simulate(double x0, double y0, double vx, double vy, TrajectoryListener listener) {
        return new Stroke(world, settings, x0, y0, vx, vy, listener).run();
    }

    /** A shot with a vertical component (a chip when vz &gt; 0); no events recorded. */
    public ShotResult simulate(double x0, double y0, double vx, double vy, double vz) {
        return new Stroke(world, settings, x0, y0, vx, vy, vz, null, false).run();
    }

    /** A shot with a vertical component, its events recorded in the result ({@link ShotResult#events()}). */
    public ShotResult simulate(double x0, double y0, double vx, double vy, double vz, TrajectoryListener listener) {
        return new Stroke(world, settings, x0, y0, vx, vy, vz, listener, true).run();
    }

    /**
     * A shot played at course clock {@code clock} (s), where moving obstacles make the moment
     * matter (docs/course-format.md, "Moving obstacles"); no events recorded.
     */
    public ShotResult simulateAt(double clock, double x0, double y0, double vx, double vy, double vz) {
        return new Stroke(world, settings, x0, y0, vx, vy, vz, clock, null, false).run();
    }

    /** A putt played at course clock {@code clock}, its states to the listener (events not recorded). */
    public ShotResult simulatePuttAt(double clock, double x0, double y0, double vx, double vy, TrajectoryListener listener) {
        return new Stroke(world, settings, x0, y0, vx, vy, 0, clock, listener, false).run();
    }

    /** As {@link #simulateAt(double, double, double, double, double, double)}, its events recorded in the result. */
    public ShotResult simulateAt(double clock, double x0, double y0, double vx, double vy, double vz,
                                 TrajectoryListener listener) {
        return new Stroke(world, settings, x0, y0, vx, vy, vz, clock, listener, true).run();
    }
}
