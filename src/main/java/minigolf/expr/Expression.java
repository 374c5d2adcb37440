package minigolf.expr;

import java.util.IdentityHashMap;
import java.util.Map;

/**
 * A terrain height formula h(x, y) in a small, closed grammar (see {@link Parser}). Safe to parse
 * from untrusted course files: nothing but arithmetic and a fixed set of java.lang.Math functions
 * can be expressed, and hostile input is rejected with an {@link ExpressionException}.
 * Instances are immutable and thread-safe.
 */
public final class Expression {
    /** Derivatives grow their tree; this keeps every tree walk well inside the default stack. */
    private static final int MAX_DERIVED_HEIGHT = 8 * Parser.MAX_HEIGHT;

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
        if (height(derived, new IdentityHashMap<>()) > MAX_DERIVED_HEIGHT) {
            throw new ExpressionException("derivative too complex", 1,
                    "its tree would be more than " + MAX_DERIVED_HEIGHT + " levels deep");
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

    /** A parseable form of the expression. */
    @Override
    public String toString() {
        return Printer.print(tree);
    }

    private static int height(Node node, Map<Node, Integer> memo) {
        Integer known = memo.get(node);
        if (known != null) {
            return known;
        }
        int height = 1;
        if (node instanceof Node.Negate negate) {
            height += height(negate.operand(), memo);
        } else if (node instanceof Node.Binary binary) {
            height += Math.max(height(binary.left(), memo), height(binary.right(), memo));
        } else if (node instanceof Node.Call call) {
            for (Node argument : call.arguments()) {
                height = Math.max(height, 1 + height(argument, memo));
            }
        }
        memo.put(node, height);
        return height;
    }
}
