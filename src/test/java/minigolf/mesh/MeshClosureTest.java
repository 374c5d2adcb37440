package minigolf.mesh;

import static org.junit.jupiter.api.Assertions.*;

import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Which meshes are closed and wound alike (MeshClosure; plain Java). */
class MeshClosureTest {
    /** A unit cube's 8 corners and its 12 triangles, counter-clockwise seen from outside. */
    private static final float[] CORNERS = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    private static final int[] CUBE = {
            0, 2, 1, 0, 3, 2,   // bottom, facing down
            4, 5, 6, 4, 6, 7,   // top
            0, 1, 5, 0, 5, 4,   // y = 0
            2, 3, 7, 2, 7, 6,   // y = 1
            1, 2, 6, 1, 6, 5,   // x = 1
            3, 0, 4, 3, 4, 7};  // x = 0

    private static TriangleMesh mesh(float[] positions, int[] indices) {
        return new TriangleMesh(positions, new float[positions.length], new float[positions.length / 3 * 2], indices,
                List.of(), List.of());
    }

    @Test
    void aCubeIsClosedAndACubeWithAHoleOrATurnedFaceIsNot() {
        assertTrue(MeshClosure.closed(mesh(CORNERS, CUBE)));
        assertFalse(MeshClosure.closed(mesh(CORNERS, Arrays.copyOf(CUBE, 30))), "the last side's two triangles missing");
        int[] turned = CUBE.clone();
        turned[1] = CUBE[2];
        turned[2] = CUBE[1]; // one bottom triangle wound the other way
        assertFalse(MeshClosure.closed(mesh(CORNERS, turned)));
        assertFalse(MeshClosure.closed(mesh(new float[]{0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[]{0, 1, 2})), "a single triangle");
    }

    @Test
    void cornersAtTheSamePositionAreOneWhateverTheirNormals() {
        // Each face with its own four corners (flat normals, as an .obj with vn writes a cube), -0 for 0 on one face.
        float[] split = new float[CUBE.length * 3];
        int[] idx = new int[CUBE.length];
        for (int i = 0; i < CUBE.length; i++) {
            for (int a = 0; a < 3; a++) split[3 * i + a] = CORNERS[3 * CUBE[i] + a];
            idx[i] = i;
        }
        for (int i = 0; i < 6 * 3; i++) if (split[i] == 0) split[i] = -0f;
        assertTrue(MeshClosure.closed(mesh(split, idx)));
    }
}
