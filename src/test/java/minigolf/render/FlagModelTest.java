package minigolf.render;

import minigolf.mesh.TriangleMesh;
import org.junit.jupiter.api.Test;

import java.util.Set;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.*;

/** The hole's flag, models/flag.obj (no GL: parsing and placing only). */
class FlagModelTest {
    static final ModelResource FLAG = ModelResource.get("flag");

    static double[] extent(MeshData d, int axis) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        float[] v = d.vertices();
        for (int i = axis; i < v.length; i += d.stride()) {
            lo = Math.min(lo, v[i]);
            hi = Math.max(hi, v[i]);
        }
        return new double[]{lo, hi};
    }

    @Test
    void theModelHasAPoleABallAndARedCloth() {
        Set<String> materials = FLAG.mesh().parts().stream().map(TriangleMesh.Part::material).collect(Collectors.toSet());
        assertEquals(Set.of("pole", "finial", "cloth"), materials);
        float[] red = FLAG.materials().color("cloth");
        assertTrue(red[0] > 0.8f && red[1] < 0.2f && red[2] < 0.2f, "cloth colour " + java.util.Arrays.toString(red));
        float[] white = FLAG.materials().color("pole");
        assertTrue(white[0] > 0.9f && white[1] > 0.9f && white[2] > 0.9f);
    }

    @Test
    void placedAtAHoleThePoleStandsFlagHeightAboveTheGround() {
        double ground = 0.37;
        MeshData d = FLAG.placed(2, -1, ground - ObjectsPass.FLAG_FOOT_DEPTH, 0, 1);
        double[] z = extent(d, 2);
        assertEquals(ground - ObjectsPass.FLAG_FOOT_DEPTH, z[0], 1e-5, "the foot sits in the cup");
        // The top (the gold ball) is a few centimetres above the pole's FLAG_HEIGHT.
        assertTrue(z[1] > ground + ObjectsPass.FLAG_HEIGHT && z[1] < ground + ObjectsPass.FLAG_HEIGHT + 0.05, "top at " + z[1]);
        // Unturned, the cloth flies along +x: 0.42 m of it beyond the pole, little sideways.
        double[] x = extent(d, 0), y = extent(d, 1);
        assertEquals(2 + ObjectsPass.POLE_RADIUS + 0.42, x[1], 1e-3);
        assertTrue(y[1] - y[0] < 0.1, "sideways extent " + (y[1] - y[0]));
    }

    @Test
    void theClothFliesSidewaysToTheLineFromTheStart() {
        // Start south of the hole: the line runs north, the cloth east or west.
        double heading = ObjectsPass.clothHeading(0, -5, 0, 0);
        MeshData d = FLAG.placed(0, 0, 0, heading, 1);
        double[] x = extent(d, 0), y = extent(d, 1);
        assertTrue(Math.max(Math.abs(x[0]), Math.abs(x[1])) > 0.4, "x extent " + java.util.Arrays.toString(x));
        assertTrue(y[1] - y[0] < 0.1, "y extent " + java.util.Arrays.toString(y));
        // A diagonal line: the cloth is perpendicular to it.
        double h = Math.toRadians(ObjectsPass.clothHeading(1, 1, 4, 5));
        assertEquals(0, Math.cos(h) * 3 + Math.sin(h) * 4, 1e-9);
        assertEquals(0, ObjectsPass.clothHeading(2, 2, 2, 2), "start on the hole: any heading, no NaN");
    }
}
