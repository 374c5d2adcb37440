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
