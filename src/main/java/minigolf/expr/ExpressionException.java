package minigolf.expr;

/**
 * Thrown when an expression cannot be accepted: a syntax error, a name outside the grammar,
 * or input that exceeds the safety limits. Unchecked, so course loaders can catch it in one place.
 */
public final class ExpressionException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final int column;

    /**
     * @param problem what is wrong, e.g. {@code "unknown function 'foo'"}
     * @param column  1-based column of the offending character
     * @param hint    extra guidance appended in parentheses, or null
     */
    public ExpressionException(String problem, int column, String hint) {
        super(problem + " at column " + column + (hint == null ? "" : " (" + hint + ")"));
        this.column = column;
    }

    public ExpressionException(String problem, int column) {
        this(problem, column, null);
    }

    /** 1-based column of the offending character. */
    public int column() {
        return column;
    }
}
