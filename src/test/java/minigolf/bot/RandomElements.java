package minigolf.bot;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import minigolf.course.CourseException;
import minigolf.physics.World;

/**
 * Seeded random courses with the elements of issue 24, for the robustness property test: the
 * random courses of {@link RandomCourses} with, for each kind in a mask, a few elements of that
 * kind (moving obstacles turning, swinging and sliding, bumpers, one-way gates, push zones, magnets,
 * teleports) at random places and with random parameters anywhere in the ranges the loader accepts.
 * Each course goes through the loader; candidates it rejects are drawn again.
 */
final class RandomElements {
    /** The element kinds, bits of a mask. */
    static final String[] KINDS = {"moving", "bumpers", "gates", "pushZones", "magnets", "teleports"};
    private static final ObjectMapper JSON = new ObjectMapper();

    private RandomElements() {
    }

    /** A course the loader accepts with elements of every kind in {@code mask} (bit i: KINDS[i]). */
    static World course(long seed, int mask) {
        SplittableRandom random = new SplittableRandom(seed);
        for (int attempt = 0; attempt < 200; attempt++) {
            try {
                ObjectNode c = (ObjectNode) JSON.readTree(RandomCourses.json(random, attempt));
                add(c, random, mask);
                return World.parse(JSON.writeValueAsString(c), "elements-" + seed + "-" + mask);
            } catch (CourseException e) {
                // A placement the loader refuses (start in water, an exit in an entry): draw again.
            } catch (java.io.IOException e) {
                throw new AssertionError(e);
            }
        }
        throw new IllegalStateException("the loader rejects every course with elements " + mask);
    }

    /** {@code count} courses, each with a random non-empty mix of the kinds. */
    static List<World> mixed(long seed, int count) {
        SplittableRandom random = new SplittableRandom(seed);
        List<World> worlds = new ArrayList<>();
        for (int i = 0; i < count; i++) worlds.add(course(random.nextLong(), 1 + random.nextInt((1 << KINDS.length) - 1)));
        return worlds;
    }

    private static void add(ObjectNode c, SplittableRandom r, int mask) {
        double minX = c.get("bounds").get("min").get(0).asDouble(), minY = c.get("bounds").get("min").get(1).asDouble();
        double maxX = c.get("bounds").get("max").get(0).asDouble(), maxY = c.get("bounds").get("max").get(1).asDouble();
        ArrayNode obstacles = (ArrayNode) c.get("obstacles");
        int n = 1 + r.nextInt(3);
        for (int k = 0; k < n; k++) {
            double x = r.nextDouble(minX, maxX), y = r.nextDouble(minY, maxY);
            if ((mask & 1) != 0) obstacles.add(moving(r, x, y));
            if ((mask & 2) != 0) {
                obstacles.add(JSON.createObjectNode().put("type", "bumper").set("position", point(x, y)));
                ((ObjectNode) obstacles.get(obstacles.size() - 1)).put("radius", pick(r, 0.02, 0.1, 0.5))
                        .put("restitution", pick(r, 0, 0.5, 1, 1.5, 2));
            }
            if ((mask & 4) != 0) {
                ObjectNode gate = JSON.createObjectNode().put("type", "gate");
                gate.set("from", point(x, y));
                gate.set("to", point(x + r.nextDouble(-3, 3), y + r.nextDouble(-3, 3) + 0.01));
                gate.put("height", pick(r, 0.05, 0.3, 2)).put("passTo", r.nextBoolean() ? "left" : "right")
                        .put("restitution", pick(r, 0, 0.7, 1.8));
                obstacles.add(gate);
            }
        }
        if ((mask & 8) != 0) {
            ArrayNode pushes = c.putArray("pushZones");
            for (int k = 0; k < n; k++) {
                ObjectNode z = pushes.addObject();
                z.set("shape", shape(r, minX, minY, maxX, maxY));
                z.set("push", point(r.nextDouble(-1, 1) * pick(r, 0.1, 1, 5, 50) / Math.sqrt(2),
                        r.nextDouble(-1, 1) * pick(r, 0.1, 1, 5, 50) / Math.sqrt(2)));
            }
        }
        if ((mask & 16) != 0) {
            ArrayNode magnets = c.putArray("magnets");
            for (int k = 0; k < n; k++) {
                ObjectNode m = magnets.addObject();
                m.set("position", point(r.nextDouble(minX, maxX), r.nextDouble(minY, maxY)));
                m.put("radius", pick(r, 0.05, 0.5, 3)).put("strength", pick(r, -50, -3, -0.5, 0.5, 3, 50));
            }
        }
        if ((mask & 32) != 0) {
            ArrayNode teleports = c.putArray("teleports");
            for (int k = 0; k < n; k++) {
                ObjectNode t = teleports.addObject();
                t.set("entry", shape(r, minX, minY, maxX, maxY));
                ArrayNode exits = t.putArray("exits");
                int count = 1 + r.nextInt(3);
                for (int e = 0; e < count; e++) {
                    ObjectNode exit = exits.addObject();
                    exit.set("position", point(r.nextDouble(minX, maxX), r.nextDouble(minY, maxY)));
                    if (r.nextBoolean()) exit.put("directionDeg", r.nextDouble(-360, 360));
                }
            }
        }
    }

