package minigolf.editor;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * A change of grid nodes: heights and/or friction, old and new value per touched node. Brushes
 * record into a {@link Recorder} while they change the course live; the finished recording is
 * the undoable edit of the whole stroke.
 */
final class NodeEdit implements Edit {
    private final String label;
    private final int[] index;
    private final double[] oldH, newH, oldK, newK, oldS, newS;
    /** The friction arrays did not exist before this edit: revert removes them again. */
    private final boolean createsFriction;
    private final int i0, j0, i1, j1;

    private NodeEdit(String label, int[] index, double[][] values, boolean createsFriction, int columns) {
        this.label = label;
        this.index = index;
        this.oldH = values[0];
        this.newH = values[1];
        this.oldK = values[2];
        this.newK = values[3];
        this.oldS = values[4];
        this.newS = values[5];
        this.createsFriction = createsFriction;
        int a = Integer.MAX_VALUE, b = Integer.MAX_VALUE, c = -1, d = -1;
        for (int k : index) {
            a = Math.min(a, k % columns);
            c = Math.max(c, k % columns);
            b = Math.min(b, k / columns);
            d = Math.max(d, k / columns);
        }
        i0 = a;
        j0 = b;
        i1 = c;
        j1 = d;
    }

    int size() {
        return index.length;
    }

    @Override
    public void apply(EditableCourse c, ChangeSet changes) {
        if (createsFriction) Recorder.createFriction(c);
        write(c, newH, newK, newS);
        changes.nodes(i0, j0, i1, j1);
    }

    @Override
    public void revert(EditableCourse c, ChangeSet changes) {
        write(c, oldH, oldK, oldS);
        if (createsFriction) {
            c.kinetic = null;
            c.statics = null;
        }
        changes.nodes(i0, j0, i1, j1);
    }

    private void write(EditableCourse c, double[] h, double[] k, double[] s) {
        for (int n = 0; n < index.length; n++) {
            c.heights[index[n]] = h[n];
            if (c.kinetic != null) {
                c.kinetic[index[n]] = k[n];
                c.statics[index[n]] = s[n];
            }
        }
    }

    @Override
    public String label() {
        return label;
    }

    /** Records node changes made live (first old value per node wins) and builds the edit. */
    static final class Recorder {
        private final EditableCourse course;
        private final String label;
        private final boolean createsFriction;
        private final Map<Integer, double[]> old = new HashMap<>();
        private final ChangeSet changes;

        Recorder(EditableCourse course, String label, boolean touchesFriction, ChangeSet changes) {
            this.course = course;
            this.label = label;
            this.changes = changes;
            this.createsFriction = touchesFriction && course.kinetic == null;
            if (createsFriction) createFriction(course);
        }

        static void createFriction(EditableCourse c) {
            if (c.kinetic != null) return;
            c.kinetic = new double[c.heights.length];
            c.statics = new double[c.heights.length];
            Arrays.fill(c.kinetic, c.properties.physics().kineticFriction());
            Arrays.fill(c.statics, c.properties.physics().staticFriction());
        }

        private void remember(int k) {
            old.computeIfAbsent(k, key -> new double[]{course.heights[key],
                    course.kinetic != null ? course.kinetic[key] : 0, course.statics != null ? course.statics[key] : 0});
            changes.nodes(k % course.columns, k / course.columns, k % course.columns, k / course.columns);
        }

        void setHeight(int i, int j, double h) {
            int k = j * course.columns + i;
            remember(k);
            course.heights[k] = h;
        }

        void setFriction(int i, int j, double kinetic, double statics) {
            int k = j * course.columns + i;
            remember(k);
            course.kinetic[k] = kinetic;
            course.statics[k] = statics;
        }

        boolean isEmpty() {
            return old.isEmpty() && !createsFriction;
        }

        /** The edit, already applied to the course. */
        NodeEdit finish() {
            int n = old.size();
            int[] index = old.keySet().stream().mapToInt(Integer::intValue).sorted().toArray();
            double[][] v = new double[6][n];
            for (int m = 0; m < n; m++) {
                int k = index[m];
                double[] o = old.get(k);
                v[0][m] = o[0];
                v[1][m] = course.heights[k];
                v[2][m] = o[1];
                v[3][m] = course.kinetic != null ? course.kinetic[k] : 0;
                v[4][m] = o[2];
                v[5][m] = course.statics != null ? course.statics[k] : 0;
            }
            return new NodeEdit(label, index, v, createsFriction, course.columns);
        }
    }
}
