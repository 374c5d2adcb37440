package minigolf.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.Obstacle;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import org.junit.jupiter.api.Test;

/** Times of impact of a swept sphere against each kind of shape, against closed forms. */
class CollisionSceneTest {
    private static final double R = 0.02;
    private static final Bounds BOUNDS = new Bounds(-10, -10, 10, 10);

    private static CollisionScene scene(Obstacle... obstacles) {
        return CollisionScene.build(List.of(obstacles), (x, y) -> 0, BOUNDS, R);
    }

    /** A turned box, a trunk, a wall and a turned, sunken box. */
    private static CollisionScene mixedScene() {
        return scene(unitBox(30),
                new Obstacle.Tree(new Vec2(3, 2), 0.15, 1, 0.7),
                new Obstacle.Wall(new Vec2(-6, -4), new Vec2(-2, -5), 0.05, 0.3, 0.7),
                new Obstacle.Box(new Vec3(4, -5, -1), new Vec3(4.5, -3, 0.5), 70, 0.7));
    }

    private static Obstacle.Box unitBox(double rotation) {
        return new Obstacle.Box(new Vec3(-0.5, -0.5, 0), new Vec3(0.5, 0.5, 1), rotation, 0.7);
    }

    @Test
    void headOnIntoAFaceStopsAtTheRadius() {
        Hit hit = new Hit();
        assertTrue(scene(unitBox(0)).sweep(-2, 0, 0.5, 0, 0, 0.5, hit, new double[3]));
        // The centre reaches x = -0.5 - R after travelling 1.5 - R of 2 m.
        assertEquals((1.5 - R) / 2, hit.fraction, 1e-12);
        assertEquals(-1, hit.nx, 1e-12);
        assertEquals(0, hit.ny, 1e-12);
        assertEquals(0, hit.nz, 1e-12);
    }

    @Test
    void cornerOfARotatedBoxIsHitOnItsVerticalEdge() {
        // Turned 45 degrees, the box's edge points at -x: at x = -sqrt(0.5).
        Hit hit = new Hit();
        assertTrue(scene(unitBox(45)).sweep(-2, 0, 0.5, 0, 0, 0.5, hit, new double[3]));
        assertEquals((2 - Math.sqrt(0.5) - R) / 2, hit.fraction, 1e-12);
        assertEquals(-1, hit.nx, 1e-9);
    }

    @Test
    void topCornerIsHitOnItsVertexFromAbove() {
        // Falling straight onto the corner (0.5, 0.5, 1), offset so that only the vertex is touched.
        double off = 0.01;
        Hit hit = new Hit();
        assertTrue(scene(unitBox(0)).sweep(0.5 + off, 0.5 + off, 3, 0.5 + off, 0.5 + off, 0, hit, new double[3]));
        double drop = Math.sqrt(R * R - 2 * off * off); // the centre's height above the vertex at contact
        assertEquals((2 - drop) / 3, hit.fraction, 1e-12);
        assertEquals(off / R, hit.nx, 1e-9);
        assertEquals(drop / R, hit.nz, 1e-9);
    }

    @Test
    void aThinFenceStopsAFastSweepAndAGrazingOneSlidesAlong() {
        CollisionScene fence = scene(new Obstacle.Wall(new Vec2(0, -1), new Vec2(0, 1), 0, 0.3, 0.7));
        Hit hit = new Hit();
        assertTrue(fence.sweep(-1, 0.3, R, 1, 0.3, R, hit, new double[3]));
        assertEquals((1 - R) / 2, hit.fraction, 1e-12);
        // Touching the fence and moving along it: no contact, whatever the triangles' inner edges.
        assertFalse(fence.sweep(-R, -0.8, 0.1, -R, 0.8, 0.1, hit, new double[3]));
        // A ball flying above the fence's top (0.3) passes.
        assertFalse(fence.sweep(-1, 0, 0.3 + R + 1e-9, 1, 0, 0.3 + R + 1e-9, hit, new double[3]));
    }

    @Test
    void treeSideAndTop() {
        CollisionScene tree = scene(new Obstacle.Tree(new Vec2(0, 0), 0.1, 1, 0.6));
        Hit hit = new Hit();
        assertTrue(tree.sweep(-1, 0.05, 0.5, 1, 0.05, 0.5, hit, new double[3]));
        double x = -Math.sqrt((0.1 + R) * (0.1 + R) - 0.05 * 0.05);
        assertEquals((x + 1) / 2, hit.fraction, 1e-12);
        assertEquals(0.6, hit.restitution);
        assertEquals(x / (0.1 + R), hit.nx, 1e-12);
        assertTrue(tree.sweep(0.02, 0, 2, 0.02, 0, 0, hit, new double[3]));
        assertEquals((1 - R) / 2, hit.fraction, 1e-12);
        assertEquals(1, hit.nz, 1e-12);
    }