    private static ObjectNode moving(SplittableRandom r, double x, double y) {
        ObjectNode o = JSON.createObjectNode();
        double size = pick(r, 0.05, 0.5, 2);
        switch (r.nextInt(3)) {
            case 0 -> {
                o.put("type", "box");
                o.set("min", JSON.createArrayNode().add(x - size).add(y - 0.03).add(-1.0));
                o.set("max", JSON.createArrayNode().add(x + size).add(y + 0.03).add(pick(r, 0.05, 0.3, 2)));
            }
            case 1 -> {
                o.put("type", "wall");
                o.set("from", point(x - size, y));
                o.set("to", point(x + size, y));
                o.put("thickness", pick(r, 0, 0.02, 0.1)).put("height", pick(r, 0.05, 0.5));
            }
            default -> {
                o.put("type", r.nextBoolean() ? "tree" : "bumper");
                o.set("position", point(x, y));
                o.put("radius", pick(r, 0.03, 0.2)).put("height", pick(r, 0.1, 1));
            }
        }
        o.put("restitution", pick(r, 0, 0.7, 1, 2));
        ObjectNode m = o.putObject("motion");
        double period = pick(r, 0.2, 0.5, 2, 10);
        switch (r.nextInt(3)) {
            case 0 -> {
                m.put("type", "rotate");
                m.set("pivot", JSON.createArrayNode().add(x + r.nextDouble(-size, size)).add(y).add(pick(r, 0, 0.3, 1)));
                m.set("axis", JSON.createArrayNode().add(pick(r, 0, 1)).add(pick(r, 0, 0.5)).add(pick(r, 1, -1, 0.2)));
            }
            case 1 -> {
                m.put("type", "swing");
                m.set("pivot", JSON.createArrayNode().add(x).add(y).add(pick(r, 0.5, 2)));
                m.set("axis", JSON.createArrayNode().add(1).add(pick(r, 0, 1)).add(0));
                m.put("amplitudeDeg", pick(r, 5, 45, 180));
            }
            default -> {
                m.put("type", "slide");
                ArrayNode path = m.putArray("path");
                path.add(JSON.createArrayNode().add(0).add(0).add(0));
                double reach = Math.min(3, 20 * period / 4);
                for (int i = 0; i < 1 + r.nextInt(3); i++) {
                    path.add(JSON.createArrayNode().add(r.nextDouble(-reach, reach)).add(r.nextDouble(-reach, reach)).add(0));
                }
                m.put("closed", r.nextBoolean());
            }
        }
        m.put("period", period).put("phase", r.nextDouble(0, 10));
        return o;
    }

    private static ObjectNode shape(SplittableRandom r, double minX, double minY, double maxX, double maxY) {
        ObjectNode s = JSON.createObjectNode();
        double x = r.nextDouble(minX, maxX), y = r.nextDouble(minY, maxY);
        if (r.nextBoolean()) {
            s.put("type", "circle");
            s.set("center", point(x, y));
            s.put("radius", pick(r, 0.05, 0.3, 2));
        } else {
            s.put("type", "rect");
            s.set("min", point(x, y));
            s.set("max", point(x + pick(r, 0.1, 1, 4), y + pick(r, 0.1, 1, 4)));
        }
        return s;
    }

    private static ArrayNode point(double x, double y) {
        return JSON.createArrayNode().add(x).add(y);
    }

    private static double pick(SplittableRandom r, double... values) {
        return values[r.nextInt(values.length)];
    }
}
