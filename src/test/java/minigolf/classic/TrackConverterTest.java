package minigolf.classic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.CourseLoader;
import minigolf.course.CourseWriter;
import minigolf.course.Limits;
import minigolf.course.Obstacle;
import minigolf.course.Shape;
import minigolf.course.Zone;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TrackConverterTest {
    static final ClassicScale SCALE = ClassicScale.standard();
    static final int BLOCK = TileMap.elementTile(0, PixelMap.BLOCK, PixelMap.BLOCK);

    static ClassicTrack track(int[] codes) {
        return new ClassicTrack(2, "Tester", "Test", EnumSet.of(TrackCategory.BASIC), null, null, null,
                ClassicTrack.DEFAULT_SETTINGS, new TileMap(codes));
    }

    static TrackConverter.Converted convert(int[] codes) throws TrackFormatException {
        return TrackConverter.convert(track(codes), ShapeMasks.builtIn(), SCALE);
    }

    static List<Obstacle.Model> models(Course c) {
        return c.obstacles().stream().filter(o -> o instanceof Obstacle.Model).map(o -> (Obstacle.Model) o).toList();
    }

    @Test
    void scaleAndPlaces() throws Exception {
        Course c = convert(Tracks.framed()).course();
        assertEquals(49 * 0.25, c.bounds().maxX(), 1e-12);
        assertEquals(25 * 0.25, c.bounds().maxY(), 1e-12);
        // The ball is 13 px across on 15 px tiles.
        assertEquals(6.5 / 15 * 0.25, c.physics().ballRadius(), 1e-12);
        // Start tile (4, 12) and hole tile (44, 12), y measured up from the bottom edge.
        assertEquals(4.5 * 0.25, c.start().x(), 1e-12);
        assertEquals(12.5 * 0.25, c.start().y(), 1e-12);
        assertEquals(44.5 * 0.25, c.hole().position().x(), 1e-12);
        assertEquals(12.5 * 0.25, c.hole().position().y(), 1e-12);
    }

    /** The blue coloured start wins over a common start; without starts the ball starts in the middle. */
    @Test
    void startChoice() throws Exception {
        int[] codes = Tracks.framed();
        Tracks.set(codes, 30, 3, TileMap.specialTile(24, PixelMap.GRASS));
        Course c = convert(codes).course();
        assertEquals(30.5 * 0.25, c.start().x(), 1e-12);
        assertEquals((25 - 3.5) * 0.25, c.start().y(), 1e-12);
        codes = Tracks.framed();
        Tracks.set(codes, 4, 12, TileMap.GRASS);
        TrackConverter.Converted none = convert(codes);
        assertEquals(49 * 0.25 / 2, none.course().start().x(), 1e-12);
        assertTrue(none.notes().stream().anyMatch(n -> n.startsWith("start: none")), none.notes().toString());
    }

    @Test
    void aMapWithoutHoleIsRefused() {
        int[] codes = Tracks.framed();
        Tracks.set(codes, 44, 12, TileMap.GRASS);
        assertEquals("Test: the map has no hole",
                assertThrows(TrackFormatException.class, () -> convert(codes)).getMessage());
    }

    /** Touching wall tiles of one kind become one model; the frame and an inner wall are few triangles. */
    @Test
    void touchingWallTilesMerge() throws Exception {
        int[] codes = Tracks.framed();
        for (int x = 10; x <= 30; x++) Tracks.set(codes, x, 6, BLOCK);
        for (int y = 1; y <= 6; y++) Tracks.set(codes, 20, y, BLOCK); // joins the frame
        // A diagonal and a rounded corner in the inner wall.
        Tracks.set(codes, 31, 6, TileMap.elementTile(4, PixelMap.BLOCK, PixelMap.GRASS));
        Tracks.set(codes, 9, 6, TileMap.elementTile(9, PixelMap.BLOCK, PixelMap.GRASS));
        Course c = convert(codes).course();
        List<Obstacle.Model> walls = models(c);
        assertEquals(1, walls.size());
        assertEquals("block.obj", walls.get(0).file());
        assertTrue(walls.get(0).mesh().triangleCount() < 400, "triangles: " + walls.get(0).mesh().triangleCount());
        assertEquals(0.81, walls.get(0).restitution(), 1e-12);
        // And the four fences on the map's edge.
        assertEquals(5, c.obstacles().size());
    }

    /** Each kind of wall is its own model with its own bounce. */
    @Test
    void wallKinds() throws Exception {
        int[] codes = Tracks.framed();
        Tracks.set(codes, 10, 5, TileMap.elementTile(0, PixelMap.STICKY, PixelMap.STICKY));
        Tracks.set(codes, 12, 5, TileMap.elementTile(0, PixelMap.BOUNCY, PixelMap.BOUNCY));
        Tracks.set(codes, 14, 5, TileMap.specialTile(3, PixelMap.GRASS));  // movable block
        Tracks.set(codes, 16, 5, TileMap.specialTile(16, PixelMap.GRASS)); // breakable brick
        Tracks.set(codes, 18, 5, TileMap.elementTile(0, PixelMap.ILLUSION, PixelMap.ILLUSION));
        TrackConverter.Converted t = convert(codes);
        List<String> files = models(t.course()).stream().map(Obstacle.Model::file).toList();
        assertEquals(List.of("block.obj", "sticky.obj", "bouncy.obj", "movable.obj"), files);
        // The brick is a breakable brick, not a wall (ClassicBricksTest).
        assertEquals(1, t.course().bricks().size());
        assertTrue(t.files().containsKey("walls.mtl"));
        assertTrue(t.notes().stream().anyMatch(n -> n.startsWith("illusion")), t.notes().toString());
    }

    /** A map packed with wall tiles in the worst pattern stays under every limit and loads. */
    @Test
    void aMapFullOfWallsLoads(@TempDir Path dir) throws Exception {
        int[] codes = Tracks.framed();
        int walls = 0;
        for (int y = 1; y < 24; y++) {
            for (int x = 1; x < 48; x++) {
                if ((x + y) % 2 == 0 && TileMap.kind(codes[x + 49 * y]) == TileMap.ELEMENT_TILE) {
                    Tracks.set(codes, x, y, TileMap.elementTile(4 + (x / 2 + y) % 8, PixelMap.BLOCK, PixelMap.GRASS));
                    walls++;
                }
            }
        }
        assertTrue(walls > 500);
        TrackConverter.Converted t = convert(codes);
        assertTrue(t.course().obstacles().size() <= Limits.OBSTACLES);
        Path course = write(t, dir);
        World w = World.load(course);
        assertEquals(t.course().obstacles().size(), w.course().obstacles().size());
    }

    /** Surfaces become cell zones with the original's friction; water and acid are hazards. */
    @Test
    void surfacesAndHazards() throws Exception {
        int[] codes = Tracks.framed();
        int[] elements = {PixelMap.SAND, PixelMap.MUD, PixelMap.ICE, PixelMap.WATER, PixelMap.ACID,
                PixelMap.SHALLOW_WATER, PixelMap.SHALLOW_ACID};
        for (int i = 0; i < elements.length; i++) {
            Tracks.set(codes, 10 + 3 * i, 20, TileMap.elementTile(0, elements[i], elements[i]));
        }
        Course c = convert(codes).course();
        assertEquals(elements.length + 1, c.zones().size()); // and the hole's (slower) surface
        Zone sand = zoneAt(c, 10), water = zoneAt(c, 19), acid = zoneAt(c, 22), shallow = zoneAt(c, 25),
                shallowAcid = zoneAt(c, 28), ice = zoneAt(c, 16), mud = zoneAt(c, 13);
        assertTrue(sand.shape() instanceof Shape.Cells);
        assertNull(sand.hazard());
        assertEquals(SCALE.friction(0.08), sand.kineticFriction(), 1e-12);
        assertTrue(mud.kineticFriction() > sand.kineticFriction());
        assertTrue(ice.kineticFriction() < c.physics().kineticFriction());
        assertEquals(new Zone.Hazard(Zone.Hazard.Kind.WATER, Zone.Hazard.When.ENTER, Zone.Hazard.ReturnTo.STROKE_START, 0),
                water.hazard());
        assertEquals(new Zone.Hazard(Zone.Hazard.Kind.ACID, Zone.Hazard.When.ENTER, Zone.Hazard.ReturnTo.COURSE_START, 0),
                acid.hazard());
        assertEquals(Zone.Hazard.When.REST, shallow.hazard().when());
        assertEquals(Zone.Hazard.ReturnTo.COURSE_START, shallowAcid.hazard().returnTo());
        // Exactly the tile: 15 x 15 cells.
        Shape.Cells cells = (Shape.Cells) sand.shape();
        double px = SCALE.pixel(), y = (25 - 20.5) * 0.25;
        assertTrue(cells.contains(10 * 0.25 + px / 2, y));
        assertTrue(cells.contains(11 * 0.25 - px / 2, y));
        assertTrue(!cells.contains(10 * 0.25 - px / 2, y) && !cells.contains(11 * 0.25 + px / 2, y));
    }

    /** A special tile's background element shows round the special (a hole on sand). */
    @Test
    void specialsStandOnTheirElement() throws Exception {
        int[] codes = Tracks.framed();
        Tracks.set(codes, 44, 12, TileMap.specialTile(1, PixelMap.SAND));
        Course c = convert(codes).course();
        Zone sand = c.zones().stream().filter(z -> z.kineticFriction() == SCALE.friction(0.08)).findFirst().orElse(null);
        assertNotNull(sand);
        Shape.Cells cells = (Shape.Cells) sand.shape();
        assertTrue(cells.contains(44 * 0.25 + 0.01, (25 - 12.5) * 0.25 + 0.1)); // the tile's corner
        assertTrue(!cells.contains(44.5 * 0.25, (25 - 12.5) * 0.25));           // the hole in the middle
    }

    private static Zone zoneAt(Course c, int tileX) {
        double x = (tileX + 0.5) * 0.25, y = (25 - 20.5) * 0.25;
        for (Zone z : c.zones()) if (z.shape().contains(x, y)) return z;
        return null;
    }

    static Path write(TrackConverter.Converted t, Path dir) throws Exception {
        for (var f : t.files().entrySet()) Files.writeString(dir.resolve(f.getKey()), f.getValue());
        Path course = dir.resolve("course.json");
        CourseWriter.save(t.course(), course);
        // And it reads back as the same course.
        Course again = CourseLoader.load(course);
        assertEquals(t.course().zones(), again.zones());
        return course;
    }
}
