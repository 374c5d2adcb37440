package minigolf.expr;

/**
 * A height function compiled to JVM bytecode by {@link Expression#compile()}. Implementations are
 * stateless and thread-safe.
 */
public interface CompiledExpression {

    /** The height h(x, y). */
    double value(double x, double y);

    /** Writes h, dh/dx, dh/dy into out[0], out[1], out[2]. */
    void valueAndGradient(double x, double y, double[] out);
}
