package minigolf.editor;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.CourseException;
import minigolf.course.CourseWriter;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.Magnet;
import minigolf.course.Obstacle;
import minigolf.course.PushZone;
import minigolf.course.Teleport;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import minigolf.course.Zone;
import minigolf.physics.World;
import minigolf.terrain.GridTerrain;

/**
 * The course editor without any window: every editing operation of the editor, each one an
 * undoable {@link Edit}, plus validation, saving and the recovery file. The window
 * ({@code minigolf.editor.ui}) only translates mouse and keys into these calls.
 */
public final class CourseEditor {
    /** The most objects a course may have unless the user changes the setting. */
    public static final int DEFAULT_MAX_OBSTACLES = 200;

    private final EditableCourse course;
    private final EditHistory history = new EditHistory();
    private final ChangeSet changes = new ChangeSet();
    private Path file;
    private int maxObstacles = DEFAULT_MAX_OBSTACLES;
    private World world;
    private long version, worldVersion = -1;
    // The brush stroke in progress.
    private NodeEdit.Recorder stroke;
    private Brush strokeBrush;
    private double strokeRadius, strokeStrength, strokeTarget;

    private CourseEditor(EditableCourse course, Path file) {
        this.course = course;
        this.file = file;
        history.markSaved();
    }

    /** Edits a course (an expression terrain is first sampled to a grid, see {@link CourseGrids}). */
    public static CourseEditor of(Course c, Path file) {
        TerrainSpec.HeightGrid grid = CourseGrids.toGrid(c);
        EditableCourse ec = new EditableCourse(grid, c.bounds(), c.zones(), c.obstacles(), c.pushZones(), c.magnets(),
                c.teleports(), new EditableCourse.Properties(c.name(), c.start(), c.hole(), c.physics()));
        ec.world = c.world();
        ec.extraHoles = c.extraHoles();
        ec.bricks = c.bricks();
        CourseEditor e = new CourseEditor(ec, file);
        // A sampled expression course is not yet a file: it counts as unsaved.
        if (!(c.terrain() instanceof TerrainSpec.HeightGrid)) e.file = null;
        return e;
    }

    /** Continues with a course from the recovery file: it counts as unsaved, its file is the original one. */
    public static CourseEditor recovered(Recovery.Recovered r) {
        CourseEditor e = of(r.course(), r.originalFile());
        e.history.markUnsaved();
        return e;
    }

    /** Opens a course file (without the water check: the editor shows such problems instead). */
    public static CourseEditor open(Path file) throws CourseException {
        return of(minigolf.course.CourseLoader.load(file), file);
    }

    /** A new course; see {@link CourseGrids#newCourse}. */
    public static CourseEditor create(String name, double width, double depth, double spacing, String heightExpression) {
        return of(CourseGrids.newCourse(name, width, depth, spacing, heightExpression), null);
    }

    // ---- state ----

    public EditableCourse course() {
        return course;
    }

    public Course toCourse() {
        return course.toCourse();
    }

    /** The course ready for the physics (rebuilt after a change, on demand). */
    public World world() {
        if (worldVersion != version || world == null) {
            Course c = course.toCourse();
            TerrainSpec.HeightGrid g = (TerrainSpec.HeightGrid) c.terrain();
            world = new World(c, new GridTerrain(g));
            worldVersion = version;
        }
        return world;
    }

    /** The file the course is saved to, or null before the first save of a new course. */
    public Path file() {
        return file;
    }

    public boolean isDirty() {
        return history.isDirty() || stroke != null;
    }

    /** What changed since the last call (for the renderer). */
    public ChangeSet takeChanges() {
        return changes.take();
    }

    /** A number that grows with every change (the recovery file compares it). */
    public long version() {
        return version;
    }

    public int maxObstacles() {
        return maxObstacles;
    }

    public void setMaxObstacles(int max) {
        if (max < 0) throw new IllegalArgumentException("the maximum object count must be >= 0");
        maxObstacles = max;
    }

    // ---- history ----

    private void push(Edit e) {
        history.push(e);
        version++;
    }

    private void perform(Edit e) {
        e.apply(course, changes);
        push(e);
    }

    public boolean undo() {
        endStroke();
        boolean done = history.undo(course, changes) != null;
        if (done) version++;
        return done;
    }

