package minigolf.expr;

import java.util.ArrayDeque;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.Set;

/**
 * Whether a height formula is smooth everywhere it is finite: no crease (abs, min, max), no kink
 * or infinite slope at a point (sqrt, a non-integer power, asin, acos) and no branch cut (atan2).
 * On such ground the engine may take long steps (docs/physics.md, "Step control"); elsewhere a
 * crease inside a long step would cost its order.
 */
final class Smoothness {
    private Smoothness() {
    }

    static boolean isSmooth(Node root) {
        Set<Node> seen = Collections.newSetFromMap(new IdentityHashMap<>());
        ArrayDeque<Node> open = new ArrayDeque<>();
        open.push(root);
        while (!open.isEmpty()) {
            Node node = open.pop();
            if (!seen.add(node)) continue;
            if (node instanceof Node.Negate negate) {
                open.push(negate.operand());
            } else if (node instanceof Node.Binary binary) {
                if (binary.operator() == BinaryOperator.POWER && !isWholeExponent(binary.right())) return false;
                open.push(binary.left());
                open.push(binary.right());
            } else if (node instanceof Node.Call call) {
                switch (call.function()) {
                    case ABS, MIN, MAX, SQRT, ASIN, ACOS, ATAN2:
                        return false;
                    case POW:
                        if (!isWholeExponent(call.argument(1))) return false;
                        break;
                    default:
                        break;
                }
                call.arguments().forEach(open::push);
            }
        }
        return true;
    }

    /** A constant whole exponent from 0 up: x^2 is smooth, x^0.5 is not at 0. */
    private static boolean isWholeExponent(Node exponent) {
        return exponent instanceof Node.Constant c && c.value() >= 0 && c.value() == Math.rint(c.value());
    }
}
