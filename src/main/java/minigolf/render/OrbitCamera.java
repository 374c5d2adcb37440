package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.terrain.Terrain;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;

import java.util.ArrayList;
import java.util.List;

/**
 * A camera orbiting a target point (normally the ball) in a z-up world. The eye sits at
 * {@code target + distance * (cos(pitch) cos(yaw), cos(pitch) sin(yaw), sin(pitch))}: yaw is the
 * direction from the target towards the eye, pitch the eye's elevation. Pitch and distance are clamped.
 */
public final class OrbitCamera {
    public static final float MIN_PITCH = (float) Math.toRadians(4);
    public static final float MAX_PITCH = (float) Math.toRadians(89);
    public static final float DEFAULT_PITCH = (float) Math.toRadians(34);
    public static final float BALL_SCREEN_SHIFT = -0.4f;
    public static final float FOV_Y = (float) Math.toRadians(45);

    private final Vector3f target = new Vector3f();
    private float yaw;
    private float pitch;
    private float distance;
    /** Where the target appears vertically, in NDC (0 = centre, -0.4 = a fifth of the height below it). */
    private float screenShiftY, screenShiftX;
    private float minDistance = 0.3f;
    private float maxDistance = 200f;

    /** Keeps the ball in sight (the eye moves in front of trees, walls, the flag), or null. */
    private CameraClearance clearance;
    /**
     * The clearance's move as drawn, eased ({@link #ease}): extra pitch (radians) and the share of
     * the distance kept. The player's own turning and zooming stay instant; the clearance's
     * corrections glide where the ball stays in sight during the glide (a correction that lets the
     * eye back out once a tree has passed), and are taken at once where it would not.
     */
    private float easedPitch, easedShare = 1;
    private boolean easing;
    /** Time constant of the easing (s): 90% of a correction in about 0.3 s. */
    public static final float EASE_SECONDS = 0.12f;

    private final Vector3f homeTarget = new Vector3f();
    private float homeYaw, homePitch, homeDistance;

    public OrbitCamera(Vector3f target, float yaw, float pitch, float distance) {
        this.target.set(target);
        this.yaw = yaw;
        this.pitch = clampPitch(pitch);
        this.distance = clampDistance(distance);
        setHome();
    }

    /**
     * The opening view of a course: behind the ball (the course start) looking towards the hole, at
     * {@link #DEFAULT_PITCH}, far enough that the whole course fits an image of this aspect ratio.
     */
    public static OrbitCamera behindBall(Course course, Terrain terrain, float aspect) {
        Vector3f ball = new Vector3f((float) course.start().x(), (float) course.start().y(),
                (float) terrain.height(course.start().x(), course.start().y()));
        double dx = course.hole().position().x() - course.start().x();
        double dy = course.hole().position().y() - course.start().y();
        if (Math.hypot(dx, dy) < 1e-9) {
            dx = -1;
            dy = 0;
        }
        float yaw = (float) Math.atan2(-dy, -dx);
        OrbitCamera cam = new OrbitCamera(ball, yaw, DEFAULT_PITCH, 10);
        // The ball sits in the lower part of the picture, leaving the room above it for the course ahead.
        cam.screenShiftY = BALL_SCREEN_SHIFT;
        cam.fit(courseOutline(course, terrain), aspect, 0.92f);
        cam.maxDistance = Math.max(cam.distance * 3, 20);
        cam.setHome();
        return cam;
    }

