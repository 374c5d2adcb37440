package minigolf.scenery;

import java.util.Random;

/**
 * The props' shapes, one method per kind, written into a {@link MeshWriter} at a place: a few dozen to a
 * few hundred flat-shaded triangles each, in their own colours (a software rasteriser pays per
 * triangle). {@code rock} is the world's rock colour; {@code snowy} puts snow on tops and tiers.
 * Sizes in metres; z is the ground's height where the prop stands.
 */
public final class PropMeshes {
    static final float[] BARK = {0.36f, 0.25f, 0.16f};
    static final float[] PINE_GREEN = {0.13f, 0.30f, 0.17f};
    static final float[] SNOW = {0.93f, 0.95f, 0.98f};
    static final float[] CACTUS_GREEN = {0.27f, 0.47f, 0.25f};
    static final float[] FENCE_WOOD = {0.55f, 0.42f, 0.28f};
    static final float[] IRON = {0.16f, 0.17f, 0.18f};
    static final float[] LAMP_GLOW = {1.0f, 0.86f, 0.50f};
    static final float[] CASTLE_STONE = {0.60f, 0.60f, 0.62f};
    static final float[] ROOF_SLATE = {0.28f, 0.30f, 0.40f};
    static final float[] WHITE = {0.94f, 0.94f, 0.92f};
    static final float[] RED = {0.78f, 0.16f, 0.14f};
    static final float[] MARRAM = {0.52f, 0.60f, 0.32f};
    static final float[] GATEWAY = {0.10f, 0.09f, 0.09f};
    /** A castle wall's courses of stone, bottom up, and their shades. */
    static final int COURSES = 4;
    static final double[] COURSE_SHADES = {0.94, 1.03, 0.97, 1.06};
    static final float[][] HUT_COLOURS = {{0.85f, 0.25f, 0.25f}, {0.25f, 0.50f, 0.80f}, {0.95f, 0.80f, 0.25f},
            {0.35f, 0.70f, 0.45f}, {0.90f, 0.55f, 0.70f}};
    static final float[][] FLOWER_COLOURS = {{0.95f, 0.85f, 0.20f}, {0.92f, 0.30f, 0.35f}, {0.95f, 0.95f, 0.95f},
            {0.95f, 0.55f, 0.75f}, {0.98f, 0.60f, 0.20f}};

    private PropMeshes() {
    }

    /** A weathered rock, {@code size} metres across, sunk a little into the ground. */
    public static void rock(MeshWriter w, double x, double y, double z, double size, long seed, float[] rock, boolean snowy) {
        Random r = new Random(seed);
        double sx = size * (0.8 + 0.4 * r.nextDouble()), sy = size * (0.7 + 0.4 * r.nextDouble());
        float[] c = shade(rock, 0.85 + 0.25 * r.nextDouble());
        w.lump(x, y, z - 0.15 * size, sx / 2, sy / 2, size * (0.35 + 0.2 * r.nextDouble()), 0.22, seed, true, z - 0.05,
                c, snowy ? SNOW : shade(c, 1.08));
    }

    /** A conifer {@code height} metres tall: a trunk and three tiers, snow on the tiers in winter. */
    public static void pine(MeshWriter w, double x, double y, double z, double height, boolean snowy) {
        w.frustum(x, y, z, z + height * 0.25, height * 0.035, height * 0.025, 6, true, BARK);
        pineTiers(w, x, y, z, height, snowy);
    }

    /** A conifer's three tiers (snow-capped in winter) for a tree {@code height} tall standing at z. */
    public static void pineTiers(MeshWriter w, double x, double y, double z, double height, boolean snowy) {
        double r = height * 0.26;
        for (int t = 0; t < 3; t++) {
            double base = z + height * (0.18 + 0.24 * t), top = base + height * (0.42 - 0.04 * t);
            double rt = r * (1 - 0.25 * t);
            w.frustum(x, y, base, top, rt, 0, 8, false, PINE_GREEN);
            if (snowy) w.frustum(x, y, base + (top - base) * 0.5, top + 0.03, rt * 0.56, 0, 8, false, SNOW);
        }
    }

    /** A saguaro: a ribbed column with a rounded top and one or two arms. */
    public static void cactus(MeshWriter w, double x, double y, double z, double height, long seed) {
        double rad = height * 0.075;
        w.frustum(x, y, z, z + height - rad, rad, rad * 0.95, 8, true, CACTUS_GREEN);
        cactusTop(w, x, y, z, height, rad, seed);
    }

