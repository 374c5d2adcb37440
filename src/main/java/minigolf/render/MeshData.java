package minigolf.render;

import java.util.Arrays;

/**
 * Interleaved vertex data and triangle indices, built on the CPU (testable without GL) and uploaded
 * by {@link Mesh}. {@code layout} lists the float count of each attribute in location order, e.g.
 * {3, 3, 3} for position, normal, colour.
 */
public record MeshData(int[] layout, float[] vertices, int[] indices) {
    /** Position, normal, colour: the layout of lit meshes. */
    public static final int[] PNC = {3, 3, 3};

    public MeshData {
        int stride = Arrays.stream(layout).sum();
        if (stride <= 0 || vertices.length % stride != 0) {
            throw new IllegalArgumentException("vertex array length " + vertices.length + " is not a multiple of the stride " + stride);
        }
        if (indices.length % 3 != 0) throw new IllegalArgumentException("indices must come in triangles");
        int count = vertices.length / stride;
        for (int i : indices) {
            if (i < 0 || i >= count) throw new IllegalArgumentException("index " + i + " out of range 0.." + (count - 1));
        }
    }

    /** a's vertices and triangles, then b's (same layout). */
    public static MeshData concat(MeshData a, MeshData b) {
        if (!Arrays.equals(a.layout, b.layout)) throw new IllegalArgumentException("layouts differ");
        float[] v = Arrays.copyOf(a.vertices, a.vertices.length + b.vertices.length);
        System.arraycopy(b.vertices, 0, v, a.vertices.length, b.vertices.length);
        int offset = a.vertexCount();
        int[] idx = Arrays.copyOf(a.indices, a.indices.length + b.indices.length);
        for (int i = 0; i < b.indices.length; i++) idx[a.indices.length + i] = b.indices[i] + offset;
        return new MeshData(a.layout, v, idx);
    }

    public int stride() {
        return Arrays.stream(layout).sum();
    }

    public int vertexCount() {
        return vertices.length / stride();
    }

    public int triangleCount() {
        return indices.length / 3;
    }

    /** Float {@code component} of attribute {@code attribute} of vertex {@code vertex}. */
    public float get(int vertex, int attribute, int component) {
        int offset = 0;
        for (int a = 0; a < attribute; a++) offset += layout[a];
        return vertices[vertex * stride() + offset + component];
    }
}