    /**
     * The game's opening view of a hole: behind the ball facing the hole ({@link #behindBall}), the
     * ball kept in sight past obstacles ({@link CameraClearance}), and where something (the
     * windmill on its hole, a castle's wall) would hide the cup from there, turned a little to one
     * side, steeper or further out (the least change that shows the cup), so the player sees where
     * to putt. R comes back to this view.
     */
    public static OrbitCamera opening(Course course, Terrain terrain, float aspect) {
        OrbitCamera cam = behindBall(course, terrain, aspect);
        cam.setClearance(CameraClearance.of(course, terrain::height));
        double hx = course.hole().position().x(), hy = course.hole().position().y();
        Vector3f cup = new Vector3f((float) hx, (float) hy, (float) terrain.height(hx, hy) + 0.02f);
        CameraClearance sight = CameraClearance.sightlines(course, terrain::height);
        if (sight.firstHit(cam.eye(), cup) >= 1) return cam;
        float yaw0 = cam.yaw, pitch0 = cam.pitch, distance0 = cam.distance, maxDistance0 = cam.maxDistance;
        float bestCost = Float.POSITIVE_INFINITY, bestYaw = yaw0, bestPitch = pitch0, bestDistance = distance0;
        for (int turn = -OPENING_TURNS; turn <= OPENING_TURNS; turn++) {
            for (float pitch = pitch0; pitch <= OPENING_MAX_PITCH + 1e-6f; pitch += OPENING_PITCH_STEP) {
                for (float far = 1; far <= OPENING_MAX_FAR + 1e-6f; far += 0.25f) {
                    // A turn of 10 degrees costs as much as 6 degrees steeper or a quarter further out.
                    float cost = Math.abs(turn) + (pitch - pitch0) / OPENING_PITCH_STEP / 2 + (far - 1) * 4;
                    if (cost >= bestCost) continue;
                    cam.yaw = yaw0 + turn * OPENING_TURN_STEP;
                    cam.pitch = pitch;
                    cam.distance = distance0 * far;
                    cam.maxDistance = Math.max(maxDistance0, cam.distance);
                    if (sight.firstHit(cam.eye(), cup) >= 1) {
                        bestCost = cost;
                        bestYaw = cam.yaw;
                        bestPitch = pitch;
                        bestDistance = cam.distance;
                    }
                }
            }
        }
        cam.yaw = bestYaw; // unchanged where nothing shows the cup: the usual view
        cam.pitch = bestPitch;
        cam.distance = bestDistance;
        cam.maxDistance = Math.max(maxDistance0, bestDistance);
        cam.setHome();
        return cam;
    }

    /** How the opening view may change to show the cup: turns of 10 degrees either way, steeper up to 70 degrees, twice as far. */
    static final int OPENING_TURNS = 4;
    static final float OPENING_TURN_STEP = (float) Math.toRadians(10), OPENING_MAX_PITCH = (float) Math.toRadians(70),
            OPENING_PITCH_STEP = (float) Math.toRadians(3), OPENING_MAX_FAR = 2f;

    /** A view from straight above-ish (pitch 80 degrees) onto {@code target}, fitting the course. */
    public static OrbitCamera topDown(Course course, Terrain terrain, Vector3f target, float aspect) {
        OrbitCamera cam = new OrbitCamera(target, (float) (-Math.PI / 2), (float) Math.toRadians(80), 10);
        cam.fit(courseOutline(course, terrain), aspect, 0.95f);
        cam.setHome();
        return cam;
    }

    /** Points that must be in view: the course's corners and edge midpoints, top and foot of the side walls, and the flag top. */
    static List<Vector3f> courseOutline(Course course, Terrain terrain) {
        Bounds b = course.bounds();
        List<Vector3f> pts = new ArrayList<>();
        for (int i = 0; i <= 4; i++) {
            for (int j = 0; j <= 4; j++) {
                if (i != 0 && i != 4 && j != 0 && j != 4) continue;
                double x = b.minX() + b.width() * i / 4, y = b.minY() + b.depth() * j / 4;
                float z = (float) terrain.height(x, y);
                pts.add(new Vector3f((float) x, (float) y, Math.max(0, z)));
                pts.add(new Vector3f((float) x, (float) y, Math.min(0, z) - 0.3f)); // the side wall's foot
            }
        }
        double hx = course.hole().position().x(), hy = course.hole().position().y();
        pts.add(new Vector3f((float) hx, (float) hy, (float) terrain.height(hx, hy) + (float) ObjectsPass.FLAG_HEIGHT));
        return pts;
    }

