package minigolf.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import minigolf.physics.World;
import minigolf.render.Offscreen;
import minigolf.render.OrbitCamera;
import minigolf.render.SceneRenderer;
import minigolf.render.TerrainMesh;
import org.joml.Vector3f;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

@Command(name = "render", description = "Renders a still of a course off-screen, saves it as PNG and exits.")
final class RenderCommand implements Callable<Integer> {
    enum View { orbit, top, overview }

    @Parameters(index = "0", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--out", required = true, paramLabel = "FILE.png", description = "Where to save the picture.")
    Path out;

    @Option(names = "--size", paramLabel = "WxH", description = "Picture size in pixels (default: ${DEFAULT-VALUE}).")
    String size = "1280x720";

    @Option(names = "--view", paramLabel = "VIEW",
            description = "orbit: behind the ball towards the hole; top: from above; overview: from further back and to the"
                    + " side, lower, so the course's world and skyline show (default: ${DEFAULT-VALUE}).")
    View view = View.orbit;

    @Option(names = "--height-map", description = "Colour the terrain by altitude (default: off).")
    boolean heightMap;

    @Option(names = "--no-reflections", description = "Plain water colours instead of reflection and refraction (default: off).")
    boolean noReflections;

    @Option(names = "--quality", paramLabel = "Q",
            description = "high (real GPUs: 4x multisampling, water images) or software (what llvmpipe gets) (default: ${DEFAULT-VALUE}).")
    String quality = "high";

    @Option(names = "--minimap", description = "Draw the minimap in the top-right corner, as the game does (default: off).")
    boolean minimap;

    @Override
    public Integer call() {
        ImageSize s = ImageSize.parse("--size", size);
        if (!out.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".png")) {
            throw new UserError("--out: the file name must end in .png, got '" + out + "'");
        }
        if (Files.isDirectory(out)) throw new UserError("--out: '" + out + "' is a directory");
        minigolf.render.RenderQuality q = minigolf.render.RenderQuality.named(quality);
        if (q == null) throw new UserError("--quality: must be high or software, got '" + quality + "'");
        World world = CourseArgument.load(course);
        float aspect = (float) s.width() / s.height();
        try (Offscreen off = new Offscreen(s.width(), s.height(), q.samples());
             SceneRenderer renderer = new SceneRenderer(world.course(), world.terrain(),
                     heightMap ? TerrainMesh.ColorMode.HEIGHT_MAP : TerrainMesh.ColorMode.GREEN, q)) {
            renderer.setCourseFolder(course.toAbsolutePath().getParent());
            renderer.setWaterReflections(!noReflections);
            OrbitCamera camera = camera(world, aspect);
            off.bind();
            renderer.render(camera, s.width(), s.height(), 0f);
            if (minimap) {
                int side = Math.min(s.width(), s.height()) / 4;
                renderer.renderMinimap(s.width() - side - side / 12, side / 12, side, s.width(), s.height());
            }
            off.savePng(out);
        }
        return 0;
    }

    private OrbitCamera camera(World world, float aspect) {
        if (view == View.top) {
            var b = world.bounds();
            float cx = (float) (b.minX() + b.maxX()) / 2, cy = (float) (b.minY() + b.maxY()) / 2;
            return OrbitCamera.topDown(world.course(), world.terrain(),
                    new Vector3f(cx, cy, (float) Math.max(0, world.terrain().height(cx, cy))), aspect);
        }
        OrbitCamera cam = OrbitCamera.behindBall(world.course(), world.terrain(), aspect);
        if (view == View.overview) {
            cam.rotate(0.5f, -0.18f); // round to the side and lower: the horizon comes into the picture
            cam.zoom(-4);
        }
        return cam;
    }
}
