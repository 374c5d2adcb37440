package minigolf.expr;

import java.util.IdentityHashMap;
import java.util.Map;

/**
 * Symbolic differentiation by the chain rule. Results are built with {@link Simplifier}, so they are
 * folded and free of neutral terms, and use only the grammar, so they print in parseable form.
 * The formulas mirror the ones the bytecode compiler emits, so both agree to the last bit or two.
 */
final class Differentiator {
    /** Smallest positive double: max(|u|, it) equals |u| for every u except zero. */
    private static final Node TINY = new Node.Constant(Double.MIN_VALUE);
    private static final Node MINUS_TINY = new Node.Constant(-Double.MIN_VALUE);

    private final char variable;
    /** The tree may share subtrees (derivatives of derivatives do); derive each once. */
    private final Map<Node, Node> memo = new IdentityHashMap<>();

    private Differentiator(char variable) {
        this.variable = variable;
    }

    /** @param node a tree that has been through {@link ConstantFolder} */
    static Node derivative(Node node, char variable) {
        return new Differentiator(variable).derive(node);
    }

    private Node derive(Node node) {
        Node known = memo.get(node);
        if (known == null) {
            known = deriveUncached(node);
            memo.put(node, known);
        }
        return known;
    }

    private Node deriveUncached(Node node) {
        if (node instanceof Node.Constant) {
            return Simplifier.constant(0);
        }
        if (node instanceof Node.Variable v) {
            return Simplifier.constant(v.name() == variable ? 1 : 0);
        }
        if (node instanceof Node.Negate negate) {
            return Simplifier.negate(derive(negate.operand()));
        }
        if (node instanceof Node.Binary binary) {
            return binary(binary);
        }
        return call((Node.Call) node);
    }

    private Node binary(Node.Binary node) {
        Node u = node.left();
        Node w = node.right();
        Node du = derive(u);
        Node dw = derive(w);
        switch (node.operator()) {
            case ADD:
                return Simplifier.add(du, dw);
            case SUBTRACT:
                return Simplifier.subtract(du, dw);
            case MULTIPLY:
                return Simplifier.add(Simplifier.multiply(du, w), Simplifier.multiply(u, dw));
            case DIVIDE:
                // (u/w)' = (u' - (u/w)*w') / w reuses the quotient itself.
                return Simplifier.divide(Simplifier.subtract(du, Simplifier.multiply(node, dw)), w);
            case POWER:
                return power(node, u, w, du, dw);
            default:
                throw new AssertionError(node.operator());
        }
    }

    private static Node power(Node node, Node u, Node w, Node du, Node dw) {
        if (w instanceof Node.Constant c) {
            // c*u^(c-1)*u' stays defined for negative u, where the general form needs ln(u).
            Node factor = Simplifier.multiply(c, Simplifier.power(u, Simplifier.constant(c.value() - 1)));
            return Simplifier.multiply(factor, du);
        }
        Node baseTerm = Simplifier.multiply(
                Simplifier.multiply(w, Simplifier.power(u, Simplifier.subtract(w, Simplifier.constant(1)))), du);
        Node exponentTerm = Simplifier.multiply(
                Simplifier.multiply(node, Simplifier.call(MathFunction.LOG, u)), dw);
        return Simplifier.add(baseTerm, exponentTerm);
    }

    private Node call(Node.Call node) {
        Node u = node.argument(0);
        Node du = derive(u);
        switch (node.function()) {
            case SIN:
                return Simplifier.multiply(Simplifier.call(MathFunction.COS, u), du);
            case COS:
                return Simplifier.negate(Simplifier.multiply(Simplifier.call(MathFunction.SIN, u), du));
            case TAN:
                // 1 + tan^2 reuses the tangent already computed.
                return Simplifier.multiply(Simplifier.add(Simplifier.constant(1), square(node)), du);
            case ASIN:
                return Simplifier.divide(du, sqrtOfOneMinusSquare(u));
            case ACOS:
                return Simplifier.negate(Simplifier.divide(du, sqrtOfOneMinusSquare(u)));
            case ATAN:
                return Simplifier.divide(du, Simplifier.add(Simplifier.constant(1), square(u)));
            case ATAN2: {
                Node w = node.argument(1);
                Node dw = derive(w);
                Node numerator = Simplifier.subtract(Simplifier.multiply(w, du), Simplifier.multiply(u, dw));
                return Simplifier.divide(numerator, Simplifier.add(square(u), square(w)));
            }
            case EXP:
                return Simplifier.multiply(node, du);
            case LOG:
                return Simplifier.divide(du, u);
            case SQRT:
                return Simplifier.divide(du, Simplifier.multiply(Simplifier.constant(2), node));
            case ABS:
                return Simplifier.multiply(sign(u, node), du);
            case MIN:
                // Pick u' where u <= w (the first at ties): the second is picked when w - u < 0.
                return select(isNegative(Simplifier.subtract(node.argument(1), u)), du, derive(node.argument(1)));
            case MAX:
                // Pick u' where u >= w (the first at ties): the second is picked when u - w < 0.
                return select(isNegative(Simplifier.subtract(u, node.argument(1))), du, derive(node.argument(1)));
            case POW:
                throw new AssertionError("pow is parsed as the ^ operator");
            default:
                throw new AssertionError(node.function());
        }
    }

    private static Node square(Node u) {
        return Simplifier.power(u, Simplifier.constant(2));
    }

    private static Node sqrtOfOneMinusSquare(Node u) {
        return Simplifier.call(MathFunction.SQRT, Simplifier.subtract(Simplifier.constant(1), square(u)));
    }

    /**
     * sign(u) in the grammar: u / max(|u|, tiny) is exactly -1, 0 or 1 for finite u, because every
     * non-zero double is at least the smallest positive double in magnitude.
     */
    private static Node sign(Node u, Node absU) {
        return Simplifier.divide(u, Simplifier.call(MathFunction.MAX, absU, TINY));
    }

    /** 1 when t < 0, else 0, exactly: min(t,0)/min(t,-tiny) is t/t below zero and 0/(-tiny) above. */
    private static Node isNegative(Node t) {
        return Simplifier.divide(Simplifier.call(MathFunction.MIN, t, Simplifier.constant(0)),
                Simplifier.call(MathFunction.MIN, t, MINUS_TINY));
    }

    /** (1 - s)*first + s*second, which is exactly first or second when s is exactly 0 or 1. */
    private static Node select(Node s, Node first, Node second) {
        return Simplifier.add(Simplifier.multiply(Simplifier.subtract(Simplifier.constant(1), s), first),
                Simplifier.multiply(s, second));
    }
}
