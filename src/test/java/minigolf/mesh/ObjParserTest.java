package minigolf.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

class ObjParserTest {
    @Test
    void quadWithUvsAndNormalsBecomesTwoIndexedTriangles() throws ObjException {
        TriangleMesh m = ObjParser.parse(String.join("\n",
                "# a unit square", "mtllib scene.mtl", "o square", "usemtl red",
                "v 0 0 0", "v 1 0 0", "v 1 1 0", "v 0 1 0",
                "vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1", "vn 0 0 2",
                "f 1/1/1 2/2/1 3/3/1 4/4/1"));
        assertEquals(4, m.vertexCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, m.indices());
        assertArrayEquals(new float[] {1, 1, 0}, java.util.Arrays.copyOfRange(m.positions(), 6, 9));
        assertArrayEquals(new float[] {1, 1}, java.util.Arrays.copyOfRange(m.uvs(), 4, 6));
        assertArrayEquals(new float[] {0, 0, 1}, java.util.Arrays.copyOfRange(m.normals(), 0, 3), "normals are unit length");
        assertEquals(List.of(new TriangleMesh.Part("square", "red", 0, 2)), m.parts());
        assertEquals(List.of("scene.mtl"), m.materialLibraries());
    }

    @Test
    void negativeIndicesCountBackFromTheLastVertex() throws ObjException {
        TriangleMesh a = ObjParser.parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        TriangleMesh b = ObjParser.parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n");
        assertEquals(a, b);
    }

    @Test
    void missingNormalsAreComputedFromTheFaces() throws ObjException {
        TriangleMesh m = ObjParser.parse("v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n");
        assertArrayEquals(new float[] {0, 0, 1, 0, 0, 1, 0, 0, 1}, m.normals());
    }

    @Test
    void groupsAndMaterialsSplitParts() throws ObjException {
        TriangleMesh m = ObjParser.parse(String.join("\n", "v 0 0 0", "v 1 0 0", "v 0 1 0", "v 0 0 1",
                "g base", "usemtl wood", "f 1 2 3", "f 1 2 4", "g sail", "usemtl cloth", "f 1 3 4"));
        assertEquals(List.of(new TriangleMesh.Part("base", "wood", 0, 2), new TriangleMesh.Part("sail", "cloth", 2, 1)),
                m.parts());
    }

    @Test
    void errorsNameTheLine() {
        assertEquals("line 4: vertex index 4 is out of range (3 defined so far)",
                message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"));
        assertEquals("line 1: 'abc' is not a number", message("v 1 abc 0\n"));
        assertEquals("line 1: 'NaN' is not a finite number", message("v 1 NaN 0\n"));
        assertEquals("line 2: a face needs at least 3 corners, got 2", message("v 0 0 0\nf 1 1\n"));
        assertEquals("line 1: unknown statement 'bogus'", message("bogus 1 2\n"));
        assertEquals("no faces (an .obj model needs at least one f line)", message("v 0 0 0\n"));
        assertEquals("line 4: malformed face corner '1/2/3/4'", message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2/3/4 2 3\n"));
        assertEquals("line 4: texture coordinate index 1 is out of range (0 defined so far)",
                message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n"));
    }

    private static String message(String text) {
        return assertThrows(ObjException.class, () -> ObjParser.parse(text)).getMessage();
    }
}
