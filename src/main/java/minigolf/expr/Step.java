package minigolf.expr;

/**
 * One distinct sub-result of a compiled expression: {@code node} tells the operation, and
 * {@code first} and {@code second} are the indices of earlier steps holding its operands (-1: none).
 */
record Step(Node node, int first, int second) {
}
