package minigolf.mesh;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads Wavefront .obj text into a {@link TriangleMesh}. Supported: {@code v} (x y z, an optional w
 * is ignored), {@code vt} (u [v [w]]), {@code vn}, {@code f} with {@code v}, {@code v/vt},
 * {@code v//vn} or {@code v/vt/vn} corners (polygons are fan-triangulated from their first corner),
 * negative (relative) indices, {@code o}, {@code g}, {@code usemtl}, {@code mtllib} (recorded, not
 * read), {@code s} and {@code l}/{@code p} (ignored), comments and blank lines. Anything else is an
 * error with its line number, so a broken file never loads half.
 */
public final class ObjParser {
    /** The most v (and each of vt, vn) lines one model may have; docs/course-format.md lists the limits. */
    public static final int MAX_VERTICES = 50_000;
    /** The most triangles one model may have, after polygons are split into triangles. */
    public static final int MAX_TRIANGLES = 50_000;

    private ObjParser() {
    }

    public static TriangleMesh parse(InputStream in) throws ObjException {
        byte[] bytes;
        try {
            bytes = in.readAllBytes();
        } catch (IOException e) {
            throw new ObjException(0, "cannot read: " + e.getMessage());
        }
        return parse(new String(bytes, StandardCharsets.UTF_8));
    }

    public static TriangleMesh parse(String text) throws ObjException {
        return new Builder().read(text);
    }

    private static final class Builder {
        private final FloatList positions = new FloatList();
        private final FloatList uvs = new FloatList();
        private final FloatList normals = new FloatList();
        // Output vertices: one per distinct (v, vt, vn) corner.
        private final Map<Corner, Integer> corners = new HashMap<>();
        private final IntList cornerV = new IntList(), cornerT = new IntList(), cornerN = new IntList();
        private final IntList indices = new IntList();
        private final List<TriangleMesh.Part> parts = new ArrayList<>();
        private final List<String> libraries = new ArrayList<>();
        private String name = "", material = "";
        private int partStart = 0;

        TriangleMesh read(String text) throws ObjException {
            String[] lines = text.split("\r\n|\n|\r", -1);
            for (int i = 0; i < lines.length; i++) {
                int lineNumber = i + 1;
                String line = lines[i];
                int hash = line.indexOf('#');
                if (hash >= 0) line = line.substring(0, hash);
                line = line.strip();
                if (line.isEmpty()) continue;
                if (i == 0 && line.charAt(0) == '\uFEFF') line = line.substring(1).strip();
                String[] t = tokens(line);
                switch (t[0]) {
                    case "v" -> {
                        if (t.length < 4 || t.length > 5) throw new ObjException(lineNumber, "v needs x y z, got " + (t.length - 1) + " numbers");
                        for (int k = 1; k <= 3; k++) positions.add(number(t[k], lineNumber));
                        if (positions.size() / 3 > MAX_VERTICES) throw new ObjException(lineNumber, "more than " + MAX_VERTICES + " vertices (the limit)");
                    }
                    case "vt" -> {
                        if (t.length < 2 || t.length > 4) throw new ObjException(lineNumber, "vt needs u [v [w]], got " + (t.length - 1) + " numbers");
                        uvs.add(number(t[1], lineNumber));
                        uvs.add(t.length > 2 ? number(t[2], lineNumber) : 0);
                        if (uvs.size() / 2 > MAX_VERTICES) throw new ObjException(lineNumber, "more than " + MAX_VERTICES + " texture coordinates (the limit)");
                    }
                    case "vn" -> {
                        if (t.length != 4) throw new ObjException(lineNumber, "vn needs x y z, got " + (t.length - 1) + " numbers");
                        for (int k = 1; k <= 3; k++) normals.add(number(t[k], lineNumber));
                        if (normals.size() / 3 > MAX_VERTICES) throw new ObjException(lineNumber, "more than " + MAX_VERTICES + " normals (the limit)");
                    }
                    case "f" -> face(t, lineNumber);
                    case "o", "g" -> {
                        closePart();
                        name = t.length > 1 ? line.substring(t[0].length()).strip() : "";
                    }
                    case "usemtl" -> {
                        if (t.length < 2) throw new ObjException(lineNumber, "usemtl needs a material name");
                        closePart();
                        material = line.substring(t[0].length()).strip();
                    }
                    case "mtllib" -> {
                        if (t.length < 2) throw new ObjException(lineNumber, "mtllib needs a file name");
                        libraries.addAll(Arrays.asList(t).subList(1, t.length));
                    }
                    case "s", "l", "p" -> { }
                    default -> throw new ObjException(lineNumber, "unknown statement '" + shorten(t[0]) + "'");
                }
            }
            closePart();
            if (indices.size() == 0) throw new ObjException(0, "no faces (an .obj model needs at least one f line)");
            return build();
        }

        private void face(String[] t, int lineNumber) throws ObjException {
            if (t.length < 4) throw new ObjException(lineNumber, "a face needs at least 3 corners, got " + (t.length - 1));
            // Checked before the work: a face of n corners adds n - 2 triangles.
            if ((long) indices.size() / 3 + (t.length - 3) > MAX_TRIANGLES) {
                throw new ObjException(lineNumber, "more than " + MAX_TRIANGLES + " triangles (the limit)");
            }
            int[] vertex = new int[t.length - 1];
            for (int k = 1; k < t.length; k++) vertex[k - 1] = corner(t[k], lineNumber);
            for (int k = 1; k + 1 < vertex.length; k++) {
                indices.add(vertex[0]);
                indices.add(vertex[k]);
                indices.add(vertex[k + 1]);
            }
        }

        /** The output vertex for one face corner such as 3/1/2, -1//-1 or 7. */
        private int corner(String token, int lineNumber) throws ObjException {
            String[] p = token.split("/", -1);
            if (p.length > 3 || p[0].isEmpty()) throw new ObjException(lineNumber, "malformed face corner '" + shorten(token) + "'");
            int v = index(p[0], positions.size() / 3, "vertex", lineNumber);
            int vt = p.length > 1 && !p[1].isEmpty() ? index(p[1], uvs.size() / 2, "texture coordinate", lineNumber) : -1;
            int vn = p.length > 2 && !p[2].isEmpty() ? index(p[2], normals.size() / 3, "normal", lineNumber) : -1;
            if (p.length == 3 && p[2].isEmpty()) throw new ObjException(lineNumber, "malformed face corner '" + shorten(token) + "'");
            Corner key = new Corner(v, vt, vn);
            Integer existing = corners.get(key);
            if (existing != null) return existing;
            int id = cornerV.size();
            cornerV.add(v);
            cornerT.add(vt);
            cornerN.add(vn);
            corners.put(key, id);
            return id;
        }

        private static int index(String s, int count, String what, int lineNumber) throws ObjException {
            int i;
            try {
                i = Integer.parseInt(s);
            } catch (NumberFormatException e) {
                throw new ObjException(lineNumber, what + " index '" + shorten(s) + "' is not an integer");
            }
            int resolved = i > 0 ? i - 1 : count + i;
            if (i == 0 || resolved < 0 || resolved >= count) {
                throw new ObjException(lineNumber, what + " index " + i + " is out of range (" + count + " defined so far)");
            }
            return resolved;
        }

        private static float number(String s, int lineNumber) throws ObjException {
            float f;
            try {
                f = Float.parseFloat(s);
            } catch (NumberFormatException e) {
                throw new ObjException(lineNumber, "'" + shorten(s) + "' is not a number");
            }
            if (!Float.isFinite(f) || s.toLowerCase(java.util.Locale.ROOT).contains("x")) {
                throw new ObjException(lineNumber, "'" + shorten(s) + "' is not a finite number");
            }
            return f;
        }

        private void closePart() {
            int triangles = indices.size() / 3;
            if (triangles > partStart) parts.add(new TriangleMesh.Part(name, material, partStart, triangles - partStart));
            partStart = triangles;
        }

        private TriangleMesh build() {
            int n = cornerV.size();
            float[] pos = new float[3 * n], nor = new float[3 * n], uv = new float[2 * n];
            boolean[] missingNormal = new boolean[n];
            for (int i = 0; i < n; i++) {
                int v = cornerV.get(i);
                System.arraycopy(positions.data, 3 * v, pos, 3 * i, 3);
                int t = cornerT.get(i);
                if (t >= 0) System.arraycopy(uvs.data, 2 * t, uv, 2 * i, 2);
                int vn = cornerN.get(i);
                if (vn >= 0) {
                    System.arraycopy(normals.data, 3 * vn, nor, 3 * i, 3);
                    normalise(nor, i, missingNormal);
                } else {
                    missingNormal[i] = true;
                }
            }
            int[] idx = indices.toArray();
            // Vertices without a normal get the area-weighted mean of their faces' normals.
            for (int k = 0; k < idx.length; k += 3) {
                int a = idx[k], b = idx[k + 1], c = idx[k + 2];
                if (!(missingNormal[a] || missingNormal[b] || missingNormal[c])) continue;
                float ux = pos[3 * b] - pos[3 * a], uy = pos[3 * b + 1] - pos[3 * a + 1], uz = pos[3 * b + 2] - pos[3 * a + 2];
                float wx = pos[3 * c] - pos[3 * a], wy = pos[3 * c + 1] - pos[3 * a + 1], wz = pos[3 * c + 2] - pos[3 * a + 2];
                float nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
                for (int v : new int[] {a, b, c}) {
                    if (!missingNormal[v]) continue;
                    nor[3 * v] += nx;
                    nor[3 * v + 1] += ny;
                    nor[3 * v + 2] += nz;
                }
            }
            for (int i = 0; i < n; i++) {
                if (missingNormal[i]) {
                    missingNormal[i] = false;
                    normalise(nor, i, missingNormal);
                }
            }
            return new TriangleMesh(pos, nor, uv, idx, parts, libraries);
        }

        /** Scales normal i to unit length; a zero normal becomes +z. */
        private static void normalise(float[] nor, int i, boolean[] unused) {
            double x = nor[3 * i], y = nor[3 * i + 1], z = nor[3 * i + 2];
            double length = Math.sqrt(x * x + y * y + z * z);
            if (length == 0 || !Double.isFinite(length)) {
                nor[3 * i] = 0;
                nor[3 * i + 1] = 0;
                nor[3 * i + 2] = 1;
                return;
            }
            nor[3 * i] = (float) (x / length);
            nor[3 * i + 1] = (float) (y / length);
            nor[3 * i + 2] = (float) (z / length);
        }

        private static String shorten(String s) {
            return s.length() > 40 ? s.substring(0, 37) + "..." : s;
        }
    }

    /** The line (already stripped) split at runs of whitespace; by hand, since this runs once per line of big files. */
    static String[] tokens(String line) {
        int count = 0, n = line.length();
        for (int i = 0; i < n; ) {
            while (i < n && Character.isWhitespace(line.charAt(i))) i++;
            if (i < n) count++;
            while (i < n && !Character.isWhitespace(line.charAt(i))) i++;
        }
        String[] out = new String[count];
        int k = 0;
        for (int i = 0; i < n; ) {
            while (i < n && Character.isWhitespace(line.charAt(i))) i++;
            int start = i;
            while (i < n && !Character.isWhitespace(line.charAt(i))) i++;
            if (i > start) out[k++] = line.substring(start, i);
        }
        return out;
    }

    private record Corner(int v, int vt, int vn) {
    }

    private static final class FloatList {
        float[] data = new float[64];
        int size;

        void add(float f) {
            if (size == data.length) data = Arrays.copyOf(data, 2 * size);
            data[size++] = f;
        }

        int size() {
            return size;
        }
    }

    private static final class IntList {
        int[] data = new int[64];
        int size;

        void add(int i) {
            if (size == data.length) data = Arrays.copyOf(data, 2 * size);
            data[size++] = i;
        }

        int get(int k) {
            return data[k];
        }

        int size() {
            return size;
        }

        int[] toArray() {
            return Arrays.copyOf(data, size);
        }
    }
}
