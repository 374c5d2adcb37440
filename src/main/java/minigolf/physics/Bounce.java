package minigolf.physics;

/**
 * The velocity after a bounce off an obstacle (docs/physics.md, "Continuous collision";
 * docs/course-format.md, "Bumpers"): in the obstacle's frame (relative to its surface's velocity u,
 * 0 for a still obstacle) the normal part of the velocity is turned round and multiplied by the
 * restitution e, the tangential part kept. A bumper (e &gt; 1) gives speed, capped: the ball leaves
 * (in the obstacle's frame) no faster than the larger of the course's maxSpeed and its speed before
 * the bounce, by a smaller normal speed where e times it would be faster.
 */
final class Bounce {
    /** The velocity after the bounce. */
    double vx, vy, vz;

    private final double maxSpeed;

    Bounce(double maxSpeed) {
        this.maxSpeed = maxSpeed;
    }

    /**
     * Bounces the velocity (wx, wy, wz) off the contact normal n (towards the ball) of a surface
     * moving at u, restitution e; the result in {@link #vx}, {@link #vy}, {@link #vz}. A ball not
     * moving into the surface (relative to it) keeps its velocity.
     */
    void off(double wx, double wy, double wz, double nx, double ny, double nz, double e,
             double ux, double uy, double uz) {
        double rx = wx - ux, ry = wy - uy, rz = wz - uz;
        double rn = rx * nx + ry * ny + rz * nz;
        if (rn >= 0) {
            vx = wx;
            vy = wy;
            vz = wz;
            return;
        }
        // The normal part rn becomes -e rn (pointing away): w - (1 + e) rn n.
        double j = -(1 + e) * rn;
        if (e > 1) {
            double speedSquared = rx * rx + ry * ry + rz * rz;
            double cap = Math.max(maxSpeed * maxSpeed, speedSquared);
            double tangentialSquared = Math.max(0, speedSquared - rn * rn);
            double out = Math.sqrt(cap - tangentialSquared);
            if (out < -e * rn) j = out - rn;
        }
        vx = wx + j * nx;
        vy = wy + j * ny;
        vz = wz + j * nz;
    }
}
