package minigolf.expr;

/** Reference tree-walking evaluation: simple and obviously right, used to check the compiled code. */
final class Evaluator {
    private Evaluator() {
    }

    static double evaluate(Node node, double x, double y) {
        if (node instanceof Node.Constant constant) {
            return constant.value();
        }
        if (node instanceof Node.Variable variable) {
            return variable.name() == 'x' ? x : y;
        }
        if (node instanceof Node.Negate negate) {
            return -evaluate(negate.operand(), x, y);
        }
        if (node instanceof Node.Binary binary) {
            double left = evaluate(binary.left(), x, y);
            double right = evaluate(binary.right(), x, y);
            return binary.operator().apply(left, right, binary.right() instanceof Node.Constant);
        }
        Node.Call call = (Node.Call) node;
        double first = evaluate(call.argument(0), x, y);
        double second = call.function().arity == 2 ? evaluate(call.argument(1), x, y) : 0;
        return call.function().apply(first, second);
    }
}
