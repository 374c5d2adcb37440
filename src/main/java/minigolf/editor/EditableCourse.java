package minigolf.editor;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.Magnet;
import minigolf.course.Obstacle;
import minigolf.course.PushZone;
import minigolf.course.Teleport;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.course.Zone;

/**
 * The course being edited, in mutable form: a height grid (row-major arrays, node (i, j) at index
 * j * columns + i), optional per-node friction, a deleted-cell mask, obstacles and the course's
 * scalar properties. Only {@link Edit}s change it, so that every change can be undone.
 */
public final class EditableCourse {
    final double originX, originY, spacing;
    final int columns, rows;
    final double[] heights;
    /** Per-node friction, or null while nothing has been painted. */
    double[] kinetic, statics;
    /** Cell (i, j) at j * (columns - 1) + i. */
    final boolean[] deleted;
    final List<Obstacle> obstacles = new ArrayList<>();
    Properties properties;
    final Bounds bounds;
    final List<Zone> zones = new ArrayList<>();
    final List<PushZone> pushZones = new ArrayList<>();
    final List<Magnet> magnets = new ArrayList<>();
    final List<Teleport> teleports = new ArrayList<>();
    /** The themed world the course is set in (kept as loaded; the editor does not change it). */
    String world = minigolf.theme.Themes.DEFAULT_ID;
    /** The holes beside the main one (kept as loaded: the editor places only the main hole). */
    List<Hole> extraHoles = List.of();
    /** Breakable bricks: kept as loaded (not editable), saved back. */
    List<minigolf.course.Brick> bricks = List.of();

    /** The course's fields that are not per node or per obstacle. */
    public record Properties(String name, Vec2 start, Hole hole, PhysicsSettings physics) {
    }

    EditableCourse(TerrainSpec.HeightGrid grid, Bounds bounds, List<Zone> zones, List<Obstacle> obstacles,
                   Properties properties) {
        originX = grid.origin().x();
        originY = grid.origin().y();
        spacing = grid.spacing();
        columns = grid.columns();
        rows = grid.rows();
        heights = flatten(grid.heights());
        kinetic = grid.kineticFriction() == null ? null : flatten(grid.kineticFriction());
        statics = grid.staticFriction() == null ? null : flatten(grid.staticFriction());
        deleted = new boolean[(columns - 1) * (rows - 1)];
        if (grid.deleted() != null) {
            for (int j = 0; j < rows - 1; j++) {
                for (int i = 0; i < columns - 1; i++) deleted[j * (columns - 1) + i] = grid.deleted()[j][i];
            }
        }
        this.bounds = bounds;
        this.zones.addAll(zones);
        this.obstacles.addAll(obstacles);
        this.properties = properties;
    }

    /** As above, with the course's push zones, magnets and teleports. */
    EditableCourse(TerrainSpec.HeightGrid grid, Bounds bounds, List<Zone> zones, List<Obstacle> obstacles,
                   List<PushZone> pushZones, List<Magnet> magnets, List<Teleport> teleports, Properties properties) {
        this(grid, bounds, zones, obstacles, properties);
        this.pushZones.addAll(pushZones);
        this.magnets.addAll(magnets);
        this.teleports.addAll(teleports);
    }

    private double[] flatten(double[][] m) {
        double[] out = new double[rows * columns];
        for (int j = 0; j < rows; j++) System.arraycopy(m[j], 0, out, j * columns, columns);
        return out;
    }

    private double[][] unflatten(double[] a) {
        double[][] m = new double[rows][columns];
        for (int j = 0; j < rows; j++) System.arraycopy(a, j * columns, m[j], 0, columns);
        return m;
    }

    /** The grid as the course format has it (fresh arrays). */
    public TerrainSpec.HeightGrid grid() {
        boolean any = false;
        for (boolean d : deleted) any |= d;
        boolean[][] mask = null;
        if (any) {
            mask = new boolean[rows - 1][columns - 1];
            for (int j = 0; j < rows - 1; j++) {
                for (int i = 0; i < columns - 1; i++) mask[j][i] = deleted[j * (columns - 1) + i];
            }
        }
        return new TerrainSpec.HeightGrid(new Vec2(originX, originY), spacing, unflatten(heights),
                kinetic == null ? null : unflatten(kinetic), statics == null ? null : unflatten(statics), mask);
    }

    /** A snapshot as an immutable course. */
    public Course toCourse() {
        Properties p = properties;
        return new Course(Course.FORMAT, p.name(), grid(), bounds, p.physics(), p.start(), p.hole(), zones, obstacles,
                pushZones, magnets, teleports, world, extraHoles, bricks);
    }

    public int columns() {
        return columns;
    }

    public int rows() {
        return rows;
    }

    public double spacing() {
        return spacing;
    }

    public double originX() {
        return originX;
    }

    public double originY() {
        return originY;
    }

    public double nodeX(int i) {
        return originX + i * spacing;
    }

    public double nodeY(int j) {
        return originY + j * spacing;
    }

    public double height(int i, int j) {
        return heights[j * columns + i];
    }

    /** Kinetic friction at node (i, j): the painted value, else the course's. */
    public double kineticFriction(int i, int j) {
        return kinetic != null ? kinetic[j * columns + i] : properties.physics().kineticFriction();
    }

    public double staticFriction(int i, int j) {
        return statics != null ? statics[j * columns + i] : properties.physics().staticFriction();
    }

    public boolean isDeleted(int i, int j) {
        return deleted[j * (columns - 1) + i];
    }

    public List<Obstacle> obstacles() {
        return List.copyOf(obstacles);
    }

    public Properties properties() {
        return properties;
    }

    public Bounds bounds() {
        return bounds;
    }

    /** The nearest node's column to x (clamped to the grid). */
    public int nearestColumn(double x) {
        return Math.max(0, Math.min(columns - 1, (int) Math.round((x - originX) / spacing)));
    }

    public int nearestRow(double y) {
        return Math.max(0, Math.min(rows - 1, (int) Math.round((y - originY) / spacing)));
    }

    /** The cell column containing x, or -1 outside the grid. */
    public int cellColumn(double x) {
        double u = (x - originX) / spacing;
        return u < 0 || u > columns - 1 ? -1 : Math.min((int) u, columns - 2);
    }

    public int cellRow(double y) {
        double v = (y - originY) / spacing;
        return v < 0 || v > rows - 1 ? -1 : Math.min((int) v, rows - 2);
    }
}
