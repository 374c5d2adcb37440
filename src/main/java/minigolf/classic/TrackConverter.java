package minigolf.classic;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import minigolf.course.Bounds;
import minigolf.course.Brick;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.Limits;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.course.Shape;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.course.Vec3;
import minigolf.course.Zone;
import minigolf.mesh.ObjException;
import minigolf.mesh.ObjParser;
import minigolf.mesh.TriangleMesh;

/**
 * A classic track as one of our courses (docs/classic-tracks.md): a flat green the size of the
 * map, each surface a zone of the map's pixels (sand, mud, ice, the downhill tiles, shallow and deep
 * water and acid as hazard zones), each kind of wall one mesh of all its touching pixels, the start,
 * the hole and fences round the map's edge. Plain Java: the caller writes the files.
 */
public final class TrackConverter {
    /** The walls' height above the ground, in tiles. */
    static final double WALL_HEIGHT_TILES = 0.6;
    /** How far walls reach below the ground, in tiles (so no ball rolls under). */
    static final double WALL_DEPTH_TILES = 0.1;
    /** The hole's capture radius as a share of the hole's drawn radius (docs/classic-tracks.md). */
    static final double HOLE_CAPTURE_SHARE = 0.8;
    /** The hole drawn in the original: a disc about this many pixels across. */
    static final double HOLE_PIXELS = 14.4;
    /** The capture speed as a multiple of the fastest shot: a hard, straight shot still drops. */
    static final double HOLE_CAPTURE_SPEED = 1.1;
    /** Static friction of the surfaces: a ball stops on them, the downhill tiles' push moves it on. */
    static final double STATIC_FRICTION = 0.06;
    static final String MATERIALS = "walls.mtl";

    /** A converted track: the course, the files its models need (name to text) and what was changed or left out. */
    public record Converted(Course course, Map<String, String> files, List<String> notes) {
    }

    /** A surface: the pixels whose value is in {@code values}, with the original's per-tick loss. */
    private record Surface(String name, int[] values, double loss, Zone.Hazard hazard) {
    }

    private static final List<Surface> SURFACES = List.of(
            new Surface("sand", new int[]{PixelMap.SAND}, 0.08, null),
            new Surface("mud", new int[]{PixelMap.MUD}, 0.2, null),
            new Surface("ice", new int[]{PixelMap.ICE, 32, 34, 36, 38}, 0.0025, null),
            new Surface("one-way", new int[]{20, 21, 22, 23}, 0.005, null),
            new Surface("hole", new int[]{PixelMap.HOLE}, 0.04, null),
            new Surface("spent mine", new int[]{PixelMap.MINE_SPENT, PixelMap.BIG_MINE_SPENT}, 0.1, null),
            new Surface("magnet", new int[]{PixelMap.MAGNET}, 0.1, null),
            new Surface("mine", new int[]{PixelMap.MINE, PixelMap.BIG_MINE}, 0, null),
            new Surface("shallow water", new int[]{PixelMap.SHALLOW_WATER}, 0.05,
                    new Zone.Hazard(Zone.Hazard.Kind.WATER, Zone.Hazard.When.REST, Zone.Hazard.ReturnTo.STROKE_START, 0)),
            new Surface("shallow acid", new int[]{PixelMap.SHALLOW_ACID}, 0.05,
                    new Zone.Hazard(Zone.Hazard.Kind.ACID, Zone.Hazard.When.REST, Zone.Hazard.ReturnTo.COURSE_START, 0)),
            new Surface("water", new int[]{PixelMap.WATER}, 1,
                    new Zone.Hazard(Zone.Hazard.Kind.WATER, Zone.Hazard.When.ENTER, Zone.Hazard.ReturnTo.STROKE_START, 0)),
            new Surface("acid", new int[]{PixelMap.ACID}, 1,
                    new Zone.Hazard(Zone.Hazard.Kind.ACID, Zone.Hazard.When.ENTER, Zone.Hazard.ReturnTo.COURSE_START, 0)));

    /** A kind of wall: its pixel values, its file's name and material, its restitution. */
    private record WallKind(String name, int[] values, double restitution) {
    }

    private static final List<WallKind> WALLS = List.of(
            new WallKind("block", new int[]{PixelMap.BLOCK}, 0.81),
            new WallKind("sticky", new int[]{PixelMap.STICKY}, 0.05),
            // 1, not above: the original's bouncy wall stops giving speed after 100 bounces in a stroke;
            // ours would give it for ever, and a downhill tile pushing the ball back at one bounced it
            // until the stroke's time limit (10 minutes) on a sample track.
            new WallKind("bouncy", new int[]{PixelMap.BOUNCY}, 1.0),
            new WallKind("movable", new int[]{PixelMap.MOVABLE, PixelMap.SINKABLE}, 0.8));

