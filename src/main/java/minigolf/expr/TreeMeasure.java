package minigolf.expr;

import java.util.IdentityHashMap;
import java.util.Map;

/**
 * Height and written-out size of a tree whose subtrees may be shared (derivatives reuse parts of
 * their input). Both are computed over the shared structure, so measuring is cheap even when
 * writing the tree out would not be; the size saturates instead of overflowing.
 */
final class TreeMeasure {
    private final Map<Node, Integer> heights = new IdentityHashMap<>();
    private final Map<Node, Long> sizes = new IdentityHashMap<>();

    int height(Node node) {
        Integer known = heights.get(node);
        if (known != null) {
            return known;
        }
        int height = 0;
        for (Node child : children(node)) {
            height = Math.max(height, height(child));
        }
        heights.put(node, height + 1);
        return height + 1;
    }

    long size(Node node) {
        Long known = sizes.get(node);
        if (known != null) {
            return known;
        }
        long size = 1;
        for (Node child : children(node)) {
            size = Math.min(Long.MAX_VALUE / 4, size + size(child));
        }
        sizes.put(node, size);
        return size;
    }

    private static Iterable<Node> children(Node node) {
        if (node instanceof Node.Negate negate) {
            return java.util.List.of(negate.operand());
        }
        if (node instanceof Node.Binary binary) {
            return java.util.List.of(binary.left(), binary.right());
        }
        if (node instanceof Node.Call call) {
            return call.arguments();
        }
        return java.util.List.of();
    }
}
