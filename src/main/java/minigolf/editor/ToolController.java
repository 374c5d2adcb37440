package minigolf.editor;

import java.util.Locale;
import minigolf.course.Magnet;
import minigolf.course.Motion;
import minigolf.course.Obstacle;
import minigolf.course.PushZone;
import minigolf.course.Shape;
import minigolf.course.Teleport;
import minigolf.course.Vec2;
import minigolf.course.Vec3;

/**
 * The editor's tool: where it is on the course, which tool is active and its settings, and what
 * a key press or a click does. Mouse and keyboard both end here, so a test that presses keys
 * exercises the same path as a player. Every change goes through {@link CourseEditor}.
 */
public final class ToolController {
    /** The two tools the original editor switched between with SHIFT. */
    public enum Mode { TERRAIN, OBJECT }

    /** What the terrain tool does on ENTER or a click. */
    public enum TerrainAction {
        RAISE, LOWER, SMOOTH, FLATTEN, PAINT_GRASS, PAINT_SAND, PAINT_TYPED, SET_HEIGHT, DELETE_CELLS, RESTORE_CELLS,
        PLACE_START, PLACE_HOLE;

        public String label() {
            return name().toLowerCase(Locale.ROOT).replace('_', ' ');
        }
    }

    /**
     * What the object tool places: obstacles (the moving ones turn, slide, as issue 24 has them) and
     * the course elements that are areas or points (push zone, magnet, teleport).
     */
    public enum ObjectKind {
        WALL, TREE, BOX, MODEL, BUMPER, GATE, WINDMILL, TURNING_BAR, SLIDING_GATE, PUSH_ZONE, MAGNET, TELEPORT;

        /** Whether this kind is an obstacle (else a push zone, magnet or teleport). */
        public boolean isObstacle() {
            return ordinal() <= SLIDING_GATE.ordinal();
        }

        public String label() {
            return name().toLowerCase(Locale.ROOT).replace('_', ' ');
        }
    }

    /** The bundled model of a windmill's hub and blades (tools/generate_blades.py), turning about its x axis. */
    public static final String WINDMILL_BLADES = "models/windmill-blades.obj";

    /** How far from the tool an object counts as under it, in metres. */
    public static final double PICK_DISTANCE = 0.35;
    public static final double ROTATE_STEP_DEG = 15;

    private final CourseEditor editor;
    private double x, y;
    private Mode mode = Mode.TERRAIN;
    private TerrainAction action = TerrainAction.RAISE;
    private ObjectKind kind = ObjectKind.WALL;
    // Settings (the panels edit them).
    public double radius = 0.6;
    public double strength = 0.05;
    public double typedHeight = 0.1;
    public double typedKinetic = 0.12, typedStatic = 0.25;
    public double wallLength = 1.0, wallThickness = 0.05, wallHeight = 0.15;
    public double treeRadius = 0.12, treeHeight = 1.2;
    public double boxSize = 0.4, boxHeight = 0.3;
    /** The bundled model the object tool places (one of {@link ModelCatalog#BUNDLED}) and its scale. */
    public String modelFile = ModelCatalog.BUNDLED.get(0);
    public double modelScale = 1.0;
    public double restitution = Obstacle.DEFAULT_RESTITUTION;
    // The elements of issue 24.
    public double bumperRadius = 0.1, bumperRestitution = Obstacle.DEFAULT_BUMPER_RESTITUTION;
    public double gateLength = 0.8;
    /** A moving obstacle's period (s), and the windmill's hub height above the ground (its blades reach 0.5 m). */
    public double motionPeriod = 4, windmillHub = 0.53;
    /** A push zone's side (m), push (m/s²) and its direction (degrees from +x). */
    public double pushSize = 1.0, pushStrength = 1.0, pushDirectionDeg = 0;
    public double magnetRadius = 0.5, magnetStrength = 2;
    /** A teleport's entry radius and where its exit lies from the entry (m), the exit's direction (degrees, NaN: the ball keeps its own). */
    public double teleportRadius = 0.15, exitDx = 2, exitDy = 0, exitDirectionDeg = Double.NaN;

