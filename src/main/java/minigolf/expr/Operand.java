package minigolf.expr;

/**
 * Where generated code finds a double: a constant known while compiling, or a local variable slot.
 * Knowing constants (above all zero and one) lets the compiler skip derivative work entirely.
 */
record Operand(int slot, double constant) {
    static final Operand ZERO = constant(0);
    static final Operand ONE = constant(1);

    static Operand constant(double value) {
        return new Operand(-1, value);
    }

    static Operand local(int slot) {
        return new Operand(slot, 0);
    }

    boolean isConstant() {
        return slot < 0;
    }

    boolean is(double value) {
        return isConstant() && constant == value;
    }
}
