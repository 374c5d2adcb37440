package minigolf.expr;

import java.util.List;

/**
 * Smart constructors that fold constants and drop neutral terms (0*a = 0, 1*a = a, a+0 = a, ...)
 * while building a tree. The derivative uses them, so d/dx of a term without x vanishes on the spot.
 * The identities only touch the sign of zero, except 0*a = 0, which is the usual convention for a
 * derivative that is exactly zero.
 */
final class Simplifier {
    private static final Node ZERO = new Node.Constant(0);
    private static final Node ONE = new Node.Constant(1);

    private Simplifier() {
    }

    static Node constant(double value) {
        return value == 0 && 1 / value > 0 ? ZERO : value == 1 ? ONE : new Node.Constant(value);
    }

    static boolean isConstant(Node node, double value) {
        return node instanceof Node.Constant c && c.value() == value;
    }

    static Node negate(Node operand) {
        if (operand instanceof Node.Constant c) {
            return constant(-c.value());
        }
        if (operand instanceof Node.Negate n) {
            return n.operand();
        }
        return new Node.Negate(operand);
    }

    static Node add(Node a, Node b) {
        if (a instanceof Node.Constant ca && b instanceof Node.Constant cb) {
            return constant(ca.value() + cb.value());
        }
        if (isConstant(a, 0)) {
            return b;
        }
        if (isConstant(b, 0)) {
            return a;
        }
        if (b instanceof Node.Negate nb) {
            return subtract(a, nb.operand());
        }
        if (a instanceof Node.Negate na) {
            return subtract(b, na.operand());
        }
        return new Node.Binary(BinaryOperator.ADD, a, b);
    }

    static Node subtract(Node a, Node b) {
        if (a instanceof Node.Constant ca && b instanceof Node.Constant cb) {
            return constant(ca.value() - cb.value());
        }
        if (isConstant(b, 0)) {
            return a;
        }
        if (isConstant(a, 0)) {
            return negate(b);
        }
        if (b instanceof Node.Negate nb) {
            return add(a, nb.operand());
        }
        return new Node.Binary(BinaryOperator.SUBTRACT, a, b);
    }

    static Node multiply(Node a, Node b) {
        if (a instanceof Node.Constant ca && b instanceof Node.Constant cb) {
            return constant(ca.value() * cb.value());
        }
        if (isConstant(a, 0) || isConstant(b, 0)) {
            return ZERO;
        }
        if (isConstant(a, 1)) {
            return b;
        }
        if (isConstant(b, 1)) {
            return a;
        }
        if (isConstant(a, -1)) {
            return negate(b);
        }
        if (isConstant(b, -1)) {
            return negate(a);
        }
        // Signs move outward exactly in IEEE arithmetic, which keeps products tidy.
        if (a instanceof Node.Negate na) {
            return negate(multiply(na.operand(), b));
        }
        if (b instanceof Node.Negate nb) {
            return negate(multiply(a, nb.operand()));
        }
        // Constants first reads naturally (2*x) and is exact, since multiplication commutes.
        if (b instanceof Node.Constant && !(a instanceof Node.Constant)) {
            return new Node.Binary(BinaryOperator.MULTIPLY, b, a);
        }
        return new Node.Binary(BinaryOperator.MULTIPLY, a, b);
    }

    static Node divide(Node a, Node b) {
        if (a instanceof Node.Constant ca && b instanceof Node.Constant cb) {
            return constant(ca.value() / cb.value());
        }
        if (isConstant(a, 0)) {
            return ZERO;
        }
        if (isConstant(b, 1)) {
            return a;
        }
        if (isConstant(b, -1)) {
            return negate(a);
        }
        if (a instanceof Node.Negate na) {
            return negate(divide(na.operand(), b));
        }
        if (b instanceof Node.Negate nb) {
            return negate(divide(a, nb.operand()));
        }
        return new Node.Binary(BinaryOperator.DIVIDE, a, b);
    }

    static Node power(Node base, Node exponent) {
        if (base instanceof Node.Constant cb && exponent instanceof Node.Constant ce) {
            return constant(Powers.constantPower(cb.value(), ce.value()));
        }
        if (isConstant(exponent, 1)) {
            return base;
        }
        if (isConstant(exponent, 0)) {
            return ONE;
        }
        return new Node.Binary(BinaryOperator.POWER, base, exponent);
    }

    static Node call(MathFunction function, Node... arguments) {
        boolean allConstant = true;
        for (Node argument : arguments) {
            allConstant &= argument instanceof Node.Constant;
        }
        if (allConstant) {
            double first = ((Node.Constant) arguments[0]).value();
            double second = arguments.length == 2 ? ((Node.Constant) arguments[1]).value() : 0;
            return constant(function.apply(first, second));
        }
        return new Node.Call(function, List.of(arguments));
    }
}
