package minigolf.expr;

import java.util.List;

/**
 * Immutable syntax tree. Only the shapes the grammar can produce exist, so a tree can never
 * describe anything but arithmetic on x and y.
 */
sealed interface Node {

    record Constant(double value) implements Node {
    }

    /** {@code name} is 'x' or 'y'. */
    record Variable(char name) implements Node {
    }

    record Negate(Node operand) implements Node {
    }

    record Binary(BinaryOperator operator, Node left, Node right) implements Node {
    }

    record Call(MathFunction function, List<Node> arguments) implements Node {
        public Call {
            arguments = List.copyOf(arguments);
        }

        Node argument(int index) {
            return arguments.get(index);
        }
    }
}
