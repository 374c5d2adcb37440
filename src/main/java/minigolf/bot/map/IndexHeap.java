package minigolf.bot.map;

import java.util.Arrays;

/** A binary min-heap of (index, key) pairs with lazy deletion: stale entries are skipped on pop. */
final class IndexHeap {
    private int[] items;
    private double[] keys;
    private int size;
    private final double[] best;

    IndexHeap(int indices) {
        items = new int[64];
        keys = new double[64];
        best = new double[indices];
        Arrays.fill(best, Double.POSITIVE_INFINITY);
    }

    boolean isEmpty() {
        skipStale();
        return size == 0;
    }

    void push(int item, double key) {
        if (key >= best[item]) return;
        best[item] = key;
        if (size == items.length) {
            items = Arrays.copyOf(items, size * 2);
            keys = Arrays.copyOf(keys, size * 2);
        }
        int i = size++;
        while (i > 0) {
            int parent = (i - 1) >> 1;
            if (keys[parent] <= key) break;
            items[i] = items[parent];
            keys[i] = keys[parent];
            i = parent;
        }
        items[i] = item;
        keys[i] = key;
    }

    int pop() {
        skipStale();
        return removeTop();
    }

    private void skipStale() {
        while (size > 0 && keys[0] > best[items[0]]) removeTop();
    }

    private int removeTop() {
        int top = items[0];
        size--;
        if (size > 0) {
            int item = items[size];
            double key = keys[size];
            int i = 0;
            while (true) {
                int child = 2 * i + 1;
                if (child >= size) break;
                if (child + 1 < size && keys[child + 1] < keys[child]) child++;
                if (keys[child] >= key) break;
                items[i] = items[child];
                keys[i] = keys[child];
                i = child;
            }
            items[i] = item;
            keys[i] = key;
        }
        return top;
    }
}
