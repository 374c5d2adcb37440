package minigolf.terrain;

import minigolf.expr.CompiledExpression;
import minigolf.expr.Expression;

/** A terrain given by a height expression, compiled to bytecode with an exact symbolic gradient. */
public final class ExpressionTerrain implements Terrain {
    private final Expression expression;
    private final CompiledExpression compiled;
    private final boolean smooth;

    /** @throws minigolf.expr.ExpressionException if the source is not a valid expression */
    public ExpressionTerrain(String source) {
        this.expression = Expression.parse(source);
        this.compiled = expression.compile();
        this.smooth = expression.isSmooth();
    }

    @Override
    public boolean isSmooth() {
        return smooth;
    }

    public Expression expression() {
        return expression;
    }

    @Override
    public double height(double x, double y) {
        return compiled.value(x, y);
    }

    @Override
    public void sample(double x, double y, double[] out) {
        compiled.valueAndGradient(x, y, out);
    }
}