    /**
     * What a saguaro has besides its column (of radius {@code rad} from z to z + height - rad): the
     * domed top and one or two arms. A course's cactus (a tree obstacle) is its own collision
     * cylinder with these on it.
     */
    public static void cactusTop(MeshWriter w, double x, double y, double z, double height, double rad, long seed) {
        Random r = new Random(seed);
        w.lump(x, y, z + height - rad, rad * 0.95, rad * 0.95, rad, 0, seed, false, z, CACTUS_GREEN, CACTUS_GREEN);
        int arms = 1 + r.nextInt(2);
        double heading = r.nextDouble() * 2 * Math.PI;
        for (int a = 0; a < arms; a++) {
            double dir = heading + a * Math.PI, ar = rad * 0.7;
            double at = z + height * (0.35 + 0.2 * r.nextDouble()), out = rad + height * 0.12;
            double ex = x + Math.cos(dir) * out, ey = y + Math.sin(dir) * out;
            // The elbow: out from the trunk, then up.
            double mx = x + Math.cos(dir) * out * 0.5, my = y + Math.sin(dir) * out * 0.5;
            w.box(mx, my, at - ar, at + ar, out, 2 * ar, Math.toDegrees(dir), 1, CACTUS_GREEN);
            double armTop = at + height * (0.2 + 0.15 * r.nextDouble());
            w.frustum(ex, ey, at - ar, armTop, ar, ar * 0.95, 6, true, CACTUS_GREEN);
            w.lump(ex, ey, armTop, ar * 0.95, ar * 0.95, ar, 0, seed + a, false, at, CACTUS_GREEN, CACTUS_GREEN);
        }
    }

    /** A clump of flowers: small coloured heads on stalks. */
    public static void flowers(MeshWriter w, double x, double y, double z, long seed) {
        flowers(w, x, y, z, seed, false);
    }

    /**
     * As above; {@code light} (the software tier, which pays per triangle): each head, 4.5 cm across,
     * from the plain icosahedron (20 faces instead of 80; a clump 260 triangles instead of 800).
     */
    public static void flowers(MeshWriter w, double x, double y, double z, long seed, boolean light) {
        Random r = new Random(seed);
        float[] colour = FLOWER_COLOURS[r.nextInt(FLOWER_COLOURS.length)];
        float[] stalk = {0.16f, 0.34f, 0.11f};
        // A tuft of leaves, then the heads just above it.
        w.lump(x, y, z, 0.28, 0.24, 0.07, 0.25, seed, true, z - 0.01, stalk, PropMeshes.shade(stalk, 1.2));
        for (int k = 0; k < 9; k++) {
            double a = r.nextDouble() * 2 * Math.PI, d = 0.22 * Math.sqrt(r.nextDouble());
            double px = x + Math.cos(a) * d, py = y + Math.sin(a) * d;
            double h = 0.07 + 0.06 * r.nextDouble();
            w.lump(px, py, z + h, 0.045, 0.045, 0.03, 0.2, seed + k, true, z, colour, colour, light);
        }
    }

    /** A post-and-rail fence from (x0, y0) to (x1, y1): posts every 1.2 m, two rails. */
    public static void fence(MeshWriter w, double x0, double y0, double x1, double y1, double z, boolean snowy) {
        double len = Math.hypot(x1 - x0, y1 - y0), turn = Math.toDegrees(Math.atan2(y1 - y0, x1 - x0));
        int posts = Math.max(2, (int) Math.round(len / 1.2) + 1);
        for (int k = 0; k < posts; k++) {
            double t = (double) k / (posts - 1);
            double px = x0 + (x1 - x0) * t, py = y0 + (y1 - y0) * t;
            w.box(px, py, z - 0.1, z + 0.75, 0.09, 0.09, turn, 0.9, FENCE_WOOD);
            if (snowy) w.box(px, py, z + 0.75, z + 0.79, 0.1, 0.1, turn, 0.8, SNOW);
        }
        double mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
        for (double h : new double[]{0.35, 0.62}) w.box(mx, my, z + h, z + h + 0.06, len, 0.04, turn, 1, shade(FENCE_WOOD, 1.1));
    }

