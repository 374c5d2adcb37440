package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import minigolf.course.Brick;
import minigolf.course.Course;
import minigolf.course.Vec3;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The editor does not edit breakable bricks; a course's bricks survive editing and saving (before, any edit dropped them). */
class BricksEditorTest {
    @TempDir
    Path dir;

    @Test
    void bricksAreKeptThroughAnEditAndASave() throws Exception {
        Course plain = EditorOperationsTest.flat().toCourse();
        List<Brick> bricks = List.of(new Brick(new Vec3(-2, 1, -0.1), new Vec3(-1.75, 1.25, 0.2), 4, 0.9),
                new Brick(new Vec3(1, -1, -0.1), new Vec3(1.25, -0.75, 0.2), 2, 0.5));
        CourseEditor e = CourseEditor.of(plain.withBricks(bricks), null);
        e.setNodeHeight(0, 0, 0.2);
        assertEquals(bricks, e.toCourse().bricks());
        assertEquals(bricks, e.world().course().bricks());
        Path file = dir.resolve("bricks.json");
        e.saveAs(file);
        assertEquals(bricks, World.load(file).course().bricks());
        assertEquals(bricks, CourseEditor.open(file).toCourse().bricks());
    }
}
