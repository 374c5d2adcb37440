package minigolf.course;

import java.util.List;

/**
 * How a moving (kinematic) obstacle moves: a rigid motion that is a function of the course clock
 * alone (docs/course-format.md, "Moving obstacles"), so a stroke's outcome depends on the moment it
 * is played and is still deterministic. Every motion repeats with its {@link #period()}. At clock
 * t the obstacle is its still shape (as the file places it) carried by {@link #poseAt}.
 */
public sealed interface Motion permits Motion.Rotate, Motion.Swing, Motion.Slide {
    /** Seconds after which the motion repeats (&gt; 0). */
    double period();

    /** Seconds added to the course clock before the motion is evaluated. */
    double phase();

    /**
     * The pose at course clock {@code clock}: writes the rigid transform p' = R p + T as 12 doubles
     * (R row by row in [0..8], T in [9..11]) into {@code out}.
     */
    void poseAt(double clock, double[] out);

    /**
     * The velocity field of the obstacle at course clock {@code clock}: a point p of the moved
     * obstacle moves at w x (p - c) + v. Writes w in out[0..2], c in out[3..5], v in out[6..8].
     */
    void velocityAt(double clock, double[] out);

    /** The fraction of the period, in [0, 1), at course clock {@code clock}. */
    default double cycle(double clock) {
        double c = (clock + phase()) / period();
        c -= Math.floor(c);
        return c >= 1 ? 0 : c;
    }

    /**
     * Turns at a constant rate about the axis through {@code pivot}: one turn every {@code period}
     * seconds, counter-clockwise seen from the tip of {@code axis} (right-handed; reverse the axis
     * to turn the other way). Windmill blades (a horizontal axis), a rotating bar (vertical axis).
     */
    record Rotate(Vec3 pivot, Vec3 axis, double period, double phase) implements Motion {
        public void poseAt(double clock, double[] out) {
            rotation(pivot, axis, 2 * Math.PI * cycle(clock), out);
        }

        public void velocityAt(double clock, double[] out) {
            spin(pivot, axis, 2 * Math.PI / period, out);
        }
    }

    /**
     * Swings like a pendulum about the axis through {@code pivot}: the angle is
     * amplitudeDeg·sin(2π (t + phase) / period).
     */
    record Swing(Vec3 pivot, Vec3 axis, double amplitudeDeg, double period, double phase) implements Motion {
        public void poseAt(double clock, double[] out) {
            double angle = Math.toRadians(amplitudeDeg) * Math.sin(2 * Math.PI * cycle(clock));
            rotation(pivot, axis, angle, out);
        }

        public void velocityAt(double clock, double[] out) {
            double rate = Math.toRadians(amplitudeDeg) * 2 * Math.PI / period * Math.cos(2 * Math.PI * cycle(clock));
            spin(pivot, axis, rate, out);
        }
    }

    /**
     * Slides along {@code path} (offsets from the placed shape, in metres; the first is usually
     * [0, 0, 0]) at a constant speed: there and back once per period, or round the closed loop once
     * per period when {@code closed}.
     */
    record Slide(List<Vec3> path, double period, double phase, boolean closed) implements Motion {
        public Slide {
            path = List.copyOf(path);
        }

        /** The length of one period's journey (there and back, or round the loop). */
        public double travel() {
            double length = 0;
            for (int i = 1; i < path.size(); i++) length += distance(path.get(i - 1), path.get(i));
            if (closed) return length + distance(path.get(path.size() - 1), path.get(0));
            return 2 * length;
        }

        public void poseAt(double clock, double[] out) {
            identity(out);
            leg(clock, out, 9, null);
        }

        public void velocityAt(double clock, double[] out) {
            java.util.Arrays.fill(out, 0, 9, 0);
            leg(clock, null, 0, out);
        }

