package minigolf.expr;

/**
 * Prints a tree in the grammar with as few parentheses as keep its exact shape, so parsing the
 * text gives back a tree that evaluates to the same bits (floating-point addition is not
 * associative, so a+(b+c) keeps its parentheses).
 */
final class Printer {
    private static final int ATOM = 5;
    private static final int UNARY = 3;

    private Printer() {
    }

    static String print(Node node) {
        StringBuilder out = new StringBuilder();
        print(node, out);
        return out.toString();
    }

    private static void print(Node node, StringBuilder out) {
        if (node instanceof Node.Constant constant) {
            out.append(constantText(constant.value()));
        } else if (node instanceof Node.Variable variable) {
            out.append(variable.name());
        } else if (node instanceof Node.Negate negate) {
            out.append('-');
            printOperand(negate.operand(), precedence(negate.operand()) < BinaryOperator.POWER.precedence, out);
        } else if (node instanceof Node.Binary binary) {
            printBinary(binary, out);
        } else {
            Node.Call call = (Node.Call) node;
            out.append(call.function().functionName).append('(');
            for (int i = 0; i < call.arguments().size(); i++) {
                if (i > 0) {
                    out.append(", ");
                }
                print(call.argument(i), out);
            }
            out.append(')');
        }
    }

    private static void printBinary(Node.Binary binary, StringBuilder out) {
        BinaryOperator operator = binary.operator();
        int level = operator.precedence;
        int left = precedence(binary.left());
        int right = precedence(binary.right());
        if (operator == BinaryOperator.POWER) {
            // Right-associative: the base must be an atom, the exponent may itself be a power.
            printOperand(binary.left(), left < ATOM, out);
            out.append('^');
            printOperand(binary.right(), right < level, out);
            return;
        }
        printOperand(binary.left(), left < level, out);
        boolean spaced = level == BinaryOperator.ADD.precedence;
        out.append(spaced ? " " + operator.symbol + " " : String.valueOf(operator.symbol));
        printOperand(binary.right(), right <= level, out);
    }

    private static void printOperand(Node node, boolean parenthesize, StringBuilder out) {
        if (parenthesize) {
            out.append('(');
        }
        print(node, out);
        if (parenthesize) {
            out.append(')');
        }
    }

    private static int precedence(Node node) {
        if (node instanceof Node.Binary binary) {
            return binary.operator().precedence;
        }
        return node instanceof Node.Negate ? UNARY : ATOM;
    }

    /**
     * Double.toString gives the shortest text that reads back to the same double. Folding can
     * produce values no literal may spell (infinities, NaN), so those print as arithmetic on
     * finite literals that yields them.
     */
    private static String constantText(double value) {
        if (Double.isNaN(value)) {
            return "(1e308*10 - 1e308*10)";
        }
        if (Double.isInfinite(value)) {
            return value > 0 ? "(1e308*10)" : "(-1e308*10)";
        }
        String text = Double.toString(value);
        return text.startsWith("-") ? "(" + text + ")" : text;
    }
}
