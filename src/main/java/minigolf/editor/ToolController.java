package minigolf.editor;

import java.util.Locale;
import minigolf.course.Obstacle;
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

    /** What the object tool places. */
    public enum ObjectKind { WALL, TREE, BOX, MODEL }

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
                return (mode == Mode.TERRAIN ? "terrain tool: " + action.label() : "object tool: " + kind.name().toLowerCase(Locale.ROOT));
            }
            case WALL -> {
                setKind(ObjectKind.WALL);
                return "object tool: wall";
            }
            case TREE -> {
                setKind(ObjectKind.TREE);
                return "object tool: tree";
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
            if (k < 0) return "no object under the tool";
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
        };
    }
}