        /**
         * Finds the leg of the path the obstacle is on at the clock; writes the offset there into
         * offset[at..at+2] and the leg's velocity into velocity[6..8] (either may be null).
         */
        private void leg(double clock, double[] offset, int at, double[] velocity) {
            double travel = travel();
            double along = cycle(clock) * travel;
            int n = path.size();
            int legs = closed ? n : 2 * (n - 1);
            for (int leg = 0; leg < legs; leg++) {
                Vec3 a = path.get(point(leg, n)), b = path.get(point(leg + 1, n));
                double length = distance(a, b);
                if (along <= length || leg == legs - 1) {
                    double s = length > 0 ? Math.min(1, along / length) : 0;
                    if (offset != null) {
                        offset[at] = a.x() + s * (b.x() - a.x());
                        offset[at + 1] = a.y() + s * (b.y() - a.y());
                        offset[at + 2] = a.z() + s * (b.z() - a.z());
                    }
                    if (velocity != null && length > 0) {
                        double speed = travel / period / length;
                        velocity[6] = (b.x() - a.x()) * speed;
                        velocity[7] = (b.y() - a.y()) * speed;
                        velocity[8] = (b.z() - a.z()) * speed;
                    }
                    return;
                }
                along -= length;
            }
        }

        /** The path point a leg starts from: forwards, then (not closed) backwards, or round the loop. */
        private int point(int leg, int n) {
            if (closed) return leg % n;
            return leg < n ? leg : 2 * (n - 1) - leg;
        }
    }

    private static double distance(Vec3 a, Vec3 b) {
        return Math.sqrt((b.x() - a.x()) * (b.x() - a.x()) + (b.y() - a.y()) * (b.y() - a.y())
                + (b.z() - a.z()) * (b.z() - a.z()));
    }

    private static void identity(double[] out) {
        java.util.Arrays.fill(out, 0, 12, 0);
        out[0] = 1;
        out[4] = 1;
        out[8] = 1;
    }

    /** A turn at {@code rate} rad/s about the axis through {@code pivot}, as {@link #velocityAt} writes it. */
    private static void spin(Vec3 pivot, Vec3 axis, double rate, double[] out) {
        double length = Math.sqrt(axis.x() * axis.x() + axis.y() * axis.y() + axis.z() * axis.z());
        out[0] = rate * axis.x() / length;
        out[1] = rate * axis.y() / length;
        out[2] = rate * axis.z() / length;
        out[3] = pivot.x();
        out[4] = pivot.y();
        out[5] = pivot.z();
        out[6] = 0;
        out[7] = 0;
        out[8] = 0;
    }

    /** The rotation by {@code angle} about the axis through {@code pivot} (Rodrigues' formula). */
    private static void rotation(Vec3 pivot, Vec3 axis, double angle, double[] out) {
        double length = Math.sqrt(axis.x() * axis.x() + axis.y() * axis.y() + axis.z() * axis.z());
        double kx = axis.x() / length, ky = axis.y() / length, kz = axis.z() / length;
        double c = Math.cos(angle), s = Math.sin(angle), v = 1 - c;
        out[0] = c + kx * kx * v;
        out[1] = kx * ky * v - kz * s;
        out[2] = kx * kz * v + ky * s;
        out[3] = ky * kx * v + kz * s;
        out[4] = c + ky * ky * v;
        out[5] = ky * kz * v - kx * s;
        out[6] = kz * kx * v - ky * s;
        out[7] = kz * ky * v + kx * s;
        out[8] = c + kz * kz * v;
        // T = pivot - R pivot, so the pivot stays where it is.
        out[9] = pivot.x() - (out[0] * pivot.x() + out[1] * pivot.y() + out[2] * pivot.z());
        out[10] = pivot.y() - (out[3] * pivot.x() + out[4] * pivot.y() + out[5] * pivot.z());
        out[11] = pivot.z() - (out[6] * pivot.x() + out[7] * pivot.y() + out[8] * pivot.z());
    }
}