    public ToolController(CourseEditor editor) {
        this.editor = editor;
        EditableCourse c = editor.course();
        x = c.nodeX(c.columns() / 2);
        y = c.nodeY(c.rows() / 2);
    }

    public CourseEditor editor() {
        return editor;
    }

    public double x() {
        return x;
    }

    public double y() {
        return y;
    }

    /** Puts the tool at (x, y), clamped to the grid. */
    public void moveTo(double nx, double ny) {
        EditableCourse c = editor.course();
        x = Math.max(c.originX(), Math.min(c.nodeX(c.columns() - 1), nx));
        y = Math.max(c.originY(), Math.min(c.nodeY(c.rows() - 1), ny));
    }

    public Mode mode() {
        return mode;
    }

    public void setMode(Mode m) {
        mode = m;
    }

    public TerrainAction action() {
        return action;
    }

    public void setAction(TerrainAction a) {
        action = a;
        mode = Mode.TERRAIN;
    }

    public ObjectKind kind() {
        return kind;
    }

    public void setKind(ObjectKind k) {
        kind = k;
        mode = Mode.OBJECT;
    }

    /** Handles one key; returns a short message for the status line (null when there is nothing to say). */
    public String press(EditorKey key) {
        // Keys move the tool from node to node (a mouse-placed tool snaps to the nearest node first).
        EditableCourse g = editor.course();
        int ni = g.nearestColumn(x), nj = g.nearestRow(y);
        switch (key) {
            case UP -> moveTo(g.nodeX(ni), g.nodeY(nj + 1));
            case DOWN -> moveTo(g.nodeX(ni), g.nodeY(nj - 1));
            case LEFT -> moveTo(g.nodeX(ni - 1), g.nodeY(nj));
            case RIGHT -> moveTo(g.nodeX(ni + 1), g.nodeY(nj));
            case TOGGLE_TOOL -> {
                mode = mode == Mode.TERRAIN ? Mode.OBJECT : Mode.TERRAIN;
                return (mode == Mode.TERRAIN ? "terrain tool: " + action.label() : "object tool: " + kind.label());
            }
            case WALL -> {
                setKind(ObjectKind.WALL);
                return "object tool: wall";
            }
            case TREE -> {
                setKind(ObjectKind.TREE);
                return "object tool: tree";
            }
            case NEXT_KIND -> {
                ObjectKind[] kinds = ObjectKind.values();
                setKind(kinds[(kind.ordinal() + 1) % kinds.length]);
                return "object tool: " + kind.label();
            }
            case PLACE -> {
                return applyAt(x, y);
            }
            case DELETE -> {
                return deleteAt(x, y);
            }
            case ROTATE_LEFT, ROTATE_RIGHT -> {
                int k = editor.obstacleNear(x, y, PICK_DISTANCE);
                if (k < 0) return "no object under the tool";
                editor.rotateObstacle(k, key == EditorKey.ROTATE_LEFT ? ROTATE_STEP_DEG : -ROTATE_STEP_DEG);
                return null;
            }
            case UNDO -> {
                String label = editor.undoLabel();
                return editor.undo() ? "undid " + label : "nothing to undo";
            }
            case REDO -> {
                String label = editor.redoLabel();
                return editor.redo() ? "redid " + label : "nothing to redo";
            }
        }
        return null;
    }