    @Test
    void fiveHundredObstaclesGiveTheSameHitsAsOneAndTheGridKeepsCandidatesFew() {
        Obstacle.Wall wall = new Obstacle.Wall(new Vec2(1, -1), new Vec2(1, 1), 0.05, 0.2, 0.7);
        List<Obstacle> many = new ArrayList<>(List.of(wall));
        for (int k = 0; k < 499; k++) {
            double x = -9 + (k % 25) * 0.5, y = 3 + (k / 25) * 0.3;
            many.add(new Obstacle.Tree(new Vec2(x, y), 0.05, 1, 0.7));
        }
        CollisionScene one = scene(wall), all = CollisionScene.build(many, (x, y) -> 0, BOUNDS, R);
        Hit a = new Hit(), b = new Hit();
        int most = 0;
        for (double y = -1.5; y <= 1.5; y += 0.01) {
            boolean hitOne = one.sweep(0, y, R, 2, y + 0.1, R, a, new double[3]);
            assertEquals(hitOne, all.sweep(0, y, R, 2, y + 0.1, R, b, new double[3]), "y " + y);
            if (hitOne) assertEquals(a.fraction, b.fraction, 0, "y " + y);
            // The broad phase: a sweep by the wall visits the wall's 12 triangles (in each cell it
            // lies in), never the 499 trunks 3 m away.
            most = Math.max(most, all.candidates(0, y, 2, y + 0.1));
        }
        assertTrue(most >= 12 && most <= 4 * 12, "candidates of a sweep by the wall: " + most + " (of 511 shapes)");
        // Among the trunks a short sweep visits the few round it (each listed in the cells within a ball radius).
        int among = all.candidates(-6, 4, -5.6, 4.2);
        assertTrue(among >= 1 && among <= 25, "a sweep among the trunks visits " + among + " entries of 499 trunks");
        assertFalse(all.anyNear(-1, -1, -0.5, -0.5), "nothing is listed near the origin");
    }

    /**
     * anyShapeNear may only say "no" where no sweep inside the rectangle can touch anything: for
     * random chords among walls, trunks and turned boxes, every chord that hits has a "yes" for
     * its own bounding rectangle, and the test sees both answers many times.
     */
    @Test
    void anyShapeNearNeverHidesAContact() {
        CollisionScene scene = mixedScene();
        java.util.Random random = new java.util.Random(3);
        Hit hit = new Hit();
        double[] scratch = new double[3];
        int hits = 0, noes = 0;
        for (int k = 0; k < 50_000; k++) {
            double x0 = -8 + 16 * random.nextDouble(), y0 = -8 + 16 * random.nextDouble();
            double x1 = x0 + random.nextGaussian() * 0.4, y1 = y0 + random.nextGaussian() * 0.4;
            boolean near = scene.anyShapeNear(Math.min(x0, x1), Math.min(y0, y1), Math.max(x0, x1), Math.max(y0, y1));
            if (scene.sweep(x0, y0, 0.1, x1, y1, 0.1, hit, scratch)) {
                hits++;
                assertTrue(near, "a hit from (" + x0 + ", " + y0 + ") to (" + x1 + ", " + y1 + ")");
            }
            if (!near) noes++;
        }
        assertTrue(hits > 500 && noes > 10_000, hits + " hits, " + noes + " noes");
    }

    /**
     * The broad phase (cells, runs of one obstacle's shapes under one box, each shape tested once
     * per sweep) finds exactly the contact that sweeping each obstacle alone and keeping the first
     * gives: 120 walls, boxes and trunks crowded on 3 x 3 m, 20,000 random chords up to 0.5 m.
     */
    @Test
    void aCrowdedSceneFindsTheFirstContactOfEachObstacleAlone() {
        java.util.Random random = new java.util.Random(5);
        List<Obstacle> obstacles = new ArrayList<>();
        for (int k = 0; k < 120; k++) {
            double x = 3 * random.nextDouble(), y = 3 * random.nextDouble();
            obstacles.add(switch (k % 3) {
                case 0 -> new Obstacle.Wall(new Vec2(x, y), new Vec2(x + random.nextGaussian() * 0.3, y + random.nextGaussian() * 0.3),
                        0.05 * random.nextInt(2), 0.1, 0.7);
                case 1 -> new Obstacle.Box(new Vec3(x, y, 0), new Vec3(x + 0.05 + 0.2 * random.nextDouble(),
                        y + 0.05 + 0.2 * random.nextDouble(), 0.2), 90 * random.nextDouble(), 0.6);
                default -> new Obstacle.Tree(new Vec2(x, y), 0.02 + 0.08 * random.nextDouble(), 1, 0.5);
            });
        }
        CollisionScene all = CollisionScene.build(obstacles, (x, y) -> 0, BOUNDS, R);
        CollisionScene[] alone = new CollisionScene[obstacles.size()];
        for (int k = 0; k < alone.length; k++) alone[k] = scene(obstacles.get(k));
        Hit hit = new Hit(), one = new Hit();
        double[] scratch = new double[3];
        int contacts = 0;
        for (int n = 0; n < 20_000; n++) {
            double x0 = -0.2 + 3.4 * random.nextDouble(), y0 = -0.2 + 3.4 * random.nextDouble(), z0 = R + 0.3 * random.nextDouble();
            double x1 = x0 + random.nextGaussian() * 0.2, y1 = y0 + random.nextGaussian() * 0.2, z1 = z0 + random.nextGaussian() * 0.05;
            double first = Double.POSITIVE_INFINITY;
            // The obstacles met first (several where the chord starts touching overlapping ones).
            java.util.Set<Integer> owners = new java.util.HashSet<>();
            for (int k = 0; k < alone.length; k++) {
                if (!alone[k].sweep(x0, y0, z0, x1, y1, z1, one, scratch) || one.fraction > first) continue;
                if (one.fraction < first) owners.clear();
                first = one.fraction;
                owners.add(k);
            }
            boolean found = all.sweep(x0, y0, z0, x1, y1, z1, hit, scratch);
            assertEquals(!owners.isEmpty(), found, "chord " + n);
            if (found) {
                contacts++;
                assertEquals(first, hit.fraction, 0, "chord " + n);
                assertTrue(owners.contains(hit.obstacle), "chord " + n + ": " + hit.obstacle + " of " + owners);
            }
        }
        assertTrue(contacts > 2_000, contacts + " contacts");
    }

