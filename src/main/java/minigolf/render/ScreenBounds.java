package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector4f;

/**
 * The pixel box of world points seen through a view-projection, for culling and scissors: points are
 * added one by one; one behind the eye makes the box unknowable (callers then take the whole image).
 * Pixels count from the bottom left of a width x height image (glScissor's convention). No GL.
 */
final class ScreenBounds {
    private final Matrix4f viewProjection;
    private final int width, height;
    private final Vector4f clip = new Vector4f();
    private float minX = Float.POSITIVE_INFINITY, minY = Float.POSITIVE_INFINITY;
    private float maxX = Float.NEGATIVE_INFINITY, maxY = Float.NEGATIVE_INFINITY;
    private boolean behindEye;

    ScreenBounds(Matrix4f viewProjection, int width, int height) {
        this.viewProjection = viewProjection;
        this.width = width;
        this.height = height;
    }

    void add(float x, float y, float z) {
        viewProjection.transform(clip.set(x, y, z, 1f));
        if (clip.w <= 1e-6f) {
            behindEye = true;
            return;
        }
        float px = (clip.x / clip.w * 0.5f + 0.5f) * width, py = (clip.y / clip.w * 0.5f + 0.5f) * height;
        minX = Math.min(minX, px);
        maxX = Math.max(maxX, px);
        minY = Math.min(minY, py);
        maxY = Math.max(maxY, py);
    }

    /** The eight corners of a box: min x, y, z, max x, y, z. */
    void addBox(float[] box) {
        for (int i = 0; i < 8; i++) add(box[(i & 1) == 0 ? 0 : 3], box[(i & 2) == 0 ? 1 : 4], box[(i & 4) == 0 ? 2 : 5]);
    }

    boolean behindEye() {
        return behindEye;
    }

    /**
     * {x, y, width, height} round the points, widened by marginX and marginY pixels and clipped to the
     * image; the whole image when a point was behind the eye; null when nothing was added or the box
     * misses the image.
     */
    int[] rect(float marginX, float marginY) {
        if (behindEye) return new int[]{0, 0, width, height};
        if (minX > maxX) return null;
        int x0 = (int) Math.max(0, Math.floor(minX - marginX)), y0 = (int) Math.max(0, Math.floor(minY - marginY));
        int x1 = (int) Math.min(width, Math.ceil(maxX + marginX)), y1 = (int) Math.min(height, Math.ceil(maxY + marginY));
        if (x1 <= x0 || y1 <= y0) return null;
        return new int[]{x0, y0, x1 - x0, y1 - y0};
    }

    /** Whether the points' box reaches into {@code rect} ({x, y, width, height}); true when one was behind the eye. */
    boolean meets(int[] rect) {
        if (behindEye) return true;
        return maxX >= rect[0] && minX <= rect[0] + rect[2] && maxY >= rect[1] && minY <= rect[1] + rect[3];
    }
}
