package minigolf.editor;

import minigolf.course.Motion;
import minigolf.course.Obstacle;
import minigolf.course.Vec2;
import minigolf.course.Vec3;

/** Where an obstacle is, and the same obstacle moved or turned. Pure functions on the course records. */
public final class ObstacleTools {
    private ObstacleTools() {
    }

    /** The obstacle's reference point in the plane: a wall's midpoint, a box's centre, a tree's or model's position. */
    public static Vec2 center(Obstacle o) {
        if (o instanceof Obstacle.Moving m) return center(m.body());
        if (o instanceof Obstacle.Wall w) return new Vec2(0.5 * (w.from().x() + w.to().x()), 0.5 * (w.from().y() + w.to().y()));
        if (o instanceof Obstacle.Gate g) return new Vec2(0.5 * (g.from().x() + g.to().x()), 0.5 * (g.from().y() + g.to().y()));
        if (o instanceof Obstacle.Tree t) return t.position();
        if (o instanceof Obstacle.Bumper b) return b.position();
        if (o instanceof Obstacle.Box b) return new Vec2(0.5 * (b.min().x() + b.max().x()), 0.5 * (b.min().y() + b.max().y()));
        Obstacle.Model m = (Obstacle.Model) o;
        return new Vec2(m.position().x(), m.position().y());
    }

    /** A short name for lists: "wall", "tree", "box", "model windmill.obj", "bumper", "gate", "turning box". */
    public static String describe(Obstacle o) {
        if (o instanceof Obstacle.Moving m) {
            String how = m.motion() instanceof Motion.Rotate ? "turning " : m.motion() instanceof Motion.Swing ? "swinging " : "sliding ";
            return how + describe(m.body());
        }
        if (o instanceof Obstacle.Wall) return "wall";
        if (o instanceof Obstacle.Tree) return "tree";
        if (o instanceof Obstacle.Bumper) return "bumper";
        if (o instanceof Obstacle.Gate) return "one-way gate";
        if (o instanceof Obstacle.Box) return "box";
        return "model " + ((Obstacle.Model) o).file();
    }

    /** The obstacle shifted by (dx, dy) in the plane (a box and a model keep their absolute heights). */
    public static Obstacle moved(Obstacle o, double dx, double dy) {
        if (o instanceof Obstacle.Moving m) return new Obstacle.Moving(moved(m.body(), dx, dy), MotionTools.moved(m.motion(), dx, dy));
        if (o instanceof Obstacle.Bumper b) return new Obstacle.Bumper(shift(b.position(), dx, dy), b.radius(), b.height(), b.restitution());
        if (o instanceof Obstacle.Gate g) {
            return new Obstacle.Gate(shift(g.from(), dx, dy), shift(g.to(), dx, dy), g.height(), g.passTo(), g.restitution());
        }
        if (o instanceof Obstacle.Wall w) {
            return new Obstacle.Wall(shift(w.from(), dx, dy), shift(w.to(), dx, dy), w.thickness(), w.height(), w.restitution());
        }
        if (o instanceof Obstacle.Tree t) return new Obstacle.Tree(shift(t.position(), dx, dy), t.radius(), t.height(), t.restitution());
        if (o instanceof Obstacle.Box b) {
            return new Obstacle.Box(shift(b.min(), dx, dy), shift(b.max(), dx, dy), b.rotationDeg(), b.restitution());
        }
        Obstacle.Model m = (Obstacle.Model) o;
        return new Obstacle.Model(m.file(), shift(m.position(), dx, dy), m.rotationDeg(), m.scale(), m.restitution(), m.mesh());
    }