    /**
     * anyShapeNearPath may only say "no" where no sweep along a path within its margin of the
     * segment touches anything: random chords among walls, trunks and turned boxes, each swept
     * moved sideways by up to the margin; and it says "no" where the rectangle test says "yes"
     * for many diagonal paths (what it is for).
     */
    @Test
    void anyShapeNearPathNeverHidesAContactAndIsTighterThanTheRectangle() {
        CollisionScene scene = mixedScene();
        java.util.Random random = new java.util.Random(8);
        Hit hit = new Hit();
        double[] scratch = new double[3];
        int hits = 0, tighter = 0;
        for (int k = 0; k < 50_000; k++) {
            double x0 = -8 + 16 * random.nextDouble(), y0 = -8 + 16 * random.nextDouble();
            double x1 = x0 + random.nextGaussian() * 0.4, y1 = y0 + random.nextGaussian() * 0.4;
            double margin = 0.05 * random.nextDouble();
            boolean near = scene.anyShapeNearPath(x0, y0, x1, y1, margin);
            double length = Math.hypot(x1 - x0, y1 - y0), side = margin * (2 * random.nextDouble() - 1);
            double ox = length > 0 ? -(y1 - y0) / length * side : side, oy = length > 0 ? (x1 - x0) / length * side : 0;
            if (scene.sweep(x0 + ox, y0 + oy, 0.1, x1 + ox, y1 + oy, 0.1, hit, scratch)) {
                hits++;
                assertTrue(near, "a hit from (" + x0 + ", " + y0 + ") to (" + x1 + ", " + y1 + "), margin " + margin);
            }
            if (!near && scene.anyShapeNear(Math.min(x0, x1) - margin, Math.min(y0, y1) - margin,
                    Math.max(x0, x1) + margin, Math.max(y0, y1) + margin)) {
                tighter++;
            }
        }
        assertTrue(hits > 500 && tighter > 100, hits + " hits, " + tighter + " paths clear that the rectangle would not clear");
    }

    /**
     * Long walls across the course (the "2500 walls" limit case in small) are listed in every cell
     * along them with the same triangles: those runs share one hull, so the hulls stay in
     * proportion to the walls, not to the cells (unshared, they took 1.2 s and 160 MB to build at
     * the limit); and the shared hulls still never hide a contact.
     */
    @Test
    void longWallsShareTheirHullsAlongTheirCellsAndHideNoContact() {
        List<Obstacle> walls = new ArrayList<>();
        for (int k = 0; k < 200; k++) {
            double y = -9.5 + 0.095 * k;
            walls.add(new Obstacle.Wall(new Vec2(-9.5, y), new Vec2(9.5, y + 0.3 * Math.sin(k)), 0.02, 0.2, 0.7));
        }
        CollisionScene scene = CollisionScene.build(walls, (x, y) -> 0, BOUNDS, R);
        long[] points = scene.hullPoints();
        assertTrue(points[0] <= 200 * 4 * 4, points[0] + " hull points stored for 200 walls");
        assertTrue(points[1] >= 10 * points[0], points[1] + " listed by the runs, " + points[0] + " stored");
        java.util.Random random = new java.util.Random(12);
        Hit hit = new Hit();
        double[] scratch = new double[3];
        int hits = 0;
        for (int k = 0; k < 20_000; k++) {
            double x0 = -9 + 18 * random.nextDouble(), y0 = -9 + 18 * random.nextDouble();
            double x1 = x0 + random.nextGaussian() * 0.2, y1 = y0 + random.nextGaussian() * 0.2;
            if (scene.sweep(x0, y0, 0.1, x1, y1, 0.1, hit, scratch)) {
                hits++;
                assertTrue(scene.anyShapeNearPath(x0, y0, x1, y1, 0), "a hit from (" + x0 + ", " + y0 + ") to (" + x1 + ", " + y1 + ")");
            }
        }
        assertTrue(hits > 1_000, hits + " hits");
    }
}
