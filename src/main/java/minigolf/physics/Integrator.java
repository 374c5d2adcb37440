package minigolf.physics;

/** The numerical integrators the engine offers. */
public enum Integrator {
    EULER("euler", 1),
    RK2("rk2", 2),
    RK4("rk4", 4);

    private final String cliName;
    private final int order;

    Integrator(String cliName, int order) {
        this.cliName = cliName;
        this.order = order;
    }

    public String cliName() {
        return cliName;
    }

    /** The global order of accuracy: halving dt divides the error by 2^order. */
    public int order() {
        return order;
    }

    public static Integrator fromName(String name) {
        for (Integrator i : values()) {
            if (i.cliName.equalsIgnoreCase(name)) return i;
        }
        return null;
    }
}
