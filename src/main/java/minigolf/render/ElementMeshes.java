package minigolf.render;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleBinaryOperator;
import minigolf.collision.ObstacleGeometry;
import minigolf.course.Course;
import minigolf.course.HeightProbe;
import minigolf.course.Magnet;
import minigolf.course.Motion;
import minigolf.course.Obstacle;
import minigolf.course.PushZone;
import minigolf.course.Shape;
import minigolf.course.Teleport;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import minigolf.physics.ShapeBoxes;

/**
 * The meshes of the course elements of issue 24 on the CPU (testable without GL), in world
 * coordinates and the position/normal/colour layout, so that a player reads each at a glance:
 * <ul>
 * <li>bumpers: red posts with a white band and a bright cap (they kick);</li>
 * <li>one-way gates: a thin yellow panel with green chevrons on the ground pointing the way through
 * and a red bar on the side it blocks;</li>
 * <li>push zones: an amber tint over the zone with rows of arrows in the push's direction;</li>
 * <li>magnets: a disc at the centre and rings at the rim, red with inward arrows for one that pulls,
 * blue with outward arrows for one that pushes away;</li>
 * <li>teleports: a glowing violet pad over the entry, a ring and an arrow at each exit (its
 * direction, or a ring alone where the ball keeps its own);</li>
 * <li>moving obstacles: each body, still, in its own mesh, which the pass moves with the clock.</li>
 * </ul>
 * The glowing parts (teleport pads, bumper caps) are a mesh of their own, which the pass draws
 * brighter, pulsing.
 */
public final class ElementMeshes {
    static final float[] BUMPER_RED = {0.86f, 0.16f, 0.14f};
    static final float[] BUMPER_BAND = {0.95f, 0.95f, 0.92f};
    static final float[] GATE_PANEL = {0.95f, 0.78f, 0.18f};
    static final float[] GATE_WAY = {0.22f, 0.78f, 0.30f};
    static final float[] GATE_BLOCK = {0.85f, 0.18f, 0.15f};
    static final float[] PUSH_TINT = {0.80f, 0.62f, 0.28f};
    static final float[] PUSH_ARROW = {0.98f, 0.86f, 0.30f};
    static final float[] MAGNET_PULL = {0.85f, 0.20f, 0.22f};
    static final float[] MAGNET_PUSH = {0.22f, 0.40f, 0.90f};
    static final float[] TELEPORT_GLOW = {0.62f, 0.36f, 0.95f};
    static final float[] TELEPORT_EXIT = {0.45f, 0.85f, 0.95f};
    static final float[] TELEPORT_FLOOR = {0.25f, 0.12f, 0.42f};
    /** Moving walls and boxes: cream, so the blades stand out from the still brickwork. */
    static final float[] MOVING = {0.94f, 0.91f, 0.83f};
    static final float[] HUB = {0.25f, 0.25f, 0.28f};
    /** How far decals float above the ground (m), above the terrain's own mesh. */
    static final double LIFT = 0.004;

    /**
     * The still element meshes: {@code solid} (bumpers, gates), {@code decals} (push zones, magnets,
     * gate arrows, exits), {@code glow} (teleport entries, bumper caps); and one body per moving
     * obstacle (in the course's order of moving obstacles), at the pose the file gives it.
     */
    public record Built(MeshData solid, MeshData decals, MeshData glow, List<MeshData> moving, List<Obstacle.Moving> movers) {
    }

    private ElementMeshes() {
    }

    public static Built build(Course course, HeightProbe ground) {
        DoubleBinaryOperator h = ground::height;
        List<MeshData> solid = new ArrayList<>(), decals = new ArrayList<>(), glow = new ArrayList<>();
        List<MeshData> moving = new ArrayList<>();
        List<Obstacle.Moving> movers = new ArrayList<>();
        for (Obstacle o : course.obstacles()) {
            if (o instanceof Obstacle.Bumper b) {
                bumper(b, ground, solid, glow);
            } else if (o instanceof Obstacle.Gate g) {
                gate(g, ground, h, solid, decals);
            } else if (o instanceof Obstacle.Moving m) {
                moving.add(body(m.body(), ground));
                movers.add(m);
                hub(m.motion(), solid);
            }
        }
        for (PushZone z : course.pushZones()) pushZone(z, h, decals);
        for (Magnet m : course.magnets()) magnet(m, h, decals);
        for (Teleport t : course.teleports()) teleport(t, h, decals, glow);
        return new Built(merge(solid), merge(decals), merge(glow), List.copyOf(moving), List.copyOf(movers));
    }

