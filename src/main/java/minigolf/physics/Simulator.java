package minigolf.physics;

/**
 * Runs whole strokes on one world with one set of settings. It builds the parts of a stroke once
 * and starts them again for every shot, so a shot without listener or events allocates only its
 * result. Cheap to create; not shared across threads.
 */
public final class Simulator {
    private final World world;
    private final SimulationSettings settings;
    /** The stroke reused for every shot; built on the first. */
    private Stroke stroke;

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
        return run(0, x0, y0, vx, vy, 0, null, false);
    }

    public ShotResult simulate(double x0, double y0, double vx, double vy, TrajectoryListener listener) {
        return run(0, x0, y0, vx, vy, 0, listener, false);
    }

    /** A shot with a vertical component (a chip when vz &gt; 0); no events recorded. */
    public ShotResult simulate(double x0, double y0, double vx, double vy, double vz) {
        return run(0, x0, y0, vx, vy, vz, null, false);
    }

    /** A shot with a vertical component, its events recorded in the result ({@link ShotResult#events()}). */
    public ShotResult simulate(double x0, double y0, double vx, double vy, double vz, TrajectoryListener listener) {
        return run(0, x0, y0, vx, vy, vz, listener, true);
    }

    /** A shot with a vertical component, heard by the listener; its events recorded in the result only if asked. */
    public ShotResult simulate(double x0, double y0, double vx, double vy, double vz, TrajectoryListener listener,
                               boolean recordEvents) {
        return run(0, x0, y0, vx, vy, vz, listener, recordEvents);
    }

    /**
     * A shot played at course clock {@code clock} (s), where moving obstacles make the moment
     * matter (docs/course-format.md, "Moving obstacles"); no events recorded.
     */
    public ShotResult simulateAt(double clock, double x0, double y0, double vx, double vy, double vz) {
        return run(clock, x0, y0, vx, vy, vz, null, false);
    }

    /** A putt played at course clock {@code clock}, its states to the listener (events not recorded). */
    public ShotResult simulatePuttAt(double clock, double x0, double y0, double vx, double vy, TrajectoryListener listener) {
        return run(clock, x0, y0, vx, vy, 0, listener, false);
    }

    /** As {@link #simulateAt(double, double, double, double, double, double)}, heard by the listener; events recorded only if asked. */
    public ShotResult simulateAt(double clock, double x0, double y0, double vx, double vy, double vz,
                                 TrajectoryListener listener, boolean recordEvents) {
        return run(clock, x0, y0, vx, vy, vz, listener, recordEvents);
    }

    /** As {@link #simulateAt(double, double, double, double, double, double)}, its events recorded in the result. */
    public ShotResult simulateAt(double clock, double x0, double y0, double vx, double vy, double vz,
                                 TrajectoryListener listener) {
        return run(clock, x0, y0, vx, vy, vz, listener, true);
    }

    private ShotResult run(double clock, double x0, double y0, double vx, double vy, double vz, TrajectoryListener listener,
                           boolean recordEvents) {
        Stroke s = stroke;
        // A listener that simulates on this simulator while its stroke runs gets a stroke of its own.
        if (s == null || s.running) {
            s = new Stroke(world, settings);
            if (stroke == null) stroke = s;
        }
        s.running = true;
        try {
            s.start(x0, y0, vx, vy, vz, clock, listener, recordEvents, false);
            return s.run();
        } finally {
            s.running = false;
        }
    }
}
