package minigolf.expr;

/** The infix operators, with the precedence the parser and printer agree on. */
enum BinaryOperator {
    ADD('+', 1),
    SUBTRACT('-', 1),
    MULTIPLY('*', 2),
    DIVIDE('/', 2),
    /** Binds tighter than unary minus (level 3) and is right-associative. */
    POWER('^', 4);

    final char symbol;
    final int precedence;

    BinaryOperator(char symbol, int precedence) {
        this.symbol = symbol;
        this.precedence = precedence;
    }

    /**
     * Applies the operator. {@code constantExponent} tells whether the right side of a power is a
     * constant, because constant integer exponents are computed by multiplication (see {@link Powers}).
     */
    double apply(double left, double right, boolean constantExponent) {
        switch (this) {
            case ADD:
                return left + right;
            case SUBTRACT:
                return left - right;
            case MULTIPLY:
                return left * right;
            case DIVIDE:
                return left / right;
            case POWER:
                return constantExponent ? Powers.constantPower(left, right) : Math.pow(left, right);
            default:
                throw new AssertionError(this);
        }
    }
}