    /** A moving obstacle's body as drawn still (its triangles, or a post for a trunk or a bumper). */
    static MeshData body(Obstacle body, HeightProbe ground) {
        List<MeshData> parts = new ArrayList<>();
        if (body instanceof Obstacle.Bumper b) {
            bumper(b, ground, parts, parts);
        } else if (ObstacleGeometry.isCylinder(body)) {
            double[] c = ObstacleGeometry.cylinder(body, ground);
            float[] colour = ObstacleMeshes.TRUNK_COLOR;
            parts.add(Shapes.cylinder(c[0], c[1], c[3], c[4], c[2], ObstacleMeshes.TRUNK_SEGMENTS, colour[0], colour[1], colour[2]));
        } else {
            ObstacleMeshes.Built built = ObstacleMeshes.build(List.of(body), ground, m -> MaterialLibrary.empty());
            // A model keeps its own colours; a moving wall or box is cream.
            parts.add(body instanceof Obstacle.Model ? pnc(built.solid()) : recolour(pnc(built.solid()), MOVING));
        }
        return merge(parts);
    }

    /** The hub a turning or swinging obstacle turns on: a short dark cylinder along its axis at the pivot. */
    private static void hub(Motion motion, List<MeshData> solid) {
        Vec3 pivot, axis;
        if (motion instanceof Motion.Rotate r) {
            pivot = r.pivot();
            axis = r.axis();
        } else if (motion instanceof Motion.Swing w) {
            pivot = w.pivot();
            axis = w.axis();
        } else {
            return;
        }
        double length = Math.sqrt(axis.x() * axis.x() + axis.y() * axis.y() + axis.z() * axis.z());
        double[] k = {axis.x() / length, axis.y() / length, axis.z() / length};
        // Two directions across the axis.
        double[] u = Math.abs(k[2]) < 0.9 ? cross(k, new double[] {0, 0, 1}) : cross(k, new double[] {1, 0, 0});
        double ul = Math.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        u = new double[] {u[0] / ul, u[1] / ul, u[2] / ul};
        double[] w = cross(k, u);
        int segments = 16;
        double radius = 0.035, half = 0.04;
        float[] v = new float[(2 * segments + 2) * 9];
        int p = 0;
        for (int s = 0; s < segments; s++) {
            double a = 2 * Math.PI * s / segments, c = Math.cos(a), sn = Math.sin(a);
            double nx = c * u[0] + sn * w[0], ny = c * u[1] + sn * w[1], nz = c * u[2] + sn * w[2];
            for (int end = -1; end <= 1; end += 2) {
                p = Shapes.putPnc(v, p, pivot.x() + radius * nx + end * half * k[0], pivot.y() + radius * ny + end * half * k[1],
                        pivot.z() + radius * nz + end * half * k[2], nx, ny, nz, HUB[0], HUB[1], HUB[2]);
            }
        }
        int[] idx = new int[6 * segments];
        int q = 0;
        for (int s = 0; s < segments; s++) {
            int a = 2 * s, b = 2 * ((s + 1) % segments);
            idx[q++] = a;
            idx[q++] = b;
            idx[q++] = b + 1;
            idx[q++] = a;
            idx[q++] = b + 1;
            idx[q++] = a + 1;
        }
        solid.add(new MeshData(MeshData.PNC, java.util.Arrays.copyOf(v, p), idx));
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static void bumper(Obstacle.Bumper b, HeightProbe ground, List<MeshData> solid, List<MeshData> glow) {
        double[] c = ObstacleGeometry.cylinder(b, ground);
        double top = c[4], band = Math.min(0.03, 0.3 * b.height());
        solid.add(Shapes.cylinder(c[0], c[1], c[3], top - 2 * band, c[2], 24, BUMPER_RED[0], BUMPER_RED[1], BUMPER_RED[2]));
        solid.add(Shapes.cylinder(c[0], c[1], top - 2 * band, top - band, c[2] * 1.02, 24, BUMPER_BAND[0], BUMPER_BAND[1], BUMPER_BAND[2]));
        glow.add(Shapes.cylinder(c[0], c[1], top - band, top, c[2], 24, BUMPER_RED[0], BUMPER_RED[1], BUMPER_RED[2]));
    }

    private static void gate(Obstacle.Gate g, HeightProbe ground, DoubleBinaryOperator h, List<MeshData> solid,
                             List<MeshData> decals) {
        double ax = g.from().x(), ay = g.from().y(), bx = g.to().x(), by = g.to().y();
        double length = Math.hypot(bx - ax, by - ay);
        double tx = (bx - ax) / length, ty = (by - ay) / length;
        Vec2 n = g.passNormal();
        double half = 0.006;
        // A thin panel standing on the ground, its top the gate's (straight between the ends), as the ball meets it.
        Obstacle.Wall panel = new Obstacle.Wall(g.from(), g.to(), 2 * half, g.height(), 0);
        ObstacleMeshes.Built built = ObstacleMeshes.build(List.of(panel), ground, m -> MaterialLibrary.empty());
        solid.add(recolour(pnc(built.solid()), GATE_PANEL));
        // Chevrons on the ground through the gate, pointing to its pass side; a red bar on the pass side
        // shows where a ball coming back is stopped.
        int arrows = Math.max(1, (int) Math.floor(length / 0.25));
        for (int k = 0; k < arrows; k++) {
            double s = (k + 0.5) * length / arrows;
            double cx = ax + tx * s, cy = ay + ty * s;
            decals.add(Shapes.groundArrow(cx - 0.12 * n.x(), cy - 0.12 * n.y(), n.x(), n.y(), 0, 0.24, 0.035, h, LIFT,
                    GATE_WAY[0], GATE_WAY[1], GATE_WAY[2]));
        }
        decals.add(Shapes.groundArrow(ax + 0.02 * n.x(), ay + 0.02 * n.y(), tx, ty, 0, length, 0.012, h, LIFT,
                GATE_BLOCK[0], GATE_BLOCK[1], GATE_BLOCK[2]));
    }

    private static void pushZone(PushZone z, DoubleBinaryOperator h, List<MeshData> decals) {
        double[] box = box(z.shape());
        double px = z.push().x(), py = z.push().y(), strength = Math.hypot(px, py);
        decals.add(tint(z.shape(), box, h, PUSH_TINT));
        if (strength == 0) return;
        // Arrows on a grid across the zone, longer for a stronger push (0.12 m at 0.5 m/s², 0.3 m from 2).
        double spacing = 0.35;
        double length = Math.max(0.12, Math.min(0.3, 0.06 + 0.12 * strength));
        double ux = px / strength, uy = py / strength;
        for (double x = box[0] + spacing / 2; x < box[2]; x += spacing) {
            for (double y = box[1] + spacing / 2; y < box[3]; y += spacing) {
                double sx = x - ux * length / 2, sy = y - uy * length / 2;
                if (!z.shape().contains(sx, sy) || !z.shape().contains(sx + ux * length, sy + uy * length)) continue;
                decals.add(Shapes.groundArrow(sx, sy, ux, uy, 0, length, 0.03, h, 2 * LIFT, PUSH_ARROW[0], PUSH_ARROW[1], PUSH_ARROW[2]));
            }
        }
    }

    private static void magnet(Magnet m, DoubleBinaryOperator h, List<MeshData> decals) {
        float[] c = m.strength() >= 0 ? MAGNET_PULL : MAGNET_PUSH;
        double cx = m.position().x(), cy = m.position().y(), r = m.radius();
        decals.add(Shapes.drapedDisc(cx, cy, Math.min(0.06, r / 4), 16, 1, h, 2 * LIFT, c[0], c[1], c[2]));
        decals.add(ring(cx, cy, r, 0.012, h, c));
        decals.add(ring(cx, cy, r / 3, 0.008, h, c));
        // Arrows across the ring of the strongest pull: inward for a magnet that pulls, outward for one that pushes.
        for (int k = 0; k < 8; k++) {
            double a = 2 * Math.PI * k / 8 + Math.PI / 8, ux = Math.cos(a), uy = Math.sin(a);
            double from = m.strength() >= 0 ? 0.85 * r : 0.25 * r, to = m.strength() >= 0 ? 0.25 * r : 0.85 * r;
            double dx = m.strength() >= 0 ? -ux : ux, dy = m.strength() >= 0 ? -uy : uy;
            decals.add(Shapes.groundArrow(cx + ux * from, cy + uy * from, dx, dy, 0, Math.abs(to - from), 0.02, h, 2 * LIFT,
                    c[0], c[1], c[2]));
        }
    }

    private static void teleport(Teleport t, DoubleBinaryOperator h, List<MeshData> decals, List<MeshData> glow) {
        double[] box = box(t.entry());
        if (t.entry() instanceof Shape.Circle c) {
            // A dark pad with glowing rings: a portal.
            double r = c.radius(), x = c.center().x(), y = c.center().y();
            decals.add(Shapes.drapedDisc(x, y, r, 32, 2, h, LIFT, TELEPORT_FLOOR[0], TELEPORT_FLOOR[1], TELEPORT_FLOOR[2]));
            glow.add(ring(x, y, r - 0.012, 0.024, h, TELEPORT_GLOW));
            glow.add(ring(x, y, 0.6 * r, 0.014, h, TELEPORT_GLOW));
            glow.add(ring(x, y, 0.25 * r, 0.01, h, TELEPORT_GLOW));
        } else if (t.entry() instanceof Shape.Cells) {
            // Drawn pixel by pixel (the classic tracks' teleports): the whole entry glows.
            glow.add(tint(t.entry(), box, h, TELEPORT_GLOW));
        } else {
            decals.add(tint(t.entry(), box, h, TELEPORT_FLOOR));
            glow.add(outline(t.entry(), h, TELEPORT_GLOW));
        }
        for (Teleport.Exit e : t.exits()) {
            double x = e.position().x(), y = e.position().y();
            decals.add(ring(x, y, 0.09, 0.015, h, TELEPORT_EXIT));
            if (e.directionDeg() != null) {
                double a = Math.toRadians(e.directionDeg());
                decals.add(Shapes.groundArrow(x, y, Math.cos(a), Math.sin(a), 0.1, 0.3, 0.03, h, 2 * LIFT,
                        TELEPORT_EXIT[0], TELEPORT_EXIT[1], TELEPORT_EXIT[2]));
            }
        }
    }

    /** A flat ring of {@code width} at radius r, draped over the ground (segments about 4 cm long). */
    static MeshData ring(double cx, double cy, double r, double width, DoubleBinaryOperator h, float[] c) {
        int segments = Math.max(24, (int) Math.ceil(2 * Math.PI * r / 0.04));
        return Shapes.drapedRing(cx, cy, r - width / 2, r + width / 2, segments, h, 2 * LIFT, c[0], c[1], c[2]);
    }

    /**
     * The shape's area as a decal: a grid of 5 cm cells over its box, each cell drawn where its centre
     * is inside the shape, draped over the ground.
     */
    static MeshData tint(Shape shape, double[] box, DoubleBinaryOperator h, float[] c) {
        double cell = Math.max(0.05, Math.max(box[2] - box[0], box[3] - box[1]) / 200);
        int nx = Math.max(1, (int) Math.ceil((box[2] - box[0]) / cell)), ny = Math.max(1, (int) Math.ceil((box[3] - box[1]) / cell));
        double sx = (box[2] - box[0]) / nx, sy = (box[3] - box[1]) / ny;
        List<float[]> quads = new ArrayList<>();
        for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
                double x0 = box[0] + i * sx, y0 = box[1] + j * sy;
                if (!shape.contains(x0 + sx / 2, y0 + sy / 2)) continue;
                quads.add(new float[] {(float) x0, (float) y0, (float) (x0 + sx), (float) (y0 + sy)});
            }
        }
        float[] v = new float[quads.size() * 4 * 9];
        int[] idx = new int[quads.size() * 6];
        int p = 0, q = 0, base = 0;
        for (float[] quad : quads) {
            double[][] corners = {{quad[0], quad[1]}, {quad[2], quad[1]}, {quad[2], quad[3]}, {quad[0], quad[3]}};
            for (double[] k : corners) p = Shapes.putPnc(v, p, k[0], k[1], h.applyAsDouble(k[0], k[1]) + LIFT, 0, 0, 1, c[0], c[1], c[2]);
            idx[q++] = base;
            idx[q++] = base + 1;
            idx[q++] = base + 2;
            idx[q++] = base;
            idx[q++] = base + 2;
            idx[q++] = base + 3;
            base += 4;
        }
        return new MeshData(MeshData.PNC, v, idx);
    }

    /** A glowing band along a rectangle's or polygon's edges. */
    static MeshData outline(Shape shape, DoubleBinaryOperator h, float[] c) {
        List<Vec2> corners;
        if (shape instanceof Shape.Rect r) {
            corners = List.of(r.min(), new Vec2(r.max().x(), r.min().y()), r.max(), new Vec2(r.min().x(), r.max().y()));
        } else {
            corners = ((Shape.Polygon) shape).points();
        }
        List<MeshData> sides = new ArrayList<>();
        for (int i = 0; i < corners.size(); i++) {
            Vec2 a = corners.get(i), b = corners.get((i + 1) % corners.size());
            double length = Math.hypot(b.x() - a.x(), b.y() - a.y());
            if (length == 0) continue;
            sides.add(Shapes.groundArrow(a.x(), a.y(), b.x() - a.x(), b.y() - a.y(), 0, length, 0.02, h, 2 * LIFT, c[0], c[1], c[2]));
        }
        return merge(sides);
    }

    /** {minX, minY, maxX, maxY} of a shape. */
    static double[] box(Shape s) {
        return ShapeBoxes.of(s);
    }

    /**
     * The mesh in position/normal/colour ({@link MeshData#PNC}), the layout this pass draws: the
     * obstacles' meshes carry a material id as a fourth colour component ({@link ObstacleMeshes#LAYOUT}),
     * which is dropped.
     */
    static MeshData pnc(MeshData d) {
        int stride = d.stride();
        if (stride == 9) return d;
        float[] from = d.vertices();
        int count = from.length / stride;
        float[] v = new float[count * 9];
        for (int k = 0; k < count; k++) System.arraycopy(from, k * stride, v, k * 9, 9);
        return new MeshData(MeshData.PNC, v, d.indices());
    }

    private static MeshData recolour(MeshData d, float[] c) {
        float[] v = d.vertices().clone();
        for (int i = 0; i + 8 < v.length; i += 9) {
            v[i + 6] = c[0];
            v[i + 7] = c[1];
            v[i + 8] = c[2];
        }
        return new MeshData(d.layout(), v, d.indices());
    }

    /** The meshes as one (empty when there are none). */
    static MeshData merge(List<MeshData> parts) {
        int floats = 0, indices = 0;
        for (MeshData d : parts) {
            floats += d.vertices().length;
            indices += d.indices().length;
        }
        float[] v = new float[floats];
        int[] idx = new int[indices];
        int fp = 0, ip = 0;
        for (MeshData d : parts) {
            int base = fp / 9;
            System.arraycopy(d.vertices(), 0, v, fp, d.vertices().length);
            for (int i : d.indices()) idx[ip++] = base + i;
            fp += d.vertices().length;
        }
        return new MeshData(MeshData.PNC, v, idx);
    }
}
