package minigolf.collision;

import java.util.List;
import minigolf.course.HeightProbe;
import minigolf.course.Obstacle;
import minigolf.mesh.TriangleMesh;

/**
 * The solid shapes of obstacles in world coordinates, as the collision code uses them and as the
 * renderer should draw them. Walls and boxes become closed triangle meshes; a model's mesh is
 * placed by its position, rotation and scale; a tree is a vertical cylinder.
 *
 * <p>How obstacles stand on the terrain h(x, y) (see docs/course-format.md):
 * <ul>
 * <li>a wall's top runs straight from h(from) + height to h(to) + height; its ends are square and
 * reach thickness/2 beyond from and to (so walls that share an end point close the corner);
 * <li>a tree's top is h(position) + height;
 * <li>walls and trunks reach {@link #FOOTING} below the lowest ground under them, so no ball passes
 * beneath;
 * <li>boxes and models use absolute heights.
 * </ul>
 */
public final class ObstacleGeometry {
    /** How far walls and trunks reach below the lowest ground height sampled along them. */
    public static final double FOOTING = 1.0;
    private static final int GROUND_SAMPLES = 32;

    private ObstacleGeometry() {
    }

    /** A wall, box or model as world-space triangles: 3 vertices of x, y, z per triangle (9 doubles). */
    public static double[] triangles(Obstacle obstacle, HeightProbe ground) {
        if (obstacle instanceof Obstacle.Wall w) return wall(w, ground);
        if (obstacle instanceof Obstacle.Box b) return box(b);
        if (obstacle instanceof Obstacle.Model m) return model(m);
        throw new IllegalArgumentException(obstacle.getClass().getSimpleName()
                + " is not made of triangles (a tree or bumper is a cylinder: use cylinder; a gate is a line)");
    }

    /** Whether the obstacle is a vertical cylinder (a tree's trunk, a bumper), see {@link #cylinder}. */
    public static boolean isCylinder(Obstacle obstacle) {
        return obstacle instanceof Obstacle.Tree || obstacle instanceof Obstacle.Bumper;
    }

    /** A tree trunk or a bumper: {cx, cy, radius, zBottom, zTop}. */
    public static double[] cylinder(Obstacle obstacle, HeightProbe ground) {
        if (obstacle instanceof Obstacle.Tree t) return cylinder(t.position().x(), t.position().y(), t.radius(), t.height(), ground);
        Obstacle.Bumper b = (Obstacle.Bumper) obstacle;
        return cylinder(b.position().x(), b.position().y(), b.radius(), b.height(), ground);
    }

    /** A tree trunk: {cx, cy, radius, zBottom, zTop}. */
    public static double[] treeCylinder(Obstacle.Tree tree, HeightProbe ground) {
        return cylinder(tree, ground);
    }

    private static double[] cylinder(double cx, double cy, double r, double height, HeightProbe ground) {
        double lowest = Double.POSITIVE_INFINITY;
        for (int k = 0; k <= GROUND_SAMPLES; k++) {
            double a = 2 * Math.PI * k / GROUND_SAMPLES;
            lowest = Math.min(lowest, ground.height(cx + r * Math.cos(a), cy + r * Math.sin(a)));
        }
        lowest = Math.min(lowest, ground.height(cx, cy));
        return new double[] {cx, cy, r, lowest - FOOTING, ground.height(cx, cy) + height};
    }

