package minigolf.editor;

/** Friction presets for the paint tool (values within the ranges of docs/physics.md's sources). */
public enum Surface {
    /** A putting green. */
    GRASS("grass", 0.08, 0.2),
    /** A bunker: the ball stops quickly and stays on slopes. */
    SAND("sand", 0.45, 0.6);

    private final String label;
    private final double kinetic, statics;

    Surface(String label, double kinetic, double statics) {
        this.label = label;
        this.kinetic = kinetic;
        this.statics = statics;
    }

    public String label() {
        return label;
    }

    public double kineticFriction() {
        return kinetic;
    }

    public double staticFriction() {
        return statics;
    }
}