    private TrackConverter() {
    }

    public static Converted convert(ClassicTrack track, ShapeMasks masks, ClassicScale scale) throws TrackFormatException {
        PixelMap map = PixelMap.of(track.tiles(), masks);
        double px = scale.pixel();
        List<String> notes = new ArrayList<>();
        if (!masks.exact()) notes.add("shapes: " + masks.source());
        if (track.tiles().filledRows() > 0) notes.add("map: the data ends after row 24; the last row is grass");

        // Start and holes, from the special tiles (row by row, as the original lists them).
        Vec2 start = null, blueStart = null;
        List<Vec2> holes = new ArrayList<>();
        int starts = 0;
        for (int ty = 0; ty < TileMap.HEIGHT; ty++) {
            for (int tx = 0; tx < TileMap.WIDTH; tx++) {
                int code = track.tiles().code(tx, ty);
                if (TileMap.kind(code) != TileMap.SPECIAL_TILE) continue;
                Vec2 centre = new Vec2((tx + 0.5) * scale.tile(), (TileMap.HEIGHT - ty - 0.5) * scale.tile());
                int special = TileMap.shape(code);
                if (special == 0) {
                    starts++;
                    if (start == null) start = centre;
                } else if (special == 24 && blueStart == null) {
                    blueStart = centre;
                } else if (special == 1) {
                    holes.add(centre);
                }
            }
        }
        // The first player starts on the blue start, else on the first common start (the original
        // draws one of several at random), else in the middle of the map.
        Vec2 first = blueStart != null ? blueStart : start != null ? start
                : new Vec2(scale.width() / 2, scale.height() / 2);
        if (blueStart == null && starts > 1) notes.add("start: the first of " + starts + " start tiles (the original draws one)");
        if (blueStart == null && start == null) notes.add("start: none on the map: the middle, as the original");
        if (holes.isEmpty()) throw new TrackFormatException(track.name() + ": the map has no hole");
        if (holes.size() > 1 + Limits.EXTRA_HOLES) {
            notes.add("holes: " + holes.size() + " on the map; the first " + (1 + Limits.EXTRA_HOLES) + " are holes here");
            holes = holes.subList(0, 1 + Limits.EXTRA_HOLES);
        }

        double width = scale.width(), height = scale.height();
        PhysicsSettings physics = new PhysicsSettings(ClassicScale.GRAVITY, scale.friction(0.0065), STATIC_FRICTION,
                scale.maxSpeed(), PhysicsModel.CLASSIC, scale.ballRadius(), PhysicsSettings.DEFAULT_BALL_MASS,
                PhysicsSettings.DEFAULT_DRAG_COEFFICIENT, PhysicsSettings.DEFAULT_AIR_DENSITY, null, true);
        // Every hole ends the stroke, as in the original; the first (row by row) carries the flag.
        List<Hole> cups = new ArrayList<>();
        for (Vec2 h : holes) {
            cups.add(new Hole(h, HOLE_CAPTURE_SHARE * HOLE_PIXELS / 2 * px, HoleRule.CAPTURE,
                    HOLE_CAPTURE_SPEED * scale.maxSpeed()));
        }

        List<Zone> zones = new ArrayList<>();
        for (Surface s : SURFACES) {
            int[] spans = spans(map, s.values());
            if (spans.length == 0) continue;
            double mu = scale.friction(s.loss());
            zones.add(new Zone(new Shape.Cells(new Vec2(0, 0), px, PixelMap.WIDTH, PixelMap.HEIGHT, spans),
                    mu, Math.max(mu, STATIC_FRICTION), s.hazard()));
        }

        List<Obstacle> obstacles = new ArrayList<>();
        Map<String, String> files = new LinkedHashMap<>();
        double top = WALL_HEIGHT_TILES * scale.tile(), bottom = -WALL_DEPTH_TILES * scale.tile();
        for (WallKind w : WALLS) {
            PixelRegions.Mask mask = mask(map, w.values());
            if (mask.isEmpty()) continue;
            List<WallMesh> parts = WallMesh.split(mask, px, bottom, top, ObjParser.MAX_TRIANGLES, ObjParser.MAX_VERTICES);
            for (int i = 0; i < parts.size(); i++) {
                String file = w.name() + (parts.size() > 1 ? "-" + (i + 1) : "") + ".obj";
                String obj = parts.get(i).obj(MATERIALS, w.name());
                TriangleMesh mesh;
                try {
                    mesh = ObjParser.parse(obj);
                } catch (ObjException e) {
                    throw new IllegalStateException("a generated wall mesh does not parse: " + e.getMessage(), e);
                }
                files.put(file, obj);
                obstacles.add(new Obstacle.Model(file, new Vec3(0, 0, 0), 0, 1, w.restitution(), mesh));
            }
        }
        if (!files.isEmpty()) files.put(MATERIALS, materials());
        // The original keeps the ball's centre inside the map: fences round the edge (the ball slides along them).
        Vec2 a = new Vec2(0, 0), b = new Vec2(width, 0), c = new Vec2(width, height), d = new Vec2(0, height);
        for (Vec2[] e : new Vec2[][]{{a, b}, {b, c}, {c, d}, {d, a}}) {
            obstacles.add(new Obstacle.Wall(e[0], e[1], 0, top, 0));
        }
        List<Vec2> avoid = new ArrayList<>(holes);
        avoid.add(0, first);
        ClassicElements elements = ClassicElements.of(track, map, scale, top, avoid);
        obstacles.addAll(elements.gates);
        notes.addAll(elements.notes);
        noteUnsupported(map, notes);
        Course course = new Course(Course.FORMAT, track.name(), new TerrainSpec.HeightExpression("0"),
                new Bounds(0, 0, width, height), physics, first, cups.get(0), zones, obstacles)
                .withElements(elements.pushZones, elements.magnets, elements.teleports)
                .withHoles(cups.get(0), cups.subList(1, cups.size()))
                .withBricks(bricks(track, scale, bottom, top));
        return new Converted(course, files, List.copyOf(notes));
    }

