package minigolf.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;

/**
 * The course elements' meshes (no GL needed) for every practice hole: built in the layout the
 * elements' pass draws, whatever layout the obstacles' meshes they reuse have (a gate's panel, a
 * moving box: ObstacleMeshes writes a material id as a fourth colour component).
 */
class ElementMeshesTest {
    @Test
    void everyPracticeHoleBuildsItsElementsInThePassLayout() throws Exception {
        Path dir = Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "practice");
        List<Path> holes;
        try (Stream<Path> s = Files.list(dir)) {
            holes = s.filter(p -> p.toString().endsWith(".json")).sorted().toList();
        }
        assertEquals(7, holes.size(), holes.toString());
        for (Path f : holes) {
            World w = World.load(f);
            ElementMeshes.Built b = ElementMeshes.build(w.course(), w.terrain()::height);
            int drawn = 0;
            for (MeshData d : Stream.concat(Stream.of(b.solid(), b.decals(), b.glow()), b.moving().stream()).toList()) {
                assertArrayEquals(MeshData.PNC, d.layout(), f.toString());
                assertEquals(0, d.vertices().length % 9, f.toString());
                for (int i : d.indices()) assertTrue(i >= 0 && i < d.vertices().length / 9, f + ": index " + i);
                drawn += d.indices().length;
            }
            assertTrue(drawn > 0, f + " draws its elements");
            assertEquals(b.movers().size(), b.moving().size());
        }
    }

    @Test
    void aMeshWithAMaterialIdLosesItAndKeepsItsColour() {
        float[] v = new float[30], expected = new float[27];
        for (int k = 0; k < 3; k++) {
            for (int c = 0; c < 9; c++) v[10 * k + c] = expected[9 * k + c] = 10 * k + c;
            v[10 * k + 9] = 4; // the material's id
        }
        MeshData d = ElementMeshes.pnc(new MeshData(ObstacleMeshes.LAYOUT, v, new int[]{0, 1, 2}));
        assertArrayEquals(MeshData.PNC, d.layout());
        assertArrayEquals(expected, d.vertices());
        assertArrayEquals(new int[]{0, 1, 2}, d.indices());
    }
}