    public boolean redo() {
        endStroke();
        boolean done = history.redo(course, changes) != null;
        if (done) version++;
        return done;
    }

    public boolean canUndo() {
        return history.canUndo();
    }

    public boolean canRedo() {
        return history.canRedo();
    }

    /** The label of the edit Undo would revert, or null. */
    public String undoLabel() {
        return history.undoLabel();
    }

    public String redoLabel() {
        return history.redoLabel();
    }

    public int historySize() {
        return history.size();
    }

    // ---- terrain ----

    /** Starts a brush stroke with a first dab at (x, y); dabs until {@link #endStroke()} are one undo step. */
    public void beginStroke(Brush brush, double x, double y, double radius, double strength) {
        endStroke();
        if (!(radius > 0)) throw new IllegalArgumentException("brush radius must be > 0");
        stroke = new NodeEdit.Recorder(course, brush.label() + " brush", false, changes);
        strokeBrush = brush;
        strokeRadius = radius;
        strokeStrength = strength;
        strokeTarget = course.height(course.nearestColumn(x), course.nearestRow(y));
        dab(x, y);
    }

    /** Another dab of the stroke in progress. */
    public void dab(double x, double y) {
        if (stroke == null) return;
        strokeBrush.dab(course, stroke, x, y, strokeRadius, strokeStrength, strokeTarget);
        version++;
    }

    public boolean isStroking() {
        return stroke != null;
    }

    /** Ends the stroke in progress (if any) and records it as one edit. */
    public void endStroke() {
        if (stroke == null) return;
        NodeEdit.Recorder r = stroke;
        stroke = null;
        if (!r.isEmpty()) push(r.finish());
    }

    /** One dab as its own edit. */
    public void brush(Brush brush, double x, double y, double radius, double strength) {
        beginStroke(brush, x, y, radius, strength);
        endStroke();
    }

    /** Sets node (i, j) to height h (negative makes water). */
    public void setNodeHeight(int i, int j, double h) {
        checkNode(i, j);
        if (!Double.isFinite(h)) throw new IllegalArgumentException("height must be a finite number");
        endStroke();
        NodeEdit.Recorder r = new NodeEdit.Recorder(course, "set height", false, changes);
        r.setHeight(i, j, h);
        push(r.finish());
    }

