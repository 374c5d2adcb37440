package minigolf.bot;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import minigolf.course.CourseException;
import minigolf.physics.World;

/**
 * Seeded random courses for property tests: anything the loader accepts, weighted towards the
 * cases that break bots (a hole walled in or ringed by water, no friction or a huge one, a tiny
 * maximum speed, a ball too big for the gaps, deleted cells, steep grids). Each course is written
 * as JSON and goes through the loader ({@link World#parse}), so what is tested is exactly what a
 * course file can hold; candidates the loader rejects (start or hole in water) are redrawn.
 */
final class RandomCourses {
    private RandomCourses() {
    }

    /** {@code count} courses the loader accepts, from {@code seed}. */
    static List<World> generate(long seed, int count) {
        SplittableRandom random = new SplittableRandom(seed);
        List<World> worlds = new ArrayList<>();
        int attempts = 0;
        while (worlds.size() < count) {
            if (++attempts > 50 * count) throw new IllegalStateException("the loader rejects almost every course");
            String json = json(random, worlds.size());
            try {
                worlds.add(World.parse(json, "random-" + seed + "-" + worlds.size()));
            } catch (CourseException e) {
                // Start or hole in water, or another placement the loader refuses: draw again.
            }
        }
        return worlds;
    }

    static String json(SplittableRandom r, int index) {
        double width = pick(r, 1.0, 3, 8, 14, 30), depth = pick(r, 1.0, 2, 6, 10, 20);
        double minX = round(r.nextDouble(-10, 10)), minY = round(r.nextDouble(-10, 10));
        double maxX = minX + width, maxY = minY + depth;
        double sx = round(r.nextDouble(minX + 0.05 * width, minX + 0.45 * width));
        double sy = round(r.nextDouble(minY + 0.1 * depth, maxY - 0.1 * depth));
        double hx = round(r.nextDouble(minX + 0.55 * width, maxX - 0.05 * width));
        double hy = round(r.nextDouble(minY + 0.1 * depth, maxY - 0.1 * depth));
        double holeRadius = pick(r, 0.01, 0.05, 0.1, 0.15, 0.5);
        double ballRadius = pick(r, 0.02135, 0.02135, 0.02135, 0.005, 0.3, 1.0);
        StringBuilder b = new StringBuilder();
        b.append("{\"format\":1,\"name\":\"random ").append(index).append("\",");
        b.append("\"terrain\":").append(terrain(r, minX, minY, maxX, maxY, hx, hy)).append(',');
        b.append("\"bounds\":{\"min\":[").append(num(minX)).append(',').append(num(minY)).append("],\"max\":[")
                .append(num(maxX)).append(',').append(num(maxY)).append("]},");
        double muK = pick(r, 0, 1e-4, 0.06, 0.1, 0.15, 0.5, 5, 50);
        double muS = pick(r, 0, 0.1, 0.2, 0.3, 1, 60);
        double maxSpeed = pick(r, 1e-3, 0.05, 1, 3, 5, 5, 8, 50);
        b.append("\"physics\":{\"kineticFriction\":").append(num(muK)).append(",\"staticFriction\":").append(num(muS))
                .append(",\"maxSpeed\":").append(num(maxSpeed)).append(",\"model\":\"")
                .append(r.nextInt(4) == 0 ? "complete" : "classic").append("\",\"ballRadius\":").append(num(ballRadius))
                .append(r.nextInt(5) == 0 ? ",\"gravity\":" + num(pick(r, 0.5, 1.62, 30)) : "").append("},");
        b.append("\"start\":[").append(num(sx)).append(',').append(num(sy)).append("],");
        b.append("\"hole\":{\"position\":[").append(num(hx)).append(',').append(num(hy)).append("],\"radius\":")
                .append(num(holeRadius)).append(",\"rule\":\"").append(r.nextInt(3) == 0 ? "capture" : "rest").append("\"},");
        b.append("\"zones\":[");
        int zones = r.nextInt(4);
        for (int z = 0; z < zones; z++) {
            if (z > 0) b.append(',');
            double cx = r.nextDouble(minX, maxX), cy = r.nextDouble(minY, maxY);
            String shape = r.nextBoolean()
                    ? "{\"type\":\"circle\",\"center\":[" + num(cx) + "," + num(cy) + "],\"radius\":" + num(pick(r, 0.2, 1, 3)) + "}"
                    : "{\"type\":\"rect\",\"min\":[" + num(cx) + "," + num(cy) + "],\"max\":[" + num(cx + pick(r, 0.3, 2, 6))
                    + "," + num(cy + pick(r, 0.3, 2, 6)) + "]}";
            b.append("{\"shape\":").append(shape).append(",\"kineticFriction\":").append(num(pick(r, 0, 0.3, 0.8, 20)))
                    .append(",\"staticFriction\":").append(num(pick(r, 0, 0.5, 1))).append('}');
        }
        b.append("],\"obstacles\":[");
        List<String> obstacles = new ArrayList<>();
        if (r.nextInt(4) == 0) {
            // The hole walled in on all four sides (sometimes with a gap narrower than the ball).
            double s = pick(r, 0.3, 0.8, 1.5), gap = r.nextBoolean() ? 0 : 0.03;
            obstacles.add(wall(hx - s, hy - s, hx + s, hy - s));
            obstacles.add(wall(hx + s, hy - s, hx + s, hy + s));
            obstacles.add(wall(hx + s, hy + s, hx - s + gap, hy + s));
            obstacles.add(wall(hx - s, hy + s, hx - s, hy - s));
        }
        int more = r.nextInt(7);
        for (int k = 0; k < more; k++) {
            double x = r.nextDouble(minX, maxX), y = r.nextDouble(minY, maxY);
            switch (r.nextInt(3)) {
                case 0 -> obstacles.add(wall(x, y, x + r.nextDouble(-4, 4), y + r.nextDouble(-4, 4)));
                case 1 -> obstacles.add("{\"type\":\"tree\",\"position\":[" + num(x) + "," + num(y) + "],\"radius\":"
                        + num(pick(r, 0.05, 0.2, 0.6)) + ",\"height\":1}");
                default -> obstacles.add("{\"type\":\"box\",\"min\":[" + num(x) + "," + num(y) + ",-2],\"max\":["
                        + num(x + pick(r, 0.1, 0.5, 2)) + "," + num(y + pick(r, 0.1, 0.5, 2)) + "," + num(pick(r, 0.01, 3))
                        + "],\"rotationDeg\":" + num(r.nextDouble(0, 90)) + "}");
            }
        }
        b.append(String.join(",", obstacles)).append("]}");
        return b.toString();
    }

