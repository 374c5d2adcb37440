package minigolf.physics.reference;

import java.util.ArrayList;
import java.util.List;
import minigolf.collision.CollisionScene;
import minigolf.collision.Hit;
import minigolf.course.Motion;
import minigolf.course.Obstacle;
import minigolf.course.Vec3;
import minigolf.physics.World;

/**
 * Moving obstacles for the reference (docs/course-format.md, "Moving obstacles"), apart from the
 * engine's: each obstacle's motion is evaluated here from the course's fields (Rodrigues' rotation
 * in vector form, a slide walked along its path), a point of the ball's path is carried into the
 * obstacle's frame at its own time, and the still body is swept there with the course's geometry
 * (the swept-sphere tests that the still obstacles share with the engine).
 */
final class ReferenceMoving {
    private record Moving(Motion motion, CollisionScene body, double restitution, double[] reach) {
    }

    private final List<Moving> moving = new ArrayList<>();
    private final Hit hit = new Hit();
    private final double[] scratch = new double[3], a = new double[3], b = new double[3];

    /** The last contact: its normal (world), restitution and the obstacle's surface velocity there. */
    double nx, ny, nz, restitution, ux, uy, uz;
    private int last;

    ReferenceMoving(World world) {
        double r = world.physics().ballRadius();
        for (Obstacle o : world.course().obstacles()) {
            if (!(o instanceof Obstacle.Moving m)) continue;
            CollisionScene body = CollisionScene.build(List.of(m.body()), world.terrain()::height, world.bounds(), r);
            moving.add(new Moving(m.motion(), body, m.restitution(), reach(body.extent(), m.motion(), r)));
        }
    }

    boolean none() {
        return moving.isEmpty();
    }

    /** A box of centre positions outside which the obstacle never touches the ball. */
    private static double[] reach(double[] e, Motion motion, double r) {
        if (motion instanceof Motion.Slide s) {
            double[] box = {e[0] - r, e[1] - r, e[3] + r, e[4] + r};
            for (Vec3 p : s.path()) {
                box[0] = Math.min(box[0], e[0] + p.x() - r);
                box[1] = Math.min(box[1], e[1] + p.y() - r);
                box[2] = Math.max(box[2], e[3] + p.x() + r);
                box[3] = Math.max(box[3], e[4] + p.y() + r);
            }
            return box;
        }
        Vec3 c = pivot(motion);
        double far = 0;
        for (double x : new double[] {e[0], e[3]}) {
            for (double y : new double[] {e[1], e[4]}) {
                for (double z : new double[] {e[2], e[5]}) {
                    far = Math.max(far, Math.sqrt((x - c.x()) * (x - c.x()) + (y - c.y()) * (y - c.y()) + (z - c.z()) * (z - c.z())));
                }
            }
        }
        return new double[] {c.x() - far - r, c.y() - far - r, c.x() + far + r, c.y() + far + r};
    }

    private static Vec3 pivot(Motion m) {
        return m instanceof Motion.Rotate r ? r.pivot() : ((Motion.Swing) m).pivot();
    }

    /** The largest rate (rad/s) any obstacle turns at, and the fastest a slide moves (m/s), for the chords' length. */
    double fastestTurn() {
        double w = 0;
        for (Moving m : moving) {
            if (m.motion instanceof Motion.Rotate r) w = Math.max(w, 2 * Math.PI / r.period());
            else if (m.motion instanceof Motion.Swing s) w = Math.max(w, Math.toRadians(s.amplitudeDeg()) * 2 * Math.PI / s.period());
        }
        return w;
    }

    double fastestSlide() {
        double v = 0;
        for (Moving m : moving) if (m.motion instanceof Motion.Slide s) v = Math.max(v, s.travel() / s.period());
        return v;
    }

    /** The longest period, within which a still ball is reached if it ever is. */
    double longestPeriod() {
        double p = 0;
        for (Moving m : moving) p = Math.max(p, m.motion.period());
        return p;
    }