    private static double[] wall(Obstacle.Wall w, HeightProbe ground) {
        double ax = w.from().x(), ay = w.from().y(), bx = w.to().x(), by = w.to().y();
        double dx = bx - ax, dy = by - ay, length = Math.hypot(dx, dy);
        double ux = length > 0 ? dx / length : 1, uy = length > 0 ? dy / length : 0;
        double half = w.thickness() / 2;
        double topA = ground.height(ax, ay) + w.height(), topB = ground.height(bx, by) + w.height();
        double lowest = Double.POSITIVE_INFINITY;
        for (int k = 0; k <= GROUND_SAMPLES; k++) {
            double s = (double) k / GROUND_SAMPLES;
            lowest = Math.min(lowest, ground.height(ax + s * dx, ay + s * dy));
        }
        double bottom = lowest - FOOTING;
        // The slab's ends reach half the thickness beyond the end points.
        double sx = ax - half * ux, sy = ay - half * uy, ex = bx + half * ux, ey = by + half * uy;
        double px = -uy * half, py = ux * half;
        if (half == 0) {
            // A thin fence: one vertical quad, two-sided.
            return quads(new double[][] {{sx, sy, bottom}, {ex, ey, bottom}, {ex, ey, topB}, {sx, sy, topA}});
        }
        double[][] c = {
                {sx - px, sy - py, bottom}, {ex - px, ey - py, bottom}, {ex + px, ey + py, bottom}, {sx + px, sy + py, bottom},
                {sx - px, sy - py, topA}, {ex - px, ey - py, topB}, {ex + px, ey + py, topB}, {sx + px, sy + py, topA}};
        return cuboid(c);
    }

    private static double[] box(Obstacle.Box b) {
        double cx = (b.min().x() + b.max().x()) / 2, cy = (b.min().y() + b.max().y()) / 2;
        double hx = (b.max().x() - b.min().x()) / 2, hy = (b.max().y() - b.min().y()) / 2;
        double angle = Math.toRadians(b.rotationDeg()), cos = Math.cos(angle), sin = Math.sin(angle);
        double[][] c = new double[8][];
        double[][] corners = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
        for (int k = 0; k < 4; k++) {
            double x = cx + cos * corners[k][0] - sin * corners[k][1];
            double y = cy + sin * corners[k][0] + cos * corners[k][1];
            c[k] = new double[] {x, y, b.min().z()};
            c[k + 4] = new double[] {x, y, b.max().z()};
        }
        return cuboid(c);
    }

    private static double[] model(Obstacle.Model m) {
        TriangleMesh mesh = m.mesh();
        float[] p = mesh.positions();
        int[] idx = mesh.indices();
        double angle = Math.toRadians(m.rotationDeg()), cos = Math.cos(angle), sin = Math.sin(angle);
        double s = m.scale();
        double[] out = new double[idx.length * 3];
        for (int k = 0; k < idx.length; k++) {
            int v = idx[k];
            double x = s * p[3 * v], y = s * p[3 * v + 1], z = s * p[3 * v + 2];
            out[3 * k] = m.position().x() + cos * x - sin * y;
            out[3 * k + 1] = m.position().y() + sin * x + cos * y;
            out[3 * k + 2] = m.position().z() + z;
        }
        return out;
    }

    /** 8 corners: 0-3 the bottom ring, 4-7 the top ring above them, in the same order. */
    private static double[] cuboid(double[][] c) {
        int[][] faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
        double[][] quads = new double[faces.length * 4][];
        for (int f = 0; f < faces.length; f++) {
            for (int k = 0; k < 4; k++) quads[4 * f + k] = c[faces[f][k]];
        }
        return quads(quads);
    }

    /** Each run of 4 corners is a quad, split into two triangles. */
    private static double[] quads(double[][] corners) {
        int quads = corners.length / 4;
        double[] out = new double[quads * 18];
        int o = 0;
        for (int q = 0; q < quads; q++) {
            for (int k : new int[] {0, 1, 2, 0, 2, 3}) {
                double[] v = corners[4 * q + k];
                out[o++] = v[0];
                out[o++] = v[1];
                out[o++] = v[2];
            }
        }
        return out;
    }

    /** The number of triangles of the still obstacles (walls, boxes, models: not cylinders, gates or moving ones). */
    public static int triangleCount(List<Obstacle> obstacles, HeightProbe ground) {
        int n = 0;
        for (Obstacle o : obstacles) if (isStillSolid(o) && !isCylinder(o)) n += triangles(o, ground).length / 9;
        return n;
    }

    /**
     * Whether the obstacle is still solid geometry of the course's collision scene: not a gate (which
     * the ball crosses one way) and not a moving obstacle (collided in its own frame).
     */
    public static boolean isStillSolid(Obstacle obstacle) {
        return !(obstacle instanceof Obstacle.Gate) && !(obstacle instanceof Obstacle.Moving);
    }
}
