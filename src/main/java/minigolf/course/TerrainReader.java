package minigolf.course;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import minigolf.expr.Expression;
import minigolf.expr.ExpressionException;

import static minigolf.course.CourseLoader.GRID_FIELDS;
import static minigolf.course.CourseLoader.TERRAIN_FIELDS;

/** Reads a course file's {@code terrain}: a height expression (compiled to check it) or a height grid with its friction and deleted cells. */
final class TerrainReader extends CourseJsonReader {
    TerrainReader(String source) {
        super(source);
    }

    TerrainSpec terrain(JsonNode n, String path) throws CourseException {
        ObjectNode o = object(n, path);
        knownFields(o, path, TERRAIN_FIELDS);
        boolean hasHeight = o.has("height"), hasGrid = o.has("grid");
        if (hasHeight == hasGrid) {
            throw error(path, "expected exactly one of height, grid, got " + (hasHeight ? "both" : "neither"));
        }
        if (hasHeight) {
            String p = join(path, "height");
            String src = string(o.get("height"), p);
            if (src.isBlank()) throw error(p, "must be a non-empty expression");
            try {
                // Compiling checks the evaluation cost (the generated code must fit the JVM's limits).
                Expression.parse(src).compile();
            } catch (ExpressionException e) {
                String msg = String.valueOf(e.getMessage());
                throw error(p, msg.contains("column") ? msg : msg + " at column " + e.column());
            } catch (RuntimeException e) {
                throw error(p, "invalid expression: " + e.getMessage());
            }
            return new TerrainSpec.HeightExpression(src);
        }
        return grid(o.get("grid"), join(path, "grid"));
    }

    TerrainSpec.HeightGrid grid(JsonNode n, String path) throws CourseException {
        ObjectNode o = object(n, path);
        knownFields(o, path, GRID_FIELDS);
        Vec2 origin = vec(required(o, path, "origin"), join(path, "origin"));
        double spacing = positive(number(required(o, path, "spacing"), join(path, "spacing")), join(path, "spacing"));
        String hp = join(path, "heights");
        JsonNode hn = required(o, path, "heights");
        if (hn.isArray() && hn.size() > 0 && hn.get(0).isArray()) {
            long nodes = (long) hn.size() * hn.get(0).size();
            if (nodes > Limits.GRID_NODES) {
                throw error(hp, "too many grid nodes: " + hn.size() + " rows of " + hn.get(0).size() + " = " + nodes
                        + " (the limit is " + Limits.GRID_NODES + ")");
            }
        }
        double[][] heights = matrix(required(o, path, "heights"), hp, -1, -1, false);
        if (heights.length < 2 || heights[0].length < 2) {
            throw error(hp, "must have at least 2 rows of at least 2 values (bicubic interpolation needs a 2x2 grid), got "
                    + heights.length + " row" + (heights.length == 1 ? "" : "s") + " of "
                    + (heights.length == 0 ? 0 : heights[0].length));
        }
        int rows = heights.length, cols = heights[0].length;
        double[][] kinetic = o.has("kineticFriction")
                ? matrix(o.get("kineticFriction"), join(path, "kineticFriction"), rows, cols, true) : null;
        double[][] stat = o.has("staticFriction")
                ? matrix(o.get("staticFriction"), join(path, "staticFriction"), rows, cols, true) : null;
        boolean[][] deleted = o.has("deletedCells")
                ? deletedCells(o.get("deletedCells"), join(path, "deletedCells"), rows - 1, cols - 1) : null;
        return new TerrainSpec.HeightGrid(origin, spacing, heights, kinetic, stat, deleted);
    }

    /** {@code [[i, j], ...]}: the cells (column i, row j) removed from the course, each listed once. */
    boolean[][] deletedCells(JsonNode n, String path, int cellRows, int cellCols) throws CourseException {
        if (!n.isArray()) throw error(path, "expected an array of [i, j] cell indices, got " + kind(n));
        if ((long) n.size() > (long) cellRows * cellCols) {
            throw error(path, "lists " + n.size() + " cells but the grid has only " + (long) cellRows * cellCols);
        }
        boolean[][] mask = new boolean[cellRows][cellCols];
        for (int k = 0; k < n.size(); k++) {
            String cp = path + "[" + k + "]";
            JsonNode c = n.get(k);
            if (!c.isArray() || c.size() != 2) throw error(cp, "expected [i, j] (two integers), got "
                    + (c.isArray() ? "an array of " + c.size() : kind(c)));
            int i = cellIndex(c.get(0), cp + "[0]", cellCols, "columns");
            int j = cellIndex(c.get(1), cp + "[1]", cellRows, "rows");
            if (mask[j][i]) throw error(cp, "cell [" + i + ", " + j + "] is listed twice");
            mask[j][i] = true;
        }
        return mask;
    }

    private int cellIndex(JsonNode v, String path, int count, String what) throws CourseException {
        if (!v.isIntegralNumber()) throw error(path, "expected an integer cell index, got " + kind(v));
        long index = v.asLong();
        if (index < 0 || index >= count || !v.canConvertToInt()) {
            throw error(path, "cell index " + v.asText() + " is outside 0.." + (count - 1) + " (the grid has "
                    + count + " cell " + what + ")");
        }
        return (int) index;
    }

    /**
     * An array of equally long rows of numbers. With rows/cols &ge; 0 the shape must be exactly
     * that (the heights' shape); otherwise the first row sets the length.
     */
    double[][] matrix(JsonNode n, String path, int rows, int cols, boolean nonNegative) throws CourseException {
        if (!n.isArray()) throw error(path, "expected an array of rows, got " + kind(n));
        if (rows >= 0 && n.size() != rows) {
            throw error(path, "has " + n.size() + " rows, expected " + rows + " (the shape of heights)");
        }
        double[][] m = new double[n.size()][];
        int expected = cols;
        for (int j = 0; j < n.size(); j++) {
            String rp = path + "[" + j + "]";
            JsonNode row = n.get(j);
            if (!row.isArray()) throw error(rp, "expected a row (an array of numbers), got " + kind(row));
            if (expected < 0) expected = row.size();
            if (row.size() != expected) {
                throw error(rp, "row has " + row.size() + " values, expected " + expected);
            }
            double[] r = new double[row.size()];
            for (int i = 0; i < r.length; i++) {
                String vp = rp + "[" + i + "]";
                r[i] = number(row.get(i), vp);
                if (nonNegative) nonNegative(r[i], vp);
            }
            m[j] = r;
        }
        return m;
    }
}