    /**
     * Whether the centre's chord from p (course clock t0) to q (t1), taken in each obstacle's frame
     * between the frames at its ends, touches a moving obstacle.
     */
    boolean touches(double px, double py, double pz, double t0, double qx, double qy, double qz, double t1) {
        for (int k = 0; k < moving.size(); k++) {
            Moving m = moving.get(k);
            double[] box = m.reach;
            if (Math.max(px, qx) < box[0] || Math.min(px, qx) > box[2] || Math.max(py, qy) < box[1] || Math.min(py, qy) > box[3]) {
                continue;
            }
            toBody(m.motion, t0, px, py, pz, a);
            toBody(m.motion, t1, qx, qy, qz, b);
            if (m.body.sweep(a[0], a[1], a[2], b[0], b[1], b[2], hit, scratch)) {
                last = k;
                restitution = m.restitution;
                double lnx = hit.nx, lny = hit.ny, lnz = hit.nz;
                // The normal back in the world: the obstacle's turn at the contact's time.
                double tc = t0 + hit.fraction * (t1 - t0);
                rotateOut(m.motion, tc, lnx, lny, lnz, scratch);
                nx = scratch[0];
                ny = scratch[1];
                nz = scratch[2];
                return true;
            }
        }
        return false;
    }

    /** The velocity of the last contact's obstacle at the world point (x, y, z) at course clock t, into ux, uy, uz. */
    void surfaceVelocity(double x, double y, double z, double t) {
        Motion motion = moving.get(last).motion;
        if (motion instanceof Motion.Slide s) {
            double[] v = slideVelocity(s, t);
            ux = v[0];
            uy = v[1];
            uz = v[2];
            return;
        }
        Vec3 axis = motion instanceof Motion.Rotate r ? r.axis() : ((Motion.Swing) motion).axis();
        double rate;
        if (motion instanceof Motion.Rotate r) {
            rate = 2 * Math.PI / r.period();
        } else {
            Motion.Swing s = (Motion.Swing) motion;
            rate = Math.toRadians(s.amplitudeDeg()) * (2 * Math.PI / s.period()) * Math.cos(2 * Math.PI * (t + s.phase()) / s.period());
        }
        double length = Math.sqrt(axis.x() * axis.x() + axis.y() * axis.y() + axis.z() * axis.z());
        double wx = rate * axis.x() / length, wy = rate * axis.y() / length, wz = rate * axis.z() / length;
        Vec3 c = pivot(motion);
        double rx = x - c.x(), ry = y - c.y(), rz = z - c.z();
        ux = wy * rz - wz * ry;
        uy = wz * rx - wx * rz;
        uz = wx * ry - wy * rx;
    }

    /** The angle (rad) a turning or swinging motion is at, at course clock t. */
    private static double angle(Motion m, double t) {
        if (m instanceof Motion.Rotate r) return 2 * Math.PI * (t + r.phase()) / r.period();
        Motion.Swing s = (Motion.Swing) m;
        return Math.toRadians(s.amplitudeDeg()) * Math.sin(2 * Math.PI * (t + s.phase()) / s.period());
    }

    /** The world point p at course clock t, in the obstacle's still frame, into out. */
    private static void toBody(Motion m, double t, double px, double py, double pz, double[] out) {
        if (m instanceof Motion.Slide s) {
            double[] offset = slideOffset(s, t);
            out[0] = px - offset[0];
            out[1] = py - offset[1];
            out[2] = pz - offset[2];
            return;
        }
        Vec3 c = pivot(m);
        Vec3 axis = m instanceof Motion.Rotate r ? r.axis() : ((Motion.Swing) m).axis();
        turn(axis, -angle(m, t), px - c.x(), py - c.y(), pz - c.z(), out);
        out[0] += c.x();
        out[1] += c.y();
        out[2] += c.z();
    }

