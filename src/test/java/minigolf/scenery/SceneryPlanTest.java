package minigolf.scenery;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import minigolf.course.Bounds;
import minigolf.theme.Theme;
import minigolf.theme.Themes;
import org.junit.jupiter.api.Test;

/** Where the props stand: off the course, in their bands, the same every time, the castle beyond the hole. */
class SceneryPlanTest {
    static final Bounds B = new Bounds(-3.8, -1.1, 3.8, 1.1);

    @Test
    void propsStandOffTheCourseInTheirBandsAndApart() {
        for (Theme t : Themes.all()) {
            List<SceneryPlan.Placed> plan = SceneryPlan.plan(t.scenery(), B, -3, 0, 3, 0, 1);
            assertFalse(plan.isEmpty(), t.id());
            assertEquals(plan, SceneryPlan.plan(t.scenery(), B, -3, 0, 3, 0, 1), t.id() + ": deterministic");
            for (SceneryPlan.Placed p : plan) {
                double d = SceneryPlan.distance(B, p.x(), p.y());
                assertTrue(d > 0.5, t.id() + ": " + p + " is off the course (" + d + " m)");
                SceneryPlan.Rule r = SceneryPlan.rule(p.prop());
                if (r.maxDistance() > 0 && p.prop() != Theme.Prop.CASTLE) {
                    assertTrue(d >= r.minDistance() - 1e-9 && d <= r.maxDistance() + 1e-9, t.id() + ": " + p + " at " + d);
                }
                if (t.scenery().sea() && p.prop() != Theme.Prop.LIGHTHOUSE) {
                    assertTrue(d < t.scenery().shoreDistance(), t.id() + ": " + p + " stands in the sea");
                }
            }
        }
    }

    @Test
    void theCastleStandsBeyondTheHoleAndFacesTheCourse() {
        List<SceneryPlan.Placed> plan = SceneryPlan.plan(Themes.WINTER.scenery(), B, -3, 0, 3, 0, 1);
        SceneryPlan.Placed castle = plan.stream().filter(p -> p.prop() == Theme.Prop.CASTLE).findFirst().orElseThrow();
        assertTrue(castle.x() > B.maxX() + 15, "beyond the hole: " + castle);
        assertEquals(0, castle.y(), 1e-9);
        assertEquals(180, castle.headingDeg(), 1e-9, "facing back towards the tee");
        assertTrue(castle.skyline());
    }

    @Test
    void softwareQualityPlacesAboutHalfAndAtLeastOneOfEachKind() {
        List<SceneryPlan.Placed> all = SceneryPlan.plan(Themes.CANYON.scenery(), B, -3, 0, 3, 0, 1);
        List<SceneryPlan.Placed> half = SceneryPlan.plan(Themes.CANYON.scenery(), B, -3, 0, 3, 0, 0.5);
        assertTrue(half.size() < 0.65 * all.size(), half.size() + " of " + all.size());
        for (Theme.PropCount pc : Themes.CANYON.scenery().props()) {
            assertTrue(half.stream().anyMatch(p -> p.prop() == pc.prop()), pc.prop() + " kept");
        }
    }

    @Test
    void theMeshHasOnePiecePerPropWithItsBoxAndOutwardFaces() {
        List<SceneryPlan.Placed> plan = SceneryPlan.plan(Themes.SEASIDE.scenery(), B, -3, 0, 3, 0, 1);
        SceneryMesh m = SceneryMesh.build(plan, Themes.SEASIDE, -0.3);
        assertEquals(plan.size(), m.pieces().size());
        int end = 0;
        for (SceneryMesh.Piece p : m.pieces()) {
            assertEquals(end, p.first(), "pieces follow one another");
            end = p.first() + p.count();
            assertTrue(p.box()[2] >= -0.3 - 2.5 && p.box()[5] > -0.3, "stands on the ground");
        }
        assertEquals(m.indices().length, end);
        assertTrue(m.triangleCount() < 40_000, "a software rasteriser pays per triangle: " + m.triangleCount());
    }

    @Test
    void lumpsFacesPointOutwards() {
        double[][] pts = Icosphere.points();
        assertEquals(42, pts.length);
        assertEquals(80, Icosphere.faces().length);
        boolean top = false;
        for (double[] p : pts) top |= Math.abs(p[2] - 1) < 1e-9;
        assertTrue(top, "a vertex points straight up");
        // The plain icosahedron (the software tier's smallest lumps): 20 faces over the first 12 points, also outward.
        assertEquals(20, Icosphere.plainFaces().length);
        java.util.List<int[]> all = new java.util.ArrayList<>(java.util.Arrays.asList(Icosphere.faces()));
        for (int[] f : Icosphere.plainFaces()) {
            assertTrue(f[0] < 12 && f[1] < 12 && f[2] < 12, "a plain face uses the icosahedron's own points");
            all.add(f);
        }
        for (int[] f : all) {
            double[] a = pts[f[0]], b = pts[f[1]], c = pts[f[2]];
            double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2], wx = c[0] - a[0], wy = c[1] - a[1], wz = c[2] - a[2];
            double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
            assertTrue(nx * (a[0] + b[0] + c[0]) + ny * (a[1] + b[1] + c[1]) + nz * (a[2] + b[2] + c[2]) > 0, "outward");
        }
    }

    /** The software tier's flowers: the heads from the plain icosahedron (a clump 260 triangles, not 800); the same clumps in the same places. */
    @Test
    void lightFlowersHaveAThirdOfTheTriangles() {
        MeshWriter full = new MeshWriter(), light = new MeshWriter();
        PropMeshes.flowers(full, 2, 3, 0.1, 42);
        PropMeshes.flowers(light, 2, 3, 0.1, 42, true);
        assertEquals(800, full.indexCount() / 3);
        assertEquals(80 + 9 * 20, light.indexCount() / 3);
        float[] a = full.box(0), b = light.box(0);
        for (int k = 0; k < 6; k++) assertEquals(a[k], b[k], 0.02, "the clump's box, coordinate " + k);
        List<SceneryPlan.Placed> plan = SceneryPlan.plan(Themes.MEADOWBROOK.scenery(), B, -3, 0, 3, 0, 0.5);
        int flowers = (int) plan.stream().filter(p -> p.prop() == Theme.Prop.FLOWERS).count();
        assertTrue(flowers > 0);
        assertEquals(flowers * (800 - 260), SceneryMesh.build(plan, Themes.MEADOWBROOK, 0).triangleCount()
                - SceneryMesh.build(plan, Themes.MEADOWBROOK, 0, true).triangleCount());
    }
}