    /** ENTER or a click at (px, py): the active tool's action there. */
    public String applyAt(double px, double py) {
        moveTo(px, py);
        try {
            if (mode == Mode.OBJECT && !kind.isObstacle()) return placeElement(x, y);
            if (mode == Mode.OBJECT) {
                Obstacle o = newObstacle(x, y);
                return editor.addObstacle(o) ? "placed " + ObstacleTools.describe(o)
                        : "the course already has the maximum of " + editor.maxObstacles() + " objects";
            }
            EditableCourse c = editor.course();
            switch (action) {
                case RAISE, LOWER, SMOOTH, FLATTEN -> editor.brush(brush(), x, y, radius, strength);
                case PAINT_GRASS -> editor.paint(x, y, radius, Surface.GRASS);
                case PAINT_SAND -> editor.paint(x, y, radius, Surface.SAND);
                case PAINT_TYPED -> editor.paint(x, y, radius, typedKinetic, typedStatic, "friction");
                case SET_HEIGHT -> editor.setNodeHeight(c.nearestColumn(x), c.nearestRow(y), typedHeight);
                case DELETE_CELLS -> editor.setCellsDeleted(x, y, Math.max(radius, 0.75 * c.spacing()), true);
                case RESTORE_CELLS -> editor.setCellsDeleted(x, y, Math.max(radius, 0.75 * c.spacing()), false);
                case PLACE_START -> editor.setStart(x, y);
                case PLACE_HOLE -> editor.setHole(x, y);
            }
            return null;
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
    }

    /** The brush of a brush action (RAISE..FLATTEN). */
    public Brush brush() {
        return switch (action) {
            case LOWER -> Brush.LOWER;
            case SMOOTH -> Brush.SMOOTH;
            case FLATTEN -> Brush.FLATTEN;
            default -> Brush.RAISE;
        };
    }

    public boolean isBrushAction() {
        return mode == Mode.TERRAIN && (action == TerrainAction.RAISE || action == TerrainAction.LOWER
                || action == TerrainAction.SMOOTH || action == TerrainAction.FLATTEN);
    }

    /** P at (px, py): the object under the tool, or (terrain tool) the cell under it. */
    public String deleteAt(double px, double py) {
        moveTo(px, py);
        if (mode == Mode.OBJECT) {
            int k = editor.obstacleNear(x, y, PICK_DISTANCE);
            if (k < 0) return deleteElementAt(x, y);
            String what = ObstacleTools.describe(editor.course().obstacles().get(k));
            editor.removeObstacle(k);
            return "deleted " + what;
        }
        EditableCourse c = editor.course();
        // The tool sits on a node: take the cell whose lower-left corner it is (the last one at the far edges);
        // half a cell's offset keeps rounding in the tool's position from picking the neighbour.
        int i = c.cellColumn(Math.min(x + 0.5 * c.spacing(), c.nodeX(c.columns() - 1)));
        int j = c.cellRow(Math.min(y + 0.5 * c.spacing(), c.nodeY(c.rows() - 1)));
        if (i < 0 || j < 0) return "no cell under the tool";
        editor.setCellDeleted(i, j, !c.isDeleted(i, j));
        return (c.isDeleted(i, j) ? "deleted" : "restored") + " cell (" + i + ", " + j + ")";
    }

    /** The object the tool would place at (px, py), standing on the terrain. */
    public Obstacle newObstacle(double px, double py) {
        return switch (kind) {
            case WALL -> new Obstacle.Wall(new Vec2(px - wallLength / 2, py), new Vec2(px + wallLength / 2, py),
                    wallThickness, wallHeight, restitution);
            case TREE -> new Obstacle.Tree(new Vec2(px, py), treeRadius, treeHeight, restitution);
            case BOX -> {
                double ground = editor.world().terrain().height(px, py);
                double hs = boxSize / 2;
                yield new Obstacle.Box(new Vec3(px - hs, py - hs, ground - 0.05), new Vec3(px + hs, py + hs, ground + boxHeight),
                        0, restitution);
            }
            // Stands on the ground at the tool: the model's z = 0 goes to the terrain height there.
            case MODEL -> new Obstacle.Model(modelFile, new Vec3(px, py, editor.world().terrain().height(px, py)), 0,
                    modelScale, restitution, ModelCatalog.load(modelFile));
            case BUMPER -> new Obstacle.Bumper(new Vec2(px, py), bumperRadius, 0.1, bumperRestitution);
            case GATE -> new Obstacle.Gate(new Vec2(px, py - gateLength / 2), new Vec2(px, py + gateLength / 2), 0.1,
                    Obstacle.Side.RIGHT, restitution);
            case WINDMILL -> {
                // Blades turning about the horizontal x axis through the hub, across a lane that runs along x.
                Vec3 hub = new Vec3(px, py, editor.world().terrain().height(px, py) + windmillHub);
                yield new Obstacle.Moving(new Obstacle.Model(WINDMILL_BLADES, hub, 0, 1, restitution, ModelCatalog.load(WINDMILL_BLADES)),
                        new Motion.Rotate(hub, new Vec3(1, 0, 0), motionPeriod, 0));
            }
            case TURNING_BAR -> {
                double ground = editor.world().terrain().height(px, py);
                yield new Obstacle.Moving(new Obstacle.Box(new Vec3(px - 0.5, py - 0.03, ground - 0.05),
                        new Vec3(px + 0.5, py + 0.03, ground + 0.12), 0, restitution),
                        new Motion.Rotate(new Vec3(px, py, ground), new Vec3(0, 0, 1), motionPeriod, 0));
            }
            case SLIDING_GATE -> {
                double ground = editor.world().terrain().height(px, py);
                yield new Obstacle.Moving(new Obstacle.Box(new Vec3(px - 0.04, py - 0.3, ground - 0.05),
                        new Vec3(px + 0.04, py + 0.3, ground + 0.2), 0, restitution),
                        new Motion.Slide(java.util.List.of(new Vec3(0, 0, 0), new Vec3(0, 0.65, 0)), motionPeriod, 0, false));
            }
            default -> throw new IllegalArgumentException(kind.label() + " is not an obstacle");
        };
    }

    /** Deletes the magnet within reach of (px, py), else the teleport or push zone it lies in (the last placed first). */
    private String deleteElementAt(double px, double py) {
        java.util.List<Magnet> magnets = editor.magnets();
        for (int i = magnets.size() - 1; i >= 0; i--) {
            if (Math.hypot(magnets.get(i).position().x() - px, magnets.get(i).position().y() - py) <= PICK_DISTANCE) {
                editor.setMagnet(i, null);
                return "deleted magnet";
            }
        }
        java.util.List<Teleport> teleports = editor.teleports();
        for (int i = teleports.size() - 1; i >= 0; i--) {
            if (teleports.get(i).entry().contains(px, py)) {
                editor.setTeleport(i, null);
                return "deleted teleport";
            }
        }
        java.util.List<PushZone> pushes = editor.pushZones();
        for (int i = pushes.size() - 1; i >= 0; i--) {
            if (pushes.get(i).shape().contains(px, py)) {
                editor.setPushZone(i, null);
                return "deleted push zone";
            }
        }
        return "no object under the tool";
    }

    /** Places the push zone, magnet or teleport of the tool's kind at (px, py). */
    private String placeElement(double px, double py) {
        switch (kind) {
            case PUSH_ZONE -> {
                double a = Math.toRadians(pushDirectionDeg), h = pushSize / 2;
                PushZone z = new PushZone(new Shape.Rect(new Vec2(px - h, py - h), new Vec2(px + h, py + h)),
                        new Vec2(pushStrength * Math.cos(a), pushStrength * Math.sin(a)));
                return editor.addPushZone(z) ? "placed push zone" : "the course already has the most push zones";
            }
            case MAGNET -> {
                return editor.addMagnet(new Magnet(new Vec2(px, py), magnetRadius, magnetStrength)) ? "placed magnet"
                        : "the course already has the most magnets";
            }
            default -> {
                Teleport t = new Teleport(new Shape.Circle(new Vec2(px, py), teleportRadius),
                        java.util.List.of(new Teleport.Exit(new Vec2(px + exitDx, py + exitDy),
                                Double.isNaN(exitDirectionDeg) ? null : exitDirectionDeg)));
                return editor.addTeleport(t) ? "placed teleport (exit at " + String.format(Locale.ROOT, "%.2f, %.2f", px + exitDx, py + exitDy) + ")"
                        : "the course already has the most teleports";
            }
        }
    }
}