    private static String terrain(SplittableRandom r, double minX, double minY, double maxX, double maxY,
                                  double hx, double hy) {
        switch (r.nextInt(7)) {
            case 0:
                return "{\"height\":\"0\"}";
            case 1:
                return "{\"height\":\"" + num(r.nextDouble(-0.3, 0.3)) + "*x+" + num(r.nextDouble(-0.3, 0.3)) + "*y+"
                        + num(r.nextDouble(0, 5)) + "\"}";
            case 2: {
                // A ring of water round the hole: unreachable along the ground.
                double ring = pick(r, 0.3, 0.8, 1.5);
                return String.format(Locale.ROOT,
                        "{\"height\":\"0.2-0.5*exp(-((sqrt((x-(%s))^2+(y-(%s))^2)-%s)^2)/%s)\"}",
                        num(hx), num(hy), num(ring), num(pick(r, 0.005, 0.02, 0.1)));
            }
            case 3:
                return "{\"height\":\"" + num(r.nextDouble(0.05, 1)) + "+" + num(pick(r, 0.05, 0.3, 2)) + "*sin("
                        + num(r.nextDouble(0.2, 3)) + "*x)*cos(" + num(r.nextDouble(0.2, 3)) + "*y)\"}";
            case 4:
                // A bowl or a mountain in the middle.
                return "{\"height\":\"" + num(r.nextDouble(0.1, 1)) + "+" + num(r.nextDouble(-2, 2)) + "*exp(-((x-("
                        + num((minX + maxX) / 2) + "))^2+(y-(" + num((minY + maxY) / 2) + "))^2)/" + num(pick(r, 0.5, 4, 20)) + ")\"}";
            default:
                return grid(r, minX, minY, maxX, maxY);
        }
    }

    private static String grid(SplittableRandom r, double minX, double minY, double maxX, double maxY) {
        int cols = 2 + r.nextInt(10), rows = 2 + r.nextInt(10);
        double spacing = Math.max((maxX - minX) / (cols - 1), (maxY - minY) / (rows - 1));
        double amplitude = pick(r, 0.01, 0.3, 3);
        StringBuilder h = new StringBuilder("[");
        StringBuilder k = new StringBuilder("[");
        StringBuilder s = new StringBuilder("[");
        for (int j = 0; j < rows; j++) {
            h.append(j > 0 ? ",[" : "[");
            k.append(j > 0 ? ",[" : "[");
            s.append(j > 0 ? ",[" : "[");
            for (int i = 0; i < cols; i++) {
                String sep = i > 0 ? "," : "";
                // Mostly dry; now and then a node under water.
                h.append(sep).append(num(r.nextInt(6) == 0 ? -0.2 : 0.2 + amplitude * r.nextDouble()));
                k.append(sep).append(num(pick(r, 0, 0.1, 0.1, 0.6)));
                s.append(sep).append(num(pick(r, 0.2, 0.2, 1)));
            }
            h.append(']');
            k.append(']');
            s.append(']');
        }
        h.append(']');
        k.append(']');
        s.append(']');
        StringBuilder deleted = new StringBuilder();
        if (r.nextBoolean() && cols > 2 && rows > 2) {
            deleted.append(",\"deletedCells\":[[").append(r.nextInt(cols - 1)).append(',').append(r.nextInt(rows - 1)).append("]]");
        }
        return "{\"grid\":{\"origin\":[" + num(minX) + "," + num(minY) + "],\"spacing\":" + num(spacing)
                + ",\"heights\":" + h + (r.nextBoolean() ? ",\"kineticFriction\":" + k + ",\"staticFriction\":" + s : "")
                + deleted + "}}";
    }

    private static String wall(double x0, double y0, double x1, double y1) {
        return "{\"type\":\"wall\",\"from\":[" + num(x0) + "," + num(y0) + "],\"to\":[" + num(x1) + "," + num(y1)
                + "],\"thickness\":0.1,\"height\":0.3}";
    }

    private static double pick(SplittableRandom r, double... values) {
        return values[r.nextInt(values.length)];
    }

    private static double round(double v) {
        return Math.round(v * 100) / 100.0;
    }

    private static String num(double v) {
        return Double.toString(v);
    }
}