    /** A direction in the obstacle's still frame, turned as the obstacle is at course clock t. */
    private static void rotateOut(Motion m, double t, double x, double y, double z, double[] out) {
        if (m instanceof Motion.Slide) {
            out[0] = x;
            out[1] = y;
            out[2] = z;
            return;
        }
        Vec3 axis = m instanceof Motion.Rotate r ? r.axis() : ((Motion.Swing) m).axis();
        turn(axis, angle(m, t), x, y, z, out);
    }

    /** v turned by angle about the axis: v cos + (k x v) sin + k (k . v)(1 - cos). */
    private static void turn(Vec3 axis, double angle, double vx, double vy, double vz, double[] out) {
        double length = Math.sqrt(axis.x() * axis.x() + axis.y() * axis.y() + axis.z() * axis.z());
        double kx = axis.x() / length, ky = axis.y() / length, kz = axis.z() / length;
        double cos = Math.cos(angle), sin = Math.sin(angle), dot = kx * vx + ky * vy + kz * vz;
        out[0] = vx * cos + (ky * vz - kz * vy) * sin + kx * dot * (1 - cos);
        out[1] = vy * cos + (kz * vx - kx * vz) * sin + ky * dot * (1 - cos);
        out[2] = vz * cos + (kx * vy - ky * vx) * sin + kz * dot * (1 - cos);
    }

    /** The path's points in the order a period visits them (there and back, or round the loop, back to the first). */
    private static List<Vec3> journey(Motion.Slide s) {
        List<Vec3> points = new ArrayList<>(s.path());
        if (s.closed()) {
            points.add(s.path().get(0));
        } else {
            for (int i = s.path().size() - 2; i >= 0; i--) points.add(s.path().get(i));
        }
        return points;
    }

    /** How far along its journey (m) a slide is at course clock t. */
    private static double along(Motion.Slide s, double[] lengths, double t) {
        double total = 0;
        for (double l : lengths) total += l;
        double cycles = (t + s.phase()) / s.period();
        return (cycles - Math.floor(cycles)) * total;
    }

    private static double[] legs(List<Vec3> points) {
        double[] lengths = new double[points.size() - 1];
        for (int i = 0; i + 1 < points.size(); i++) {
            Vec3 p = points.get(i), q = points.get(i + 1);
            lengths[i] = Math.sqrt((q.x() - p.x()) * (q.x() - p.x()) + (q.y() - p.y()) * (q.y() - p.y()) + (q.z() - p.z()) * (q.z() - p.z()));
        }
        return lengths;
    }

    private static double[] slideOffset(Motion.Slide s, double t) {
        List<Vec3> points = journey(s);
        double[] lengths = legs(points);
        double d = along(s, lengths, t);
        for (int i = 0; i < lengths.length; i++) {
            if (d <= lengths[i] || i == lengths.length - 1) {
                double f = lengths[i] == 0 ? 0 : Math.min(1, d / lengths[i]);
                Vec3 p = points.get(i), q = points.get(i + 1);
                return new double[] {p.x() + f * (q.x() - p.x()), p.y() + f * (q.y() - p.y()), p.z() + f * (q.z() - p.z())};
            }
            d -= lengths[i];
        }
        throw new AssertionError();
    }

    private static double[] slideVelocity(Motion.Slide s, double t) {
        List<Vec3> points = journey(s);
        double[] lengths = legs(points);
        double total = 0;
        for (double l : lengths) total += l;
        double speed = total / s.period();
        double d = along(s, lengths, t);
        for (int i = 0; i < lengths.length; i++) {
            if ((d <= lengths[i] || i == lengths.length - 1) && lengths[i] > 0) {
                Vec3 p = points.get(i), q = points.get(i + 1);
                return new double[] {(q.x() - p.x()) / lengths[i] * speed, (q.y() - p.y()) / lengths[i] * speed,
                        (q.z() - p.z()) / lengths[i] * speed};
            }
            d -= lengths[i];
        }
        return new double[3];
    }
}