    /** Sets the smallest distance at which every point projects inside [-margin, margin] in NDC. */
    public void fit(List<Vector3f> points, float aspect, float margin) {
        float lo = 0.2f, hi = 2000f;
        float savedMax = maxDistance, savedMin = minDistance;
        maxDistance = hi;
        minDistance = lo;
        Matrix4f vp = new Matrix4f();
        Vector4f clip = new Vector4f();
        for (int iter = 0; iter < 40; iter++) {
            float mid = 0.5f * (lo + hi);
            distance = mid;
            viewProjection(aspect, vp);
            boolean fits = true;
            for (Vector3f p : points) {
                clip.set(p, 1).mul(vp);
                if (clip.w <= 0 || Math.abs(clip.x / clip.w) > margin || Math.abs(clip.y / clip.w) > margin) {
                    fits = false;
                    break;
                }
            }
            if (fits) hi = mid;
            else lo = mid;
        }
        distance = hi;
        maxDistance = Math.max(savedMax, hi);
        minDistance = Math.min(savedMin, hi);
    }

    /**
     * Moves the eye to where the whole course stays in view however the camera turns about its
     * target at this pitch: the largest of the distances that frame it from eight sides.
     */
    public void frameFromAllSides(Course course, Terrain terrain, float aspect, float margin) {
        List<Vector3f> outline = courseOutline(course, terrain);
        float savedYaw = yaw, far = 0;
        for (int k = 0; k < 8; k++) {
            yaw = (float) (k * Math.PI / 4);
            fit(outline, aspect, margin);
            far = Math.max(far, distance);
        }
        yaw = savedYaw;
        distance = clampDistance(far);
    }

    private void setHome() {
        homeTarget.set(target);
        homeYaw = yaw;
        homePitch = pitch;
        homeDistance = distance;
    }

    /** Back to the view this camera was created (or framed) with. */
    public void reset() {
        target.set(homeTarget);
        yaw = homeYaw;
        pitch = homePitch;
        distance = homeDistance;
        easing = false; // a cut: no glide from the old view
    }

    public void rotate(float deltaYaw, float deltaPitch) {
        yaw = (float) ((yaw + deltaYaw) % (2 * Math.PI));
        pitch = clampPitch(pitch + deltaPitch);
    }

    /** Moves the target along the ground by a drag of (dx, dy) pixels in a viewport {@code viewportHeight} pixels tall. */
    public void pan(float dxPixels, float dyPixels, int viewportHeight) {
        float metresPerPixel = (float) (2 * distance * Math.tan(FOV_Y / 2) / Math.max(1, viewportHeight));
        float c = (float) Math.cos(yaw), s = (float) Math.sin(yaw);
        // Screen right on the ground is (-sin yaw, cos yaw); screen up on the ground is (-cos yaw, -sin yaw).
        target.x += (s * dxPixels - c * dyPixels) * metresPerPixel;
        target.y += (-c * dxPixels - s * dyPixels) * metresPerPixel;
    }

    /** Zooms in for positive steps (mouse wheel forward), out for negative; 10% per step. */
    public void zoom(float steps) {
        distance = clampDistance((float) (distance * Math.pow(0.9, steps)));
    }

    public void setTarget(Vector3f t) {
        target.set(t);
    }

    public Vector3f target() {
        return new Vector3f(target);
    }

    public float yaw() {
        return yaw;
    }

    public float pitch() {
        return pitch;
    }

    public float screenShiftY() {
        return screenShiftY;
    }

    public void setScreenShiftY(float ndc) {
        screenShiftY = ndc;
    }

    /** Where the target shows across the picture, in NDC (0: the middle; positive: to the right). */
    public float screenShiftX() {
        return screenShiftX;
    }