    /** A lamp post: a dark iron pole with a lantern that glows warm. */
    public static void lampPost(MeshWriter w, double x, double y, double z, boolean snowy) {
        w.frustum(x, y, z, z + 0.15, 0.09, 0.07, 6, false, IRON);
        w.frustum(x, y, z + 0.15, z + 2.1, 0.04, 0.03, 6, true, IRON);
        w.box(x, y, z + 2.1, z + 2.42, 0.2, 0.2, 45, 1.15, LAMP_GLOW);
        w.frustum(x, y, z + 2.42, z + 2.62, 0.19, 0, 4, false, IRON);
        if (snowy) w.frustum(x, y, z + 2.5, z + 2.64, 0.1, 0, 4, false, SNOW);
    }

    /**
     * A castle facing the course: a curtain wall with merlons, a gatehouse, round corner towers with
     * slate cones, {@code size} metres wide. {@code facingDeg}: the direction it faces.
     */
    public static void castle(MeshWriter w, double x, double y, double z, double size, double facingDeg, boolean snowy) {
        double a = Math.toRadians(facingDeg), fx = Math.cos(a), fy = Math.sin(a), sx = -fy, sy = fx;
        double half = size / 2, wallH = size * 0.16, depth = size * 0.45;
        float[] stone = CASTLE_STONE, dark = shade(stone, 0.85);
        // Front wall (towards the course) either side of the gate, side walls, back wall.
        double[][] walls = {
                {-half, 0, -size * 0.1, 0}, {size * 0.1, 0, half, 0},
                {-half, 0, -half, -depth}, {half, 0, half, -depth}, {-half, -depth, half, -depth}};
        for (double[] wl : walls) {
            double ax = x + sx * wl[0] + fx * wl[1], ay = y + sy * wl[0] + fy * wl[1];
            double bx = x + sx * wl[2] + fx * wl[3], by = y + sy * wl[2] + fy * wl[3];
            double len = Math.hypot(bx - ax, by - ay), turn = Math.toDegrees(Math.atan2(by - ay, bx - ax));
            float[] face = wl[1] == 0 && wl[3] == 0 ? stone : dark;
            // A battered plinth, then courses of stone in slightly different shades, so the wall reads as masonry from the tee.
            w.box((ax + bx) / 2, (ay + by) / 2, z - 0.5, z + wallH * 0.18, len + size * 0.02, size * 0.075, turn, 0.9, shade(face, 0.8));
            for (int c = 0; c < COURSES; c++) {
                double z0 = z + wallH * (0.18 + 0.82 * c / COURSES), z1 = z + wallH * (0.18 + 0.82 * (c + 1) / COURSES);
                w.box((ax + bx) / 2, (ay + by) / 2, z0, z1, len, size * (c % 2 == 0 ? 0.05 : 0.049), turn, 1,
                        shade(face, COURSE_SHADES[c % COURSE_SHADES.length]));
            }
            int merlons = (int) (len / (size * 0.06));
            for (int k = 0; k < merlons; k += 2) {
                double t = (k + 0.5) / merlons;
                w.box(ax + (bx - ax) * t, ay + (by - ay) * t, z + wallH, z + wallH + size * 0.035, len / merlons, size * 0.05,
                        turn, 1, stone);
            }
            if (snowy) w.box((ax + bx) / 2, (ay + by) / 2, z + wallH, z + wallH + 0.05, len, size * 0.05, turn, 1, SNOW);
        }
        // Gatehouse over the gap (a dark gateway in its face), then the keep behind with its windows.
        w.box(x + fx * 0.2, y + fy * 0.2, z + wallH * 0.55, z + wallH * 1.35, size * 0.24, size * 0.12, facingDeg + 90, 1, stone);
        w.box(x + fx * (0.2 + size * 0.061), y + fy * (0.2 + size * 0.061), z, z + wallH * 0.5, size * 0.12, size * 0.004,
                facingDeg + 90, 1, GATEWAY);
        double kx = x - fx * depth * 0.55, ky = y - fy * depth * 0.55;
        w.box(kx, ky, z - 0.5, z + wallH * 2.2, size * 0.26, size * 0.22, facingDeg, 1, dark);
        for (int row = 0; row < 2; row++) {
            for (int col = -1; col <= 1; col++) {
                double off = size * 0.111, side = col * size * 0.07;
                w.box(kx + fx * off + sx * side, ky + fy * off + sy * side, z + wallH * (1.3 + 0.5 * row), z + wallH * (1.55 + 0.5 * row),
                        size * 0.02, size * 0.004, facingDeg + 90, 1, GATEWAY);
            }
        }
        w.frustum(kx, ky, z + wallH * 3.0 - 0.2, z + wallH * 3.0 + size * 0.09, size * 0.004, size * 0.004, 4, false, IRON);
        double[] poleTop = {kx, ky, z + wallH * 3.0 + size * 0.09}, poleMid = {kx, ky, z + wallH * 3.0 + size * 0.06};
        double[] tip = {kx + sx * size * 0.06, ky + sy * size * 0.06, z + wallH * 3.0 + size * 0.075};
        w.flatTriangle(poleMid, tip, poleTop, RED);
        w.flatTriangle(poleTop, tip, poleMid, RED);
        w.frustum(x - fx * depth * 0.55, y - fy * depth * 0.55, z + wallH * 2.2, z + wallH * 3.0, size * 0.17, 0, 4, false,
                snowy ? SNOW : ROOF_SLATE);
        double[][] towers = {{-half, 0}, {half, 0}, {-half, -depth}, {half, -depth}};
        for (double[] t : towers) {
            double tx = x + sx * t[0] + fx * t[1], ty = y + sy * t[0] + fy * t[1];
            double r = size * 0.07, h = wallH * 1.6;
            w.frustum(tx, ty, z - 0.5, z + h, r, r * 0.95, 10, true, stone);
            w.frustum(tx, ty, z + h * 0.45, z + h * 0.5, r * 1.01, r * 1.0, 10, true, shade(stone, 0.85));
            // An arrow slit facing the course.
            w.box(tx + fx * r * 0.97, ty + fy * r * 0.97, z + h * 0.62, z + h * 0.8, size * 0.012, size * 0.004, facingDeg + 90, 1, GATEWAY);
            w.frustum(tx, ty, z + h, z + h + r * 2.4, r * 1.2, 0, 10, false, snowy ? SNOW : ROOF_SLATE);
        }
    }

