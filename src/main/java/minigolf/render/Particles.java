package minigolf.render;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

/**
 * The game's small effects as particles, simulated here without OpenGL and drawn as one mesh of
 * little lit squares ({@link #mesh()}): confetti bursting from the cup when a ball is holed (more,
 * higher and with gold for a hole in one) and a splash of droplets where a ball goes into the water.
 * Each burst is deterministic (its seed); particles live a fixed time and the effect ends by itself.
 */
public final class Particles {
    public enum Kind {
        /** A ball holed: a burst of confetti from the cup. */
        CONFETTI(70, 2.0, 2.2, 0.05),
        /** A hole in one: twice the confetti, higher, with gold, for longer. */
        ACE_CONFETTI(170, 2.9, 3.2, 0.06),
        /** A ball into the water: a ring of droplets. */
        SPLASH(40, 1.6, 0.9, 0.022);

        final int count;
        final double launch;
        final double life;
        final double size;

        Kind(int count, double launch, double life, double size) {
            this.count = count;
            this.launch = launch;
            this.life = life;
            this.size = size;
        }

        public int count() {
            return count;
        }

        public double life() {
            return life;
        }
    }

    static final double GRAVITY = 9.81;
    /** Confetti flutters down at about this speed (m/s) once past the top of its flight. */
    static final double FLUTTER_SPEED = 0.6;
    private static final float[][] CONFETTI_COLOURS = {
        {0.95f, 0.25f, 0.25f}, {0.25f, 0.55f, 0.95f}, {0.98f, 0.85f, 0.2f}, {0.3f, 0.85f, 0.35f}, {0.85f, 0.35f, 0.9f},
        {1f, 0.6f, 0.15f}};
    private static final float[] GOLD = {1f, 0.8f, 0.25f};

    private static final class P {
        double x, y, z, vx, vy, vz, age, life, size, spin, spinRate, tilt;
        float r, g, b;
        boolean confetti;
        double floor;
    }

    private final List<P> live = new ArrayList<>();
    private double lastTime = Double.NaN;

    /** Starts a burst of {@code kind} at (x, y, z) (the cup, the point where the ball met the water). */
    public void burst(Kind kind, double x, double y, double z, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int i = 0; i < kind.count; i++) {
            P p = new P();
            p.x = x;
            p.y = y;
            p.z = z + 0.02;
            double a = random.nextDouble() * 2 * Math.PI;
            boolean confetti = kind != Kind.SPLASH;
            double out = confetti ? 0.2 + random.nextDouble() * 0.9 : 0.3 + random.nextDouble() * 0.5;
            p.vx = out * Math.cos(a);
            p.vy = out * Math.sin(a);
            p.vz = kind.launch * (0.6 + 0.4 * random.nextDouble());
            p.life = kind.life * (0.75 + 0.25 * random.nextDouble());
            p.size = kind.size * (0.7 + 0.6 * random.nextDouble());
            p.spin = random.nextDouble() * 2 * Math.PI;
            p.spinRate = (random.nextDouble() - 0.5) * 24;
            p.tilt = random.nextDouble() * Math.PI;
            p.confetti = confetti;
            p.floor = confetti ? z - 0.05 : Math.min(z, 0) - 0.01;
            float[] c;
            if (kind == Kind.SPLASH) {
                float w = (float) (0.75 + 0.25 * random.nextDouble());
                c = new float[]{0.7f * w, 0.85f * w, w};
            } else if (kind == Kind.ACE_CONFETTI && i % 3 == 0) {
                c = GOLD;
            } else {
                c = CONFETTI_COLOURS[random.nextInt(CONFETTI_COLOURS.length)];
            }
            p.r = c[0];
            p.g = c[1];
            p.b = c[2];
            live.add(p);
        }
    }

    /** Advances every particle by {@code dt} seconds; spent ones go. */
    public void update(double dt) {
        if (!(dt > 0)) return;
        dt = Math.min(dt, 0.1); // a long frame does not throw the confetti through the ground
        for (int i = live.size() - 1; i >= 0; i--) {
            P p = live.get(i);
            p.age += dt;
            if (p.confetti) {
                p.vx *= Math.exp(-1.2 * dt);
                p.vy *= Math.exp(-1.2 * dt);
                p.vz -= GRAVITY * 0.6 * dt;
                // Past the top a paper square catches the air: it settles to a slow flutter.
                if (p.vz < -FLUTTER_SPEED) p.vz += (-FLUTTER_SPEED - p.vz) * (1 - Math.exp(-8 * dt));
                p.spin += p.spinRate * dt;
            } else {
                p.vz -= GRAVITY * dt;
            }
            p.x += p.vx * dt;
            p.y += p.vy * dt;
            p.z += p.vz * dt;
            if (p.age >= p.life || p.z < p.floor) live.remove(i);
        }
    }

    /** Advances to {@code time} (seconds, any clock), the first call only setting the clock. */
    public void advanceTo(double time) {
        if (!Double.isNaN(lastTime)) update(time - lastTime);
        lastTime = time;
    }

    public boolean isActive() {
        return !live.isEmpty();
    }

    public int count() {
        return live.size();
    }

    /** The highest particle's height, for tests (NaN when none). */
    public double top() {
        return live.stream().mapToDouble(p -> p.z).max().orElse(Double.NaN);
    }

    public void clear() {
        live.clear();
    }

    /** Every live particle as a small square (two triangles, PNC), turned by its spin; null when none. */
    public MeshData mesh() {
        if (live.isEmpty()) return null;
        float[] v = new float[live.size() * 6 * 9];
        int[] idx = new int[live.size() * 6];
        int f = 0;
        for (int n = 0; n < live.size(); n++) {
            P p = live.get(n);
            // Two edge vectors: one turning in the horizontal plane, one tilted up by the particle's tilt.
            double cs = Math.cos(p.spin), sn = Math.sin(p.spin), ct = Math.cos(p.tilt + p.spin * 0.5), st = Math.sin(p.tilt + p.spin * 0.5);
            double h = p.size / 2;
            double ux = cs * h, uy = sn * h, uz = 0;
            double wx = -sn * ct * h, wy = cs * ct * h, wz = st * h;
            double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
            double l = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (l == 0) {
                nx = 0;
                ny = 0;
                nz = 1;
            } else {
                if (nz < 0) l = -l; // lit from above whichever side faces up
                nx /= l;
                ny /= l;
                nz /= l;
            }
            double[][] corners = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
            for (double[] c : corners) {
                f = Shapes.putPnc(v, f, p.x + c[0] * ux + c[1] * wx, p.y + c[0] * uy + c[1] * wy, p.z + c[0] * uz + c[1] * wz,
                        nx, ny, nz, p.r, p.g, p.b);
            }
        }
        for (int i = 0; i < idx.length; i++) idx[i] = i;
        return new MeshData(MeshData.PNC, v, idx);
    }
}