    public void setScreenShiftX(float ndc) {
        screenShiftX = ndc;
    }

    public float distance() {
        return distance;
    }

    /** What moves the eye where something would hide the target; null for the plain orbit. */
    public CameraClearance clearance() {
        return clearance;
    }

    /** Lets {@code c} move the eye where something would hide the target (null: the plain orbit). */
    public void setClearance(CameraClearance c) {
        clearance = c;
        easing = false;
    }

    /**
     * Moves the drawn clearance correction towards the one the view needs now, over
     * {@link #EASE_SECONDS} (call once a frame with the frame's time step). Until the first call
     * the eye is the clearance's own placement.
     */
    public void ease(float dt) {
        if (clearance == null) return;
        Vector3f placed = clearance.place(target, yaw, pitch, distance, minDistance, MAX_PITCH, new Vector3f());
        float d = placed.distance(target);
        float wantPitch = (float) Math.asin(Math.max(-1, Math.min(1, (placed.z - target.z) / Math.max(1e-6f, d)))) - pitch;
        float wantShare = distance > 0 ? d / distance : 1;
        if (!easing) {
            easedPitch = wantPitch;
            easedShare = wantShare;
            easing = true;
            return;
        }
        float k = (float) (1 - Math.exp(-Math.max(0, dt) / EASE_SECONDS));
        float oldPitch = easedPitch, oldShare = easedShare;
        easedPitch += (wantPitch - easedPitch) * k;
        easedShare += (wantShare - easedShare) * k;
        // Gliding must never hide the ball: where the eased eye's line to it is blocked, the correction is taken at once.
        Vector3f from = new Vector3f(target.x, target.y, target.z + CameraClearance.BALL_TOP);
        if (clearance.firstHit(from, eye()) < 1 && (oldPitch != wantPitch || oldShare != wantShare)) {
            easedPitch = wantPitch;
            easedShare = wantShare;
        }
    }

    public Vector3f eye() {
        if (clearance != null && !easing) return clearance.place(target, yaw, pitch, distance, minDistance, MAX_PITCH, new Vector3f());
        float p = clearance != null ? clampPitch(pitch + easedPitch) : pitch;
        float dist = clearance != null ? Math.max(minDistance, distance * easedShare) : distance;
        float cp = (float) Math.cos(p);
        return new Vector3f(target).add(dist * cp * (float) Math.cos(yaw), dist * cp * (float) Math.sin(yaw),
                dist * (float) Math.sin(p));
    }

    public float near() {
        return Math.max(0.01f, Math.min(0.5f, distance / 200));
    }

    public float far() {
        return Math.max(150f, distance * 20);
    }

    public Matrix4f view(Matrix4f dest) {
        return dest.setLookAt(eye(), target, new Vector3f(0, 0, 1));
    }

    public Matrix4f projection(float aspect, Matrix4f dest) {
        // A lens shift: the image moves on screen, the view direction does not.
        return dest.translation(screenShiftX, screenShiftY, 0).perspective(FOV_Y, aspect, near(), far());
    }

    public Matrix4f viewProjection(float aspect, Matrix4f dest) {
        Matrix4f v = view(new Matrix4f());
        return projection(aspect, dest).mul(v);
    }

    /** Where a world point lands in a width x height image, in pixels from the top-left; null if behind the eye. */
    public float[] project(Vector3f world, int width, int height) {
        Vector4f clip = new Vector4f(world, 1).mul(viewProjection((float) width / height, new Matrix4f()));
        if (clip.w <= 0) return null;
        float nx = clip.x / clip.w, ny = clip.y / clip.w;
        return new float[]{(nx * 0.5f + 0.5f) * width, (0.5f - ny * 0.5f) * height};
    }

    private float clampPitch(float p) {
        return Math.max(MIN_PITCH, Math.min(MAX_PITCH, p));
    }

    private float clampDistance(float d) {
        return Math.max(minDistance, Math.min(maxDistance, d));
    }
}