    /**
     * The breakable bricks: one per brick tile (the original's special blocks 40..43, a whole tile
     * each), with 4..1 hits left as the tile shows, restitution 0.9 as the original's.
     */
    static List<Brick> bricks(ClassicTrack track, ClassicScale scale, double bottom, double top) {
        List<Brick> bricks = new ArrayList<>();
        double t = scale.tile();
        for (int ty = 0; ty < TileMap.HEIGHT; ty++) {
            for (int tx = 0; tx < TileMap.WIDTH; tx++) {
                int code = track.tiles().code(tx, ty);
                if (TileMap.kind(code) != TileMap.SPECIAL_TILE) continue;
                int value = 24 + TileMap.shape(code);
                if (value < PixelMap.BRICK_FULL || value > PixelMap.BRICK_QUARTER) continue;
                double y0 = (TileMap.HEIGHT - ty - 1) * t;
                bricks.add(new Brick(new Vec3(tx * t, y0, bottom), new Vec3((tx + 1) * t, y0 + t, top),
                        PixelMap.BRICK_QUARTER + 1 - value, Brick.DEFAULT_RESTITUTION));
            }
        }
        return bricks;
    }

    /** Elements the course does not play as the original yet (docs/classic-tracks.md lists them). */
    private static void noteUnsupported(PixelMap map, List<String> notes) {
        boolean mine = false, movable = false, illusion = false;
        for (int y = 0; y < PixelMap.HEIGHT; y++) {
            for (int x = 0; x < PixelMap.WIDTH; x++) {
                int v = map.at(x, y);
                mine |= v == PixelMap.MINE || v == PixelMap.BIG_MINE;
                movable |= v == PixelMap.MOVABLE || v == PixelMap.SINKABLE;
                illusion |= v == PixelMap.ILLUSION;
            }
        }
        if (mine) notes.add("not yet played: mines");
        if (movable) notes.add("not yet played: movable blocks (still walls)");
        if (illusion) notes.add("illusion blocks are drawn as grass (the ball rolls through them, as in the original)");
    }

    /** The pixels with one of {@code values}, as cell spans {row, start, end} with row 0 at the bottom. */
    static int[] spans(PixelMap map, int[] values) {
        return ClassicElements.spans(map.where(values));
    }

    static PixelRegions.Mask mask(PixelMap map, int[] values) {
        return new PixelRegions.Mask(PixelMap.WIDTH, PixelMap.HEIGHT, map.where(values));
    }

    /** The walls' colours, close to the original's sprites. */
    static String materials() {
        return """
                # made by minigolf import-tracks
                newmtl block
                Kd 0.55 0.42 0.33
                newmtl sticky
                Kd 0.36 0.52 0.22
                newmtl bouncy
                Kd 0.88 0.38 0.62
                newmtl movable
                Kd 0.66 0.50 0.27
                newmtl brick
                Kd 0.72 0.28 0.18
                """;
    }
}