    /** A butte: layered rock with a flat top, {@code width} across and {@code height} tall, the strata banded. */
    public static void mesa(MeshWriter w, double x, double y, double z, double width, double height, long seed, float[] rock) {
        Random r = new Random(seed);
        int n = 10;
        double[] radius = new double[n];
        for (int k = 0; k < n; k++) radius[k] = width / 2 * (0.75 + 0.35 * r.nextDouble());
        double[] levels = {0, 0.35, 0.45, 0.8, 1.0};
        double[] widen = {1.25, 1.05, 1.0, 0.97, 0.95};
        for (int l = 0; l + 1 < levels.length; l++) {
            float[] band = shade(rock, l % 2 == 0 ? 0.95 + 0.1 * r.nextDouble() : 1.12);
            for (int k = 0; k < n; k++) {
                int m = (k + 1) % n;
                double a0 = 2 * Math.PI * k / n, a1 = 2 * Math.PI * m / n;
                double[] p00 = ring(x, y, z + height * levels[l], radius[k] * widen[l], a0);
                double[] p01 = ring(x, y, z + height * levels[l], radius[m] * widen[l], a1);
                double[] p11 = ring(x, y, z + height * levels[l + 1], radius[m] * widen[l + 1], a1);
                double[] p10 = ring(x, y, z + height * levels[l + 1], radius[k] * widen[l + 1], a0);
                w.flatQuad(p00, p01, p11, p10, band);
            }
        }
        double[] centre = {x, y, z + height};
        float[] top = shade(rock, 1.05);
        for (int k = 0; k < n; k++) {
            int m = (k + 1) % n;
            w.flatTriangle(centre, ring(x, y, z + height, radius[k] * 0.95, 2 * Math.PI * k / n),
                    ring(x, y, z + height, radius[m] * 0.95, 2 * Math.PI * m / n), top);
        }
    }

    private static double[] ring(double x, double y, double z, double r, double a) {
        return new double[]{x + r * Math.cos(a), y + r * Math.sin(a), z};
    }

