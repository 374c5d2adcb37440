package minigolf.render;

import minigolf.physics.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import static org.junit.jupiter.api.Assertions.*;
import static org.lwjgl.opengl.GL11.GL_NO_ERROR;
import static org.lwjgl.opengl.GL11.glGetError;

/** Every course in courses/ renders from above; water shows exactly where the course has water (needs xvfb-run). */
class CourseRenderTest {
    static final int W = 480, H = 300;

    static List<Path> courses() throws IOException {
        Path dir = Path.of(System.getProperty("minigolf.projectDir", ".")).resolve("courses");
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(p -> p.toString().endsWith(".json")).sorted().toList();
        }
    }

    @Test
    void everyCourseRendersWithWaterExactlyWhereItHasWater() throws Exception {
        List<Path> all = courses();
        assertTrue(all.size() >= 8, "courses found: " + all);
        StringBuilder problems = new StringBuilder();
        for (Path file : all) {
            World w = World.load(file);
            var b = w.bounds();
            // Does the course dip below z = 0 anywhere? (sampled on the water pass's own grid)
            boolean wet = WaterPass.buildPlane(b, w.terrain()) != null;
            String name = file.getFileName().toString().replace(".json", "");
            Path png = TestCourses.screenshotDir().resolve("course-" + name + ".png");
            float cx = (float) (b.minX() + b.maxX()) / 2, cy = (float) (b.minY() + b.maxY()) / 2;
            OrbitCamera cam = OrbitCamera.topDown(w.course(), w.terrain(), new Vector3f(cx, cy, 0), (float) W / H);
            try (Offscreen off = new Offscreen(W, H, 0);
                 SceneRenderer r = new SceneRenderer(w.course(), w.terrain(), TerrainMesh.ColorMode.GREEN)) {
                off.bind();
                r.render(cam, W, H, 0f);
                int error = glGetError();
                if (error != GL_NO_ERROR) problems.append(name).append(": GL error ").append(error).append('\n');
                off.savePng(png);
            }
            Pixels px = Pixels.read(png);
            int water = 0, grass = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    if (px.isWater(x, y)) water++;
                    if (px.g(x, y) > px.r(x, y) + 30 && px.g(x, y) > px.b(x, y) + 30) grass++;
                }
            }
            if (grass < W * H / 10) problems.append(name).append(": only ").append(grass).append(" grass pixels\n");
            if (wet && water < 50) problems.append(name).append(": has water but ").append(water).append(" water pixels\n");
            if (!wet && water > 0) problems.append(name).append(": dry but ").append(water).append(" water pixels\n");
        }
        assertEquals("", problems.toString());
    }
}