    /** Paints friction on every node within {@code radius} of (x, y). */
    public void paint(double x, double y, double radius, double kinetic, double statics, String what) {
        if (!(kinetic >= 0) || !(statics >= 0)) throw new IllegalArgumentException("friction must be >= 0");
        endStroke();
        NodeEdit.Recorder r = new NodeEdit.Recorder(course, "paint " + what, true, changes);
        int i0 = Math.max(0, (int) Math.floor((x - radius - course.originX) / course.spacing));
        int i1 = Math.min(course.columns - 1, (int) Math.ceil((x + radius - course.originX) / course.spacing));
        int j0 = Math.max(0, (int) Math.floor((y - radius - course.originY) / course.spacing));
        int j1 = Math.min(course.rows - 1, (int) Math.ceil((y + radius - course.originY) / course.spacing));
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) {
                if (Math.hypot(course.nodeX(i) - x, course.nodeY(j) - y) <= radius) r.setFriction(i, j, kinetic, statics);
            }
        }
        push(r.finish());
    }

    public void paint(double x, double y, double radius, Surface surface) {
        paint(x, y, radius, surface.kineticFriction(), surface.staticFriction(), surface.label());
    }

    /** Deletes (or restores) cell (i, j); a deleted cell is out of bounds. */
    public void setCellDeleted(int i, int j, boolean deleted) {
        if (i < 0 || j < 0 || i >= course.columns - 1 || j >= course.rows - 1) {
            throw new IllegalArgumentException("no cell (" + i + ", " + j + ") on a " + (course.columns - 1) + "x"
                    + (course.rows - 1) + " grid");
        }
        if (course.isDeleted(i, j) == deleted) return;
        endStroke();
        perform(new CellEdit(course, new int[]{j * (course.columns - 1) + i}, deleted));
    }

    /** Deletes or restores every cell whose centre lies within {@code radius} of (x, y), as one edit. */
    public int setCellsDeleted(double x, double y, double radius, boolean deleted) {
        List<Integer> cells = new ArrayList<>();
        for (int j = 0; j < course.rows - 1; j++) {
            for (int i = 0; i < course.columns - 1; i++) {
                double cx = Reachability.centerX(course, i), cy = Reachability.centerY(course, j);
                if (Math.hypot(cx - x, cy - y) <= radius && course.isDeleted(i, j) != deleted) {
                    cells.add(j * (course.columns - 1) + i);
                }
            }
        }
        if (cells.isEmpty()) return 0;
        endStroke();
        perform(new CellEdit(course, cells.stream().mapToInt(Integer::intValue).toArray(), deleted));
        return cells.size();
    }

    private void checkNode(int i, int j) {
        if (i < 0 || j < 0 || i >= course.columns || j >= course.rows) {
            throw new IllegalArgumentException("no node (" + i + ", " + j + ") on a " + course.columns + "x" + course.rows + " grid");
        }
    }

    // ---- obstacles ----

    /** Adds an obstacle; returns false (and changes nothing) when the course already has the maximum count. */
    public boolean addObstacle(Obstacle o) {
        if (course.obstacles.size() >= maxObstacles) return false;
        endStroke();
        perform(ListItemEdit.obstacle(course.obstacles.size(), null, o, "place " + ObstacleTools.describe(o)));
        return true;
    }

    public void moveObstacle(int index, double dx, double dy) {
        Obstacle o = obstacle(index);
        endStroke();
        perform(ListItemEdit.obstacle(index, o, ObstacleTools.moved(o, dx, dy), "move " + ObstacleTools.describe(o)));
    }

    public void rotateObstacle(int index, double degrees) {
        Obstacle o = obstacle(index);
        endStroke();
        perform(ListItemEdit.obstacle(index, o, ObstacleTools.rotated(o, degrees), "rotate " + ObstacleTools.describe(o)));
    }

    /** Replaces the obstacle (e.g. its size typed in the object panel); nothing happens when it is the same. */
    public void replaceObstacle(int index, Obstacle replacement) {
        replaceObstacle(index, replacement, "edit " + ObstacleTools.describe(obstacle(index)));
    }

    private void replaceObstacle(int index, Obstacle replacement, String label) {
        Obstacle o = obstacle(index);
        if (o.equals(replacement)) return;
        endStroke();
        perform(ListItemEdit.obstacle(index, o, replacement, label));
    }

    /** A wall's thickness (>= 0, 0 a thin fence) and height above the ground (> 0). */
    public void setWallSize(int index, double thickness, double height) {
        if (!(obstacle(index) instanceof Obstacle.Wall w)) throw new IllegalArgumentException("object " + index + " is not a wall");
        if (!(thickness >= 0) || !(height > 0) || !Double.isFinite(thickness) || !Double.isFinite(height)) {
            throw new IllegalArgumentException("wall thickness must be >= 0 and height > 0");
        }
        if (thickness == 0 && w.from().equals(w.to())) throw new IllegalArgumentException("a wall of no length needs a thickness");
        replaceObstacle(index, new Obstacle.Wall(w.from(), w.to(), thickness, height, w.restitution()), "wall size");
    }

    /** A tree trunk's radius and height (both > 0). */
    public void setTreeSize(int index, double radius, double height) {
        if (!(obstacle(index) instanceof Obstacle.Tree t)) throw new IllegalArgumentException("object " + index + " is not a tree");
        if (!(radius > 0) || !(height > 0) || !Double.isFinite(radius) || !Double.isFinite(height)) {
            throw new IllegalArgumentException("tree radius and height must be > 0");
        }
        replaceObstacle(index, new Obstacle.Tree(t.position(), radius, height, t.restitution()), "tree size");
    }

    /** A box's width (x), depth (y) and height (z), all > 0: it keeps its centre in the plane and its bottom. */
    public void setBoxSize(int index, double width, double depth, double height) {
        if (!(obstacle(index) instanceof Obstacle.Box b)) throw new IllegalArgumentException("object " + index + " is not a box");
        if (!(width > 0) || !(depth > 0) || !(height > 0) || !Double.isFinite(width + depth + height)) {
            throw new IllegalArgumentException("box width, depth and height must be > 0");
        }
        Vec2 c = ObstacleTools.center(b);
        replaceObstacle(index, new Obstacle.Box(new Vec3(c.x() - width / 2, c.y() - depth / 2, b.min().z()),
                new Vec3(c.x() + width / 2, c.y() + depth / 2, b.min().z() + height), b.rotationDeg(), b.restitution()), "box size");
    }

    /** A model's scale (> 0). */
    public void setModelScale(int index, double scale) {
        if (!(obstacle(index) instanceof Obstacle.Model m)) throw new IllegalArgumentException("object " + index + " is not a model");
        if (!(scale > 0) || !Double.isFinite(scale)) throw new IllegalArgumentException("model scale must be > 0");
        replaceObstacle(index, new Obstacle.Model(m.file(), m.position(), m.rotationDeg(), scale, m.restitution(), m.mesh()),
                "model scale");
    }

    /** The share of the normal speed a ball keeps when it bounces off the object, 0 to 2 (above 1 a bumper). */
    public void setRestitution(int index, double restitution) {
        Obstacle o = obstacle(index);
        if (!(restitution >= 0 && restitution <= Obstacle.MAX_RESTITUTION)) {
            throw new IllegalArgumentException("restitution must be between 0 and " + (int) Obstacle.MAX_RESTITUTION);
        }
        replaceObstacle(index, ObstacleTools.withRestitution(o, restitution), "restitution");
    }

    /** A bumper's radius and height (both > 0). */
    public void setBumperSize(int index, double radius, double height) {
        Obstacle o = obstacle(index);
        Obstacle body = o instanceof Obstacle.Moving m ? m.body() : o;
        if (!(body instanceof Obstacle.Bumper b)) throw new IllegalArgumentException("object " + index + " is not a bumper");
        if (!(radius > 0) || !(height > 0) || !Double.isFinite(radius + height)) {
            throw new IllegalArgumentException("bumper radius and height must be > 0");
        }
        Obstacle sized = new Obstacle.Bumper(b.position(), radius, height, b.restitution());
        replaceObstacle(index, o instanceof Obstacle.Moving m ? new Obstacle.Moving(sized, m.motion()) : sized, "bumper size");
    }

    /** Turns a one-way gate round: the side the ball may pass to becomes the other. */
    public void flipGate(int index) {
        if (!(obstacle(index) instanceof Obstacle.Gate g)) throw new IllegalArgumentException("object " + index + " is not a gate");
        Obstacle.Side other = g.passTo() == Obstacle.Side.LEFT ? Obstacle.Side.RIGHT : Obstacle.Side.LEFT;
        replaceObstacle(index, new Obstacle.Gate(g.from(), g.to(), g.height(), other, g.restitution()), "gate direction");
    }

    /**
     * A moving obstacle's period and phase (s), its kind of motion kept; the limits of the course
     * format (docs/course-format.md, "Moving obstacles").
     */
    public void setMotionTiming(int index, double period, double phase) {
        if (!(obstacle(index) instanceof Obstacle.Moving m)) throw new IllegalArgumentException("object " + index + " does not move");
        if (!(period >= minigolf.course.Limits.SHORTEST_PERIOD && period <= minigolf.course.Limits.LONGEST_PERIOD)) {
            throw new IllegalArgumentException("the period must be between " + minigolf.course.Limits.SHORTEST_PERIOD + " and "
                    + (int) minigolf.course.Limits.LONGEST_PERIOD + " s");
        }
        if (!Double.isFinite(phase)) throw new IllegalArgumentException("the phase must be a number");
        replaceObstacle(index, new Obstacle.Moving(m.body(), MotionTools.withTiming(m.motion(), period, phase)), "motion timing");
    }

    // ---- push zones, magnets, teleports ----

    public List<PushZone> pushZones() {
        return List.copyOf(course.pushZones);
    }

    public List<Magnet> magnets() {
        return List.copyOf(course.magnets);
    }

    public List<Teleport> teleports() {
        return List.copyOf(course.teleports);
    }

    /** Adds a push zone (at most {@link minigolf.course.Limits#PUSH_ZONES}); false when full. */
    public boolean addPushZone(PushZone z) {
        if (course.pushZones.size() >= minigolf.course.Limits.PUSH_ZONES) return false;
        endStroke();
        perform(ListItemEdit.element(c -> c.pushZones, course.pushZones.size(), null, z, "place push zone"));
        return true;
    }

    public boolean addMagnet(Magnet m) {
        if (course.magnets.size() >= minigolf.course.Limits.MAGNETS) return false;
        endStroke();
        perform(ListItemEdit.element(c -> c.magnets, course.magnets.size(), null, m, "place magnet"));
        return true;
    }

    public boolean addTeleport(Teleport t) {
        if (course.teleports.size() >= minigolf.course.Limits.TELEPORTS) return false;
        endStroke();
        perform(ListItemEdit.element(c -> c.teleports, course.teleports.size(), null, t, "place teleport"));
        return true;
    }

    /** Replaces push zone {@code index} (null removes it). */
    public void setPushZone(int index, PushZone z) {
        PushZone before = item(course.pushZones, index, "push zone");
        if (z != null) {
            double strength = Math.hypot(z.push().x(), z.push().y());
            if (!(strength <= minigolf.course.Limits.FORCE)) {
                throw new IllegalArgumentException("a push must be at most " + (int) minigolf.course.Limits.FORCE + " m/s^2");
            }
        }
        if (before.equals(z)) return;
        endStroke();
        perform(ListItemEdit.element(c -> c.pushZones, index, before, z, z == null ? "delete push zone" : "edit push zone"));
    }

    /** Replaces magnet {@code index} (null removes it). */
    public void setMagnet(int index, Magnet m) {
        Magnet before = item(course.magnets, index, "magnet");
        if (m != null && (!(m.radius() > 0) || !(Math.abs(m.strength()) <= minigolf.course.Limits.FORCE))) {
            throw new IllegalArgumentException("a magnet's radius must be > 0 and its strength within +-"
                    + (int) minigolf.course.Limits.FORCE + " m/s^2");
        }
        if (before.equals(m)) return;
        endStroke();
        perform(ListItemEdit.element(c -> c.magnets, index, before, m, m == null ? "delete magnet" : "edit magnet"));
    }

    /** Replaces teleport {@code index} (null removes it). */
    public void setTeleport(int index, Teleport t) {
        Teleport before = item(course.teleports, index, "teleport");
        if (before.equals(t)) return;
        endStroke();
        perform(ListItemEdit.element(c -> c.teleports, index, before, t, t == null ? "delete teleport" : "edit teleport"));
    }

    private static <T> T item(List<T> list, int index, String what) {
        if (index < 0 || index >= list.size()) {
            throw new IllegalArgumentException("no " + what + " " + index + " (the course has " + list.size() + ")");
        }
        return list.get(index);
    }

    public void removeObstacle(int index) {
        Obstacle o = obstacle(index);
        endStroke();
        perform(ListItemEdit.obstacle(index, o, null, "delete " + ObstacleTools.describe(o)));
    }

    // ---- friction zones ----

    /** The course's friction zones (later ones win where they overlap). */
    public List<Zone> zones() {
        return List.copyOf(course.zones);
    }

    public void removeZone(int index) {
        Zone z = zone(index);
        endStroke();
        perform(ListItemEdit.zone(index, z, null, "delete zone"));
    }

    /** A zone's friction (both >= 0), its shape unchanged. */
    public void setZoneFriction(int index, double kinetic, double statics) {
        Zone z = zone(index);
        if (!(kinetic >= 0) || !(statics >= 0) || !Double.isFinite(kinetic + statics)) {
            throw new IllegalArgumentException("friction must be >= 0");
        }
        Zone next = new Zone(z.shape(), kinetic, statics);
        if (next.equals(z)) return;
        endStroke();
        perform(ListItemEdit.zone(index, z, next, "zone friction"));
    }

    private Zone zone(int index) {
        if (index < 0 || index >= course.zones.size()) {
            throw new IllegalArgumentException("no zone " + index + " (the course has " + course.zones.size() + ")");
        }
        return course.zones.get(index);
    }

    /** The index of the obstacle nearest to (x, y) within {@code maxDistance}, or -1. */
    public int obstacleNear(double x, double y, double maxDistance) {
        int best = -1;
        double bestD = maxDistance;
        for (int k = 0; k < course.obstacles.size(); k++) {
            double d = ObstacleTools.distance(course.obstacles.get(k), x, y);
            if (d <= bestD) {
                bestD = d;
                best = k;
            }
        }
        return best;
    }

    private Obstacle obstacle(int index) {
        if (index < 0 || index >= course.obstacles.size()) {
            throw new IllegalArgumentException("no obstacle " + index + " (the course has " + course.obstacles.size() + ")");
        }
        return course.obstacles.get(index);
    }

    // ---- start, hole, physics, name ----

    public void setStart(double x, double y) {
        inside(x, y, "start");
        EditableCourse.Properties p = course.properties;
        setProperties(new EditableCourse.Properties(p.name(), new Vec2(x, y), p.hole(), p.physics()), "move start");
    }

    public void setHole(double x, double y) {
        inside(x, y, "hole");
        EditableCourse.Properties p = course.properties;
        Hole h = p.hole();
        setProperties(new EditableCourse.Properties(p.name(), p.start(),
                new Hole(new Vec2(x, y), h.radius(), h.rule(), h.captureSpeed()), p.physics()), "move hole");
    }

    public void setHoleRadius(double radius) {
        if (!(radius > 0)) throw new IllegalArgumentException("hole radius must be > 0");
        EditableCourse.Properties p = course.properties;
        Hole h = p.hole();
        setProperties(new EditableCourse.Properties(p.name(), p.start(),
                new Hole(h.position(), radius, h.rule(), h.captureSpeed()), p.physics()), "hole radius");
    }

    public void setHoleRule(HoleRule rule) {
        EditableCourse.Properties p = course.properties;
        Hole h = p.hole();
        setProperties(new EditableCourse.Properties(p.name(), p.start(),
                new Hole(h.position(), h.radius(), rule, h.captureSpeed()), p.physics()), "hole rule");
    }

    public void setPhysics(PhysicsSettings physics) {
        if (!(physics.gravity() > 0) || !(physics.maxSpeed() > 0) || !(physics.kineticFriction() >= 0)
                || !(physics.staticFriction() >= 0)) {
            throw new IllegalArgumentException("gravity and maximum speed must be > 0, friction >= 0");
        }
        EditableCourse.Properties p = course.properties;
        setProperties(new EditableCourse.Properties(p.name(), p.start(), p.hole(), physics), "physics");
    }

    public void setName(String name) {
        if (name == null || name.isBlank()) throw new IllegalArgumentException("the course needs a name");
        EditableCourse.Properties p = course.properties;
        setProperties(new EditableCourse.Properties(name, p.start(), p.hole(), p.physics()), "rename");
    }

    private void setProperties(EditableCourse.Properties next, String label) {
        if (next.equals(course.properties)) return;
        endStroke();
        perform(new PropertiesEdit(course.properties, next, label));
    }

    private void inside(double x, double y, String what) {
        Bounds b = course.bounds;
        if (!b.contains(x, y)) {
            throw new IllegalArgumentException(String.format(java.util.Locale.ROOT,
                    "%s (%.2f, %.2f) must lie inside the bounds [%.2f, %.2f] x [%.2f, %.2f]", what, x, y,
                    b.minX(), b.maxX(), b.minY(), b.maxY()));
        }
    }

    // ---- validation and saving ----

    public List<Problem> validate() {
        endStroke();
        return CourseChecks.check(course, world());
    }

    /** Saves to the current file; see {@link #saveAs}. */
    public void save() throws CourseException {
        if (file == null) throw new CourseException(course.properties.name(), null, "cannot save: choose a file first (Save as)");
        saveAs(file);
    }

    /**
     * Validates, then writes the course atomically (a failed save leaves the previous file as it
     * was). The file becomes the editor's file and the course counts as saved.
     *
     * @throws CourseException naming the first problem when validation fails, or the write failed
     */
    public void saveAs(Path target) throws CourseException {
        List<Problem> problems = validate();
        if (!problems.isEmpty()) {
            throw new CourseException(String.valueOf(target), null, "cannot save: " + problems.get(0).message()
                    + (problems.size() > 1 ? " (and " + (problems.size() - 1) + " more)" : ""));
        }
        CourseWriter.save(course.toCourse(), target);
        file = target;
        history.markSaved();
    }
}
