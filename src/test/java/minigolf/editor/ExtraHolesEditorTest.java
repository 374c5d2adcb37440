package minigolf.editor;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.Vec2;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The editor places only the main hole; a course's other holes (extraHoles) survive editing and saving. */
class ExtraHolesEditorTest {
    @TempDir
    Path dir;

    @Test
    void extraHolesAreKeptThroughAnEditAndASave() throws Exception {
        Course plain = EditorOperationsTest.flat().toCourse();
        List<Hole> extra = List.of(new Hole(new Vec2(-2, 1), 0.12, HoleRule.CAPTURE, 0.5),
                new Hole(new Vec2(1, -1), 0.1, HoleRule.REST, null));
        CourseEditor e = CourseEditor.of(plain.withHoles(plain.hole(), extra), null);
        e.setNodeHeight(0, 0, 0.2);
        assertEquals(extra, e.toCourse().extraHoles());
        Path file = dir.resolve("holes.json");
        e.saveAs(file);
        assertEquals(extra, World.load(file).course().extraHoles());
        assertEquals(extra, CourseEditor.open(file).toCourse().extraHoles());
    }
}
