package minigolf.render;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.HeightProbe;
import org.joml.Vector3f;

/**
 * Keeps the ball in sight: where the camera's eye would sit behind or inside something (a tree's
 * crown or trunk, a wall, the windmill, the flag, a hill), the eye moves to where nothing stands
 * between it and the ball: it rises (a steeper pitch) or comes in along the ball-to-eye line to
 * just in front of the first thing in the way. Plain geometry, no OpenGL: each obstacle is the box round its drawn triangles (the
 * renderer's pieces, crowns included), the flag the box round its model, the ground sampled along
 * the line. Order of preference: a little steeper (up to {@link #FIRST_RISE} more), then nearer
 * (keeping at least {@link #LEAST_SHARE} of the distance), then as steep as it takes.
 */
public final class CameraClearance {
    /** The eye stays this far (m) in front of what it would otherwise sit behind. */
    static final float MARGIN = 0.3f;
    /** Coming in is preferred while it keeps at least this share of the wanted distance; else the eye rises. */
    static final float LEAST_SHARE = 0.45f;
    /** The line of sight starts this far above the ball's contact point: at the top of the ball. */
    static final float BALL_TOP = 0.05f;
    /** How much steeper the eye may first go before it comes in instead. */
    static final float FIRST_RISE = (float) Math.toRadians(24);
    /** Pitch steps tried when the eye rises. */
    static final float PITCH_STEP = (float) Math.toRadians(6);
    /** Half-width of the kept-clear cone per metre from the ball (tan 8 degrees). */
    static final float CONE = 0.14f;
    /** Points at which the ground is sampled along the line of sight. */
    static final int GROUND_SAMPLES = 32;

    /** min x, y, z, max x, y, z per occluder. */
    private final List<float[]> boxes;
    private final HeightProbe ground;

    // The last placement, reused while nothing changed (the eye is asked for many times a frame).
    private final float[] lastKey = new float[7];
    private final Vector3f lastEye = new Vector3f();
    private boolean cached;

    private final float cone;

    /** Occluders as boxes (min x, y, z, max x, y, z); {@code ground} may be null (no hills). */
    public CameraClearance(List<float[]> boxes, HeightProbe ground) {
        this(boxes, ground, CONE);
    }

    /** As above with the cone's half-width per metre ({@code 0}: a bare line of sight). */
    public CameraClearance(List<float[]> boxes, HeightProbe ground, float cone) {
        this.boxes = List.copyOf(boxes);
        this.ground = ground;
        this.cone = cone;
    }

    /** The course's obstacles (with the trees' crowns), its flag and its ground. */
    public static CameraClearance of(Course course, HeightProbe ground) {
        List<float[]> boxes = obstacleBoxes(course, ground);
        double hx = course.hole().position().x(), hy = course.hole().position().y();
        MeshData flag = ModelResource.get("flag").placed(hx, hy, ground.height(hx, hy) - ObjectsPass.FLAG_FOOT_DEPTH,
                ObjectsPass.clothHeading(course.start().x(), course.start().y(), hx, hy), 1);
        boxes.add(bounds(flag));
        return new CameraClearance(boxes, ground);
    }

    /**
     * Lines of sight past the course's obstacles, crowns and ground, without the flag: whether the
     * cup itself can be seen (the flag stands in it). A thin cone (5 mm per metre) keeps a line that
     * grazes a wall's top from counting as a view.
     */
    public static CameraClearance sightlines(Course course, HeightProbe ground) {
        return new CameraClearance(obstacleBoxes(course, ground), ground, 0.005f);
    }

    private static List<float[]> obstacleBoxes(Course course, HeightProbe ground) {
        List<float[]> boxes = new ArrayList<>();
        ObstacleMeshes.Built built = ObstacleMeshes.build(course.obstacles(), ground, m -> MaterialLibrary.empty());
        for (ObstacleMeshes.Piece p : built.solidPieces()) if (p.count() > 0) boxes.add(p.box().clone());
        for (ObstacleMeshes.Piece p : built.decorationPieces()) if (p.count() > 0) boxes.add(p.box().clone());
        return boxes;
    }

    public List<float[]> boxes() {
        return boxes;
    }

    static float[] bounds(MeshData mesh) {
        float[] b = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
        for (int v = 0; v < mesh.vertexCount(); v++) {
            for (int k = 0; k < 3; k++) {
                float c = mesh.get(v, 0, k);
                b[k] = Math.min(b[k], c);
                b[k + 3] = Math.max(b[k + 3], c);
            }
        }
        return b;
    }

    /**
     * The eye of a camera orbiting {@code target} at (yaw, pitch, distance), moved where it sees the
     * ball: unchanged if the line is clear, else nearer along the line, else higher. Never nearer than
     * {@code minDistance}.
     */
    public Vector3f place(Vector3f target, float yaw, float pitch, float distance, float minDistance, float maxPitch,
                          Vector3f dest) {
        float[] key = {target.x, target.y, target.z, yaw, pitch, distance, minDistance};
        if (cached && java.util.Arrays.equals(key, lastKey)) return dest.set(lastEye);
        Vector3f from = new Vector3f(target.x, target.y, target.z + BALL_TOP);
        Vector3f eye = new Vector3f();
        // With the cone first; where nothing keeps it clear (a ball under a crown), the bare line of sight.
        if (!placeWith(cone, from, target, yaw, pitch, distance, minDistance, maxPitch, eye) && cone > 0) {
            placeWith(0, from, target, yaw, pitch, distance, minDistance, maxPitch, eye);
        }
        System.arraycopy(key, 0, lastKey, 0, key.length);
        lastEye.set(eye);
        cached = true;
        return dest.set(eye);
    }