    /** The obstacle turned counter-clockwise by {@code degrees} about its {@link #center}; a tree is unchanged. */
    public static Obstacle rotated(Obstacle o, double degrees) {
        if (o instanceof Obstacle.Moving m) {
            return new Obstacle.Moving(rotated(m.body(), degrees), MotionTools.rotated(m.motion(), center(m.body()), degrees));
        }
        if (o instanceof Obstacle.Bumper) return o;
        if (o instanceof Obstacle.Gate g) {
            Vec2 c = center(g);
            double a = Math.toRadians(degrees), cos = Math.cos(a), sin = Math.sin(a);
            return new Obstacle.Gate(turn(g.from(), c, cos, sin), turn(g.to(), c, cos, sin), g.height(), g.passTo(), g.restitution());
        }
        if (o instanceof Obstacle.Wall w) {
            Vec2 c = center(w);
            double a = Math.toRadians(degrees), cos = Math.cos(a), sin = Math.sin(a);
            return new Obstacle.Wall(turn(w.from(), c, cos, sin), turn(w.to(), c, cos, sin), w.thickness(), w.height(),
                    w.restitution());
        }
        if (o instanceof Obstacle.Tree) return o;
        if (o instanceof Obstacle.Box b) return new Obstacle.Box(b.min(), b.max(), normalise(b.rotationDeg() + degrees), b.restitution());
        Obstacle.Model m = (Obstacle.Model) o;
        return new Obstacle.Model(m.file(), m.position(), normalise(m.rotationDeg() + degrees), m.scale(), m.restitution(), m.mesh());
    }

    /** The distance from (x, y) to the obstacle's reference (a wall's segment, else its centre), for picking. */
    public static double distance(Obstacle o, double x, double y) {
        if (o instanceof Obstacle.Moving m) return distance(m.body(), x, y);
        if (o instanceof Obstacle.Wall || o instanceof Obstacle.Gate) {
            Vec2 from = o instanceof Obstacle.Wall w ? w.from() : ((Obstacle.Gate) o).from();
            Vec2 to = o instanceof Obstacle.Wall w ? w.to() : ((Obstacle.Gate) o).to();
            double ax = from.x(), ay = from.y(), bx = to.x() - ax, by = to.y() - ay;
            double len2 = bx * bx + by * by;
            double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - ax) * bx + (y - ay) * by) / len2));
            return Math.hypot(x - ax - t * bx, y - ay - t * by);
        }
        Vec2 c = center(o);
        return Math.hypot(x - c.x(), y - c.y());
    }

    /** The same obstacle with another restitution. */
    public static Obstacle withRestitution(Obstacle o, double r) {
        if (o instanceof Obstacle.Moving m) return new Obstacle.Moving(withRestitution(m.body(), r), m.motion());
        if (o instanceof Obstacle.Bumper b) return new Obstacle.Bumper(b.position(), b.radius(), b.height(), r);
        if (o instanceof Obstacle.Gate g) return new Obstacle.Gate(g.from(), g.to(), g.height(), g.passTo(), r);
        if (o instanceof Obstacle.Wall w) return new Obstacle.Wall(w.from(), w.to(), w.thickness(), w.height(), r);
        if (o instanceof Obstacle.Tree t) return new Obstacle.Tree(t.position(), t.radius(), t.height(), r);
        if (o instanceof Obstacle.Box b) return new Obstacle.Box(b.min(), b.max(), b.rotationDeg(), r);
        Obstacle.Model m = (Obstacle.Model) o;
        return new Obstacle.Model(m.file(), m.position(), m.rotationDeg(), m.scale(), r, m.mesh());
    }

    private static double normalise(double deg) {
        double d = deg % 360;
        return d < 0 ? d + 360 : d;
    }

    private static Vec2 shift(Vec2 v, double dx, double dy) {
        return new Vec2(v.x() + dx, v.y() + dy);
    }

    private static Vec3 shift(Vec3 v, double dx, double dy) {
        return new Vec3(v.x() + dx, v.y() + dy, v.z());
    }

    private static Vec2 turn(Vec2 p, Vec2 c, double cos, double sin) {
        double x = p.x() - c.x(), y = p.y() - c.y();
        return new Vec2(c.x() + cos * x - sin * y, c.y() + sin * x + cos * y);
    }
}
