package minigolf.expr;

/**
 * A terrain height formula h(x, y) in a small, closed grammar (see {@link Parser}). Safe to parse
 * from untrusted course files: nothing but arithmetic and a fixed set of java.lang.Math functions
 * can be expressed, and hostile input is rejected with an {@link ExpressionException}.
 * Instances are immutable and thread-safe.
 */
public final class Expression {
    /**
     * Derivatives grow their tree. These bounds keep every recursive tree walk well inside a default
     * thread stack and the printed form to some megabytes. The height bound holds for the first
     * derivative of anything the parser accepts (at most three levels per input level, plus a few);
     * the size bound only stops pathological inputs, such as long chains of quotients of large terms.
     */
    static final int MAX_DERIVED_HEIGHT = 1_000;
    static final long MAX_DERIVED_SIZE = 2_000_000;

    private final String source;
    /** The tree as written, for printing. */
    private final Node tree;
    /** The tree with constant parts folded: the meaning that evaluation and compilation share. */
    private final Node folded;

    private Expression(String source, Node tree) {
        this.source = source;
        this.tree = tree;
        this.folded = ConstantFolder.fold(tree);
    }

    /** @throws ExpressionException if the text is not a valid expression or exceeds a safety limit */
    public static Expression parse(String source) {
        return new Expression(source, Parser.parse(source));
    }

    /** The text this expression was parsed from (for derivatives: their printed form). */
    public String source() {
        return source;
    }

    /** Reference evaluation by walking the tree; slow but simple. */
    public double evaluate(double x, double y) {
        return Evaluator.evaluate(folded, x, y);
    }

    /**
     * The exact symbolic partial derivative, simplified.
     *
     * @param variable 'x' or 'y'
     * @throws IllegalArgumentException for any other variable
     * @throws ExpressionException if the result would be too large to handle safely
     */
    public Expression derivative(char variable) {
        if (variable != 'x' && variable != 'y') {
            throw new IllegalArgumentException("can only differentiate by 'x' or 'y', not '" + variable + "'");
        }
        Node derived = Differentiator.derivative(folded, variable);
        TreeMeasure measure = new TreeMeasure();
        if (measure.height(derived) > MAX_DERIVED_HEIGHT) {
            throw new ExpressionException("derivative too complex", 1,
                    "its tree would be more than " + MAX_DERIVED_HEIGHT + " levels deep");
        }
        if (measure.size(derived) > MAX_DERIVED_SIZE) {
            throw new ExpressionException("derivative too complex", 1,
                    "it would have more than " + MAX_DERIVED_SIZE + " operations");
        }
        return new Expression(Printer.print(derived), derived);
    }

    /**
     * Compiles to JVM bytecode for fast repeated evaluation.
     *
     * @throws ExpressionException if the expression is too large for one JVM method
     */
    public CompiledExpression compile() {
        return BytecodeCompiler.compile(folded, source);
    }

    /** Whether the height is smooth wherever it is finite (no crease, kink or branch cut: {@link Smoothness}). */
    public boolean isSmooth() {
        return Smoothness.isSmooth(folded);
    }

    /** A parseable form of the expression. */
    @Override
    public String toString() {
        return Printer.print(tree);
    }
}
