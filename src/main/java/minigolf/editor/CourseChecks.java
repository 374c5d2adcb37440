package minigolf.editor;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import minigolf.collision.CollisionScene;
import minigolf.course.Vec2;
import minigolf.physics.World;

/**
 * The editor's validation before saving: start and hole inside the bounds, not on a deleted cell,
 * on dry terrain, not covered by an obstacle, and the hole reachable from the start (A* over the
 * grid, {@link Reachability}). Each problem carries the position to mark on the course.
 */
public final class CourseChecks {
    private CourseChecks() {
    }

    public static List<Problem> check(EditableCourse c, World world) {
        List<Problem> problems = new ArrayList<>();
        boolean startOk = place(c, world, world.course().start(), "start", problems);
        boolean holeOk = place(c, world, world.hole().position(), "hole", problems);
        teleports(world, problems);
        if (startOk && holeOk && Reachability.path(c, world) == null) {
            Vec2 h = world.hole().position();
            problems.add(new Problem("hole: no way from the start to the hole (A* on the course grid)", h.x(), h.y()));
        }
        return problems;
    }

    /**
     * The teleports as the loader wants them (docs/course-format.md, "Teleports"): every exit in the
     * bounds, on dry land and outside every entry; the start and the hole outside every entry.
     */
    private static void teleports(World world, List<Problem> problems) {
        List<minigolf.course.Teleport> teleports = world.course().teleports();
        List<Vec2> points = new ArrayList<>(List.of(world.course().start(), world.hole().position()));
        List<String> names = new ArrayList<>(List.of("start", "hole"));
        for (int i = 0; i < teleports.size(); i++) {
            for (int k = 0; k < teleports.get(i).exits().size(); k++) {
                Vec2 p = teleports.get(i).exits().get(k).position();
                points.add(p);
                names.add("teleport " + i + " exit " + k);
                String at = String.format(Locale.ROOT, "(%.2f, %.2f)", p.x(), p.y());
                if (!world.playArea().contains(p.x(), p.y())) {
                    problems.add(new Problem(names.get(names.size() - 1) + ": " + at + " is outside the course", p.x(), p.y()));
                } else if (world.terrain().height(p.x(), p.y()) < 0) {
                    problems.add(new Problem(names.get(names.size() - 1) + ": " + at + " is in water", p.x(), p.y()));
                }
            }
        }
        for (int n = 0; n < points.size(); n++) {
            Vec2 p = points.get(n);
            for (int j = 0; j < teleports.size(); j++) {
                if (teleports.get(j).entry().contains(p.x(), p.y())) {
                    problems.add(new Problem(names.get(n) + String.format(Locale.ROOT, ": (%.2f, %.2f)", p.x(), p.y())
                            + " is inside the entry of teleport " + j, p.x(), p.y()));
                }
            }
        }
    }

    private static boolean place(EditableCourse c, World world, Vec2 p, String what, List<Problem> problems) {
        int before = problems.size();
        String at = String.format(Locale.ROOT, "(%.2f, %.2f)", p.x(), p.y());
        if (!world.bounds().contains(p.x(), p.y())) {
            problems.add(new Problem(what + ": " + at + " is outside the bounds", p.x(), p.y()));
            return false;
        }
        int i = c.cellColumn(p.x()), j = c.cellRow(p.y());
        if (i >= 0 && j >= 0 && c.isDeleted(i, j)) {
            problems.add(new Problem(what + ": " + at + " is on a deleted cell", p.x(), p.y()));
        }
        double h = world.terrain().height(p.x(), p.y());
        if (h < 0) {
            problems.add(new Problem(what + ": " + at + String.format(Locale.ROOT, " is in water (h = %.3f)", h), p.x(), p.y()));
        }
        CollisionScene scene = world.obstacles();
        double r = world.physics().ballRadius();
        if (scene != null && scene.clearance(p.x(), p.y(), h + r) < r) {
            problems.add(new Problem(what + ": " + at + " is covered by an obstacle", p.x(), p.y()));
        }
        return problems.size() == before;
    }
}