    /** Places the eye with a cone of {@code c}; true if it found a clear line of sight without the last resort. */
    private boolean placeWith(float c, Vector3f from, Vector3f target, float yaw, float pitch, float distance,
                              float minDistance, float maxPitch, Vector3f eye) {
        orbit(target, yaw, pitch, distance, eye);
        float hit = firstHit(from, eye, c);
        if (hit >= 1) return true;
        float pulled = hit * distance - MARGIN;
        // Rising a little keeps the view of the course; then coming in, if that leaves enough of the
        // distance; then rising as far as it takes; then as near as allowed.
        if (rise(c, from, target, yaw, pitch, Math.min(maxPitch, pitch + FIRST_RISE), distance, eye)) return true;
        if (pulled >= LEAST_SHARE * distance && pulled >= minDistance) {
            orbit(target, yaw, pitch, pulled, eye);
            return true;
        }
        if (rise(c, from, target, yaw, pitch, maxPitch, distance, eye)) return true;
        // The last resort, close in front of the first thing in the way: false, so a narrower search may do better.
        orbit(target, yaw, pitch, Math.max(minDistance, pulled), eye);
        return false;
    }

    /** Tries steeper pitches up to {@code upTo}; true (and the eye there) at the first clear one. */
    private boolean rise(float c, Vector3f from, Vector3f target, float yaw, float pitch, float upTo, float distance, Vector3f eye) {
        for (float p = pitch + PITCH_STEP; p < upTo + PITCH_STEP - 1e-6f; p += PITCH_STEP) {
            orbit(target, yaw, Math.min(p, upTo), distance, eye);
            if (firstHit(from, eye, c) >= 1) return true;
        }
        return false;
    }

    static Vector3f orbit(Vector3f target, float yaw, float pitch, float distance, Vector3f dest) {
        float cp = (float) Math.cos(pitch);
        return dest.set(target).add(distance * cp * (float) Math.cos(yaw), distance * cp * (float) Math.sin(yaw),
                distance * (float) Math.sin(pitch));
    }

    /**
     * The first point (as a fraction of the way from {@code from} to {@code to}) where the line enters
     * an occluder or goes under the ground; 1 or more when it is clear. Boxes the line starts in (a
     * wall's box round a ball resting beside it, the flag's round a ball at the cup) do not count.
     */
    public float firstHit(Vector3f from, Vector3f to) {
        return firstHit(from, to, cone);
    }

    private float firstHit(Vector3f from, Vector3f to, float c) {
        float dx = to.x - from.x, dy = to.y - from.y, dz = to.z - from.z;
        float best = Float.POSITIVE_INFINITY;
        float[] grown = new float[6];
        for (float[] b : boxes) {
            // The line of sight is a narrow cone from the ball: a box is grown by the cone's radius at its
            // nearest point, so what stands beside the line keeps out of the middle of the picture too.
            float cx = Math.max(b[0] - from.x, Math.max(0, from.x - b[3]));
            float cy = Math.max(b[1] - from.y, Math.max(0, from.y - b[4]));
            float cz = Math.max(b[2] - from.z, Math.max(0, from.z - b[5]));
            float grow = c * (float) Math.sqrt(cx * cx + cy * cy + cz * cz);
            for (int k = 0; k < 3; k++) {
                grown[k] = b[k] - grow;
                grown[k + 3] = b[k + 3] + grow;
            }
            float t = entry(grown, from.x, from.y, from.z, dx, dy, dz);
            if (t < best) best = t;
        }
        if (ground != null) {
            for (int i = 1; i <= GROUND_SAMPLES; i++) {
                float t = (float) i / GROUND_SAMPLES;
                if (t >= best) break;
                double x = from.x + t * dx, y = from.y + t * dy, z = from.z + t * dz;
                if (z < ground.height(x, y)) {
                    best = (float) (i - 1) / GROUND_SAMPLES;
                    break;
                }
            }
        }
        return best;
    }

    /** Where the ray o + t d (t in [0, 1]) enters the box, or +inf if it misses it or starts inside. */
    static float entry(float[] b, float ox, float oy, float oz, float dx, float dy, float dz) {
        float t0 = 0, t1 = 1;
        float[] o = {ox, oy, oz}, d = {dx, dy, dz};
        boolean inside = true;
        for (int k = 0; k < 3; k++) {
            float lo = b[k], hi = b[k + 3];
            if (o[k] < lo || o[k] > hi) inside = false;
            if (Math.abs(d[k]) < 1e-12f) {
                if (o[k] < lo || o[k] > hi) return Float.POSITIVE_INFINITY;
                continue;
            }
            float a = (lo - o[k]) / d[k], c = (hi - o[k]) / d[k];
            t0 = Math.max(t0, Math.min(a, c));
            t1 = Math.min(t1, Math.max(a, c));
            if (t0 > t1) return Float.POSITIVE_INFINITY;
        }
        return inside ? Float.POSITIVE_INFINITY : t0;
    }
}
