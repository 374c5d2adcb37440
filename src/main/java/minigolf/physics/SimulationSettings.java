package minigolf.physics;

/**
 * How a stroke is integrated. The game, the bots and the command line all take the defaults
 * unless a user asks otherwise.
 *
 * @param maxTime safety limit on simulated time of one stroke, in seconds
 */
public record SimulationSettings(Integrator integrator, double dt, double maxTime) {
    public static final double DEFAULT_DT = 1.0 / 60.0;
    public static final double DEFAULT_MAX_TIME = 600.0;
    public static final SimulationSettings DEFAULT = new SimulationSettings(Integrator.RK4, DEFAULT_DT, DEFAULT_MAX_TIME);
    /**
     * The steps a user may choose, in the settings, a saved game or on the command line: 1/1000 to
     * 1/30 s (a 600 s stroke is then at most 600,000 steps; tests may go finer through the constructor).
     */
    public static final double MIN_DT = 1.0 / 1000, MAX_DT = 1.0 / 30;

    /** "must be 1/1000 to 1/30 s, got X", or null for a step a user may choose. */
    public static String dtProblem(double dt) {
        return dt >= MIN_DT && dt <= MAX_DT ? null : "must be 1/1000 to 1/30 s (0.001 to 0.0333), got " + dt;
    }

    public SimulationSettings {
        if (integrator == null) throw new IllegalArgumentException("integrator must be given");
        if (!(dt > 0) || dt > 0.1) throw new IllegalArgumentException("dt must be in (0, 0.1] s, got " + dt);
        if (!(maxTime > 0)) throw new IllegalArgumentException("maxTime must be > 0, got " + maxTime);
    }

    public SimulationSettings withIntegrator(Integrator newIntegrator) {
        return new SimulationSettings(newIntegrator, dt, maxTime);
    }

    public SimulationSettings withDt(double newDt) {
        return new SimulationSettings(integrator, newDt, maxTime);
    }
}