    /** A lighthouse on a rock: a white tower with red bands, a gallery, a lantern room and a red cap. */
    public static void lighthouse(MeshWriter w, double x, double y, double z, float[] rock) {
        w.lump(x, y, z - 0.5, 2.6, 2.3, 1.8, 0.25, 7, true, z - 1, shade(rock, 0.9), shade(rock, 1.0));
        double base = z + 1.0, h = 11;
        for (int band = 0; band < 5; band++) {
            double z0 = base + h * band / 5, z1 = base + h * (band + 1) / 5;
            double r0 = 1.3 - 0.5 * band / 5, r1 = 1.3 - 0.5 * (band + 1) / 5;
            w.frustum(x, y, z0, z1, r0, r1, 12, true, band % 2 == 0 ? WHITE : RED);
        }
        double top = base + h;
        w.frustum(x, y, top, top + 0.2, 1.15, 1.15, 12, false, IRON);
        w.frustum(x, y, top + 0.2, top + 1.3, 0.6, 0.6, 8, false, LAMP_GLOW);
        w.frustum(x, y, top + 1.3, top + 2.0, 0.75, 0, 8, false, RED);
    }

    /** A beach hut: a painted box with a pitched roof and a white door, facing {@code facingDeg}. */
    public static void hut(MeshWriter w, double x, double y, double z, double facingDeg, int colour) {
        float[] c = HUT_COLOURS[Math.floorMod(colour, HUT_COLOURS.length)];
        double a = Math.toRadians(facingDeg), fx = Math.cos(a), fy = Math.sin(a);
        w.box(x, y, z - 0.2, z + 1.7, 1.5, 1.4, facingDeg, 1, c);
        w.box(x + fx * 0.71, y + fy * 0.71, z, z + 1.4, 0.04, 0.6, facingDeg, 1, WHITE);
        // The roof: a prism along the facing direction.
        double sx = -fy, sy = fx;
        double[] l0 = {x - fx * 0.85 + sx * 0.82, y - fy * 0.85 + sy * 0.82, z + 1.7}, l1 = {x + fx * 0.85 + sx * 0.82, y + fy * 0.85 + sy * 0.82, z + 1.7};
        double[] r0 = {x - fx * 0.85 - sx * 0.82, y - fy * 0.85 - sy * 0.82, z + 1.7}, r1 = {x + fx * 0.85 - sx * 0.82, y + fy * 0.85 - sy * 0.82, z + 1.7};
        double[] t0 = {x - fx * 0.85, y - fy * 0.85, z + 2.3}, t1 = {x + fx * 0.85, y + fy * 0.85, z + 2.3};
        // Counter-clockwise seen from outside, as every face: the normals are made from the winding (and the
        // software tier culls by it); the roof was wound inside out, its slopes lit as if facing in.
        w.flatQuad(t0, t1, l1, l0, WHITE);
        w.flatQuad(t1, t0, r0, r1, WHITE);
        w.flatTriangle(r1, l1, t1, c);
        w.flatTriangle(l0, r0, t0, c);
    }

    /** A low, smooth mound: a snow drift (white) or a dune's body (sand, its crest lighter). */
    public static void mound(MeshWriter w, double x, double y, double z, double size, long seed, float[] base, float[] top) {
        Random r = new Random(seed);
        w.lump(x, y, z - size * 0.06, size * (0.5 + 0.3 * r.nextDouble()), size * (0.35 + 0.2 * r.nextDouble()),
                size * 0.22, 0.1, seed, false, z - 0.02, base, top);
    }

    /**
     * A dune: a sand mound with tufts of marram grass on its crest. (A green cap on a sand ring read as
     * a crater from above.)
     */
    public static void dune(MeshWriter w, double x, double y, double z, double size, long seed, float[] sand) {
        Random r = new Random(seed);
        double rz = size * 0.26, base = z - size * 0.06;
        w.lump(x, y, base, size * (0.5 + 0.3 * r.nextDouble()), size * (0.35 + 0.2 * r.nextDouble()), rz, 0.12, seed, false,
                z - 0.02, sand, shade(sand, 1.07));
        double crest = base + rz * 0.9;
        for (int k = 0; k < 5; k++) {
            double a = 2 * Math.PI * r.nextDouble(), d = size * 0.18 * r.nextDouble();
            double tx = x + d * Math.cos(a), ty = y + d * Math.sin(a), h = size * (0.06 + 0.04 * r.nextDouble());
            w.frustum(tx, ty, crest - 0.05, crest + h, size * 0.035, 0, 5, false, MARRAM);
        }
    }

    static float[] shade(float[] c, double k) {
        return new float[]{(float) Math.min(1, c[0] * k), (float) Math.min(1, c[1] * k), (float) Math.min(1, c[2] * k)};
    }
}
