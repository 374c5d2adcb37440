package minigolf.editor;

import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.terrain.Terrain;
import minigolf.terrain.Terrains;

/** New courses and grids sampled from height expressions. */
public final class CourseGrids {
    /** The most grid nodes along either side of a sampled or new course. */
    public static final int MAX_NODES = 513;
    /** The spacing an expression course is sampled at, where the node limit allows. */
    public static final double SAMPLE_SPACING = 0.1;

    private CourseGrids() {
    }

    /**
     * A new course of width x depth metres centred on the origin, a grid with the given spacing,
     * flat at 0.1 m or sampled from {@code heightExpression} (null or blank: flat). The start is
     * a quarter of the width left of the centre, the hole a quarter right.
     *
     * @throws IllegalArgumentException for a bad size or spacing, or an expression that does not parse
     */
    public static Course newCourse(String name, double width, double depth, double spacing, String heightExpression) {
        if (name == null || name.isBlank()) throw new IllegalArgumentException("the course needs a name");
        if (!(width > 0) || !(depth > 0)) throw new IllegalArgumentException("width and depth must be > 0");
        if (!(spacing > 0)) throw new IllegalArgumentException("grid spacing must be > 0");
        int cols = (int) Math.round(width / spacing) + 1, rows = (int) Math.round(depth / spacing) + 1;
        if (cols < 2 || rows < 2) throw new IllegalArgumentException("the grid needs at least 2x2 nodes: use a smaller spacing");
        if (cols > MAX_NODES || rows > MAX_NODES) {
            throw new IllegalArgumentException("at most " + MAX_NODES + " nodes a side: use a larger spacing");
        }
        double w = (cols - 1) * spacing, d = (rows - 1) * spacing;
        Vec2 origin = new Vec2(-w / 2, -d / 2);
        Terrain t;
        try {
            t = heightExpression == null || heightExpression.isBlank() ? null
                    : Terrains.create(new TerrainSpec.HeightExpression(heightExpression));
        } catch (RuntimeException e) {
            throw new IllegalArgumentException("height expression: " + e.getMessage(), e);
        }
        double[][] h = new double[rows][cols];
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < cols; i++) h[j][i] = t == null ? 0.1 : t.height(origin.x() + i * spacing, origin.y() + j * spacing);
        }
        Bounds b = new Bounds(origin.x(), origin.y(), origin.x() + w, origin.y() + d);
        PhysicsSettings physics = new PhysicsSettings(PhysicsSettings.DEFAULT_GRAVITY, 0.08, 0.2,
                PhysicsSettings.DEFAULT_MAX_SPEED, PhysicsModel.CLASSIC);
        return new Course(Course.FORMAT, name, new TerrainSpec.HeightGrid(origin, spacing, h, null, null), b, physics,
                new Vec2(-w / 4, 0), new Hole(new Vec2(w / 4, 0), 0.1, HoleRule.REST, null), List.of());
    }

    /**
     * The course's terrain as a grid: a grid course's own (a copy), an expression sampled at
     * {@link #SAMPLE_SPACING} over the bounds (coarser where the node limit needs it).
     */
    public static TerrainSpec.HeightGrid toGrid(Course c) {
        if (c.terrain() instanceof TerrainSpec.HeightGrid g) return g;
        Bounds b = c.bounds();
        double spacing = Math.max(SAMPLE_SPACING, Math.max(b.width(), b.depth()) / (MAX_NODES - 1));
        int cols = (int) Math.ceil(b.width() / spacing - 1e-9) + 1, rows = (int) Math.ceil(b.depth() / spacing - 1e-9) + 1;
        Terrain t = Terrains.create(c.terrain());
        double[][] h = new double[rows][cols];
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < cols; i++) h[j][i] = t.height(b.minX() + i * spacing, b.minY() + j * spacing);
        }
        return new TerrainSpec.HeightGrid(new Vec2(b.minX(), b.minY()), spacing, h, null, null);
    }
}
