package minigolf.mesh;

import java.util.Arrays;
import java.util.List;

/**
 * An indexed triangle mesh as read from a Wavefront .obj file: one vertex per distinct
 * (position, uv, normal) corner, three indices per triangle, and the parts (runs of triangles that
 * share an object/group name and a material). The renderer draws exactly these triangles and the
 * collision code collides with exactly these triangles, so what the player sees is what the ball hits
 * (the software quality tier may draw a model's lighter twin of the same shape instead:
 * {@code minigolf.course.ModelTwins}).
 *
 * <p>Coordinates are in the model's own frame (as written in the file); a course's {@code model}
 * obstacle places them in the world (see {@code minigolf.collision.ObstacleGeometry}).
 *
 * @param positions x, y, z per vertex
 * @param normals   unit normal per vertex (from the file's {@code vn}, or the area-weighted average of
 *                  the faces that use the vertex when the file gives none)
 * @param uvs       u, v per vertex (0, 0 where the file gives none)
 * @param indices   three vertex indices per triangle, counter-clockwise as in the file
 * @param parts     the triangle runs by object/group and material, in file order
 * @param materialLibraries the files named by {@code mtllib}, as written (not read)
 */
public record TriangleMesh(float[] positions, float[] normals, float[] uvs, int[] indices, List<Part> parts,
                           List<String> materialLibraries) {

    /**
     * Triangles [firstTriangle, firstTriangle + triangleCount) belong to this part.
     *
     * @param name     the {@code o} or {@code g} name in force ("" if none)
     * @param material the {@code usemtl} name in force ("" if none)
     */
    public record Part(String name, String material, int firstTriangle, int triangleCount) {
    }

    public TriangleMesh {
        parts = List.copyOf(parts);
        materialLibraries = List.copyOf(materialLibraries);
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int triangleCount() {
        return indices.length / 3;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof TriangleMesh m && Arrays.equals(positions, m.positions) && Arrays.equals(normals, m.normals)
                && Arrays.equals(uvs, m.uvs) && Arrays.equals(indices, m.indices) && parts.equals(m.parts)
                && materialLibraries.equals(m.materialLibraries);
    }

    @Override
    public int hashCode() {
        return 31 * Arrays.hashCode(positions) + Arrays.hashCode(indices);
    }

    @Override
    public String toString() {
        return "TriangleMesh[" + vertexCount() + " vertices, " + triangleCount() + " triangles, " + parts.size() + " parts]";
    }
}
