package minigolf.expr;

import java.util.ArrayList;
import java.util.List;

/**
 * Replaces every part that does not mention x or y by its value, bottom-up, so later stages
 * (evaluation, compilation, differentiation) see constants where the formula has them. Folding
 * applies each operation once to constant operands, exactly what evaluation would do at run time.
 */
final class ConstantFolder {
    private ConstantFolder() {
    }

    static Node fold(Node node) {
        if (node instanceof Node.Constant || node instanceof Node.Variable) {
            return node;
        }
        if (node instanceof Node.Negate negate) {
            Node operand = fold(negate.operand());
            return operand instanceof Node.Constant c ? new Node.Constant(-c.value()) : new Node.Negate(operand);
        }
        if (node instanceof Node.Binary binary) {
            Node left = fold(binary.left());
            Node right = fold(binary.right());
            if (left instanceof Node.Constant l && right instanceof Node.Constant r) {
                return new Node.Constant(binary.operator().apply(l.value(), r.value(), true));
            }
            return new Node.Binary(binary.operator(), left, right);
        }
        Node.Call call = (Node.Call) node;
        List<Node> arguments = new ArrayList<>();
        boolean allConstant = true;
        for (Node argument : call.arguments()) {
            Node folded = fold(argument);
            arguments.add(folded);
            allConstant &= folded instanceof Node.Constant;
        }
        if (allConstant) {
            double first = ((Node.Constant) arguments.get(0)).value();
            double second = arguments.size() == 2 ? ((Node.Constant) arguments.get(1)).value() : 0;
            return new Node.Constant(call.function().apply(first, second));
        }
        return new Node.Call(call.function(), arguments);
    }
}
