package minigolf.bot;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import minigolf.course.CourseException;
import minigolf.physics.World;

/**
 * Seeded tile-style courses, like those of classic online minigolf games, for measuring the
 * planner on courses it was not tuned on: a grid of square tiles joined into a maze (randomised
 * depth-first search, then a few extra openings so that there are several routes), walls on the
 * tiles' edges (some with a narrow gap a little wider than the ball), diagonal walls across some
 * corners, ponds in some dead ends, sand patches, gentle hills and a rim of walls round the course.
 * The start is in the first column, the hole in the last. Each course goes through the loader.
 */
public final class TileCourses {
    static final double TILE = 1.6;
    static final int COLS = 6, ROWS = 4;
    private static final double SPACING = 0.2;

    private TileCourses() {
    }

    /** {@code count} courses from {@code seed} (course i depends on the seed and i only). */
    public static List<World> generate(long seed, int count) {
        List<World> worlds = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            String json = json(seed, i);
            try {
                worlds.add(World.parse(json, "tile-" + seed + "-" + i));
            } catch (CourseException e) {
                throw new IllegalStateException("the generator wrote a course the loader refuses: " + e.getMessage(), e);
            }
        }
        return worlds;
    }

    /** Course {@code index} of {@code seed}: its file's JSON. */
    static String json(long seed, int index) {
        SplittableRandom seeds = new SplittableRandom(seed);
        long courseSeed = 0;
        for (int i = 0; i <= index; i++) courseSeed = seeds.nextLong();
        return json(new SplittableRandom(courseSeed), "tile " + seed + "-" + index);
    }

    static String json(SplittableRandom r, String name) {
        int n = COLS * ROWS;
        // Maze over tiles: open[a][b] when tiles a and b are joined.
        boolean[][] open = new boolean[n][n];
        boolean[] seen = new boolean[n];
        int startTile = r.nextInt(ROWS) * COLS, holeTile = r.nextInt(ROWS) * COLS + COLS - 1;
        List<Integer> stack = new ArrayList<>(List.of(startTile));
        seen[startTile] = true;
        while (!stack.isEmpty()) {
            int t = stack.get(stack.size() - 1);
            List<Integer> next = new ArrayList<>();
            for (int nb : neighbours(t)) if (!seen[nb]) next.add(nb);
            if (next.isEmpty()) {
                stack.remove(stack.size() - 1);
                continue;
            }
            int nb = next.get(r.nextInt(next.size()));
            open[t][nb] = open[nb][t] = true;
            seen[nb] = true;
            stack.add(nb);
        }
        // A few extra openings: loops, so there is more than one way.
        for (int k = 0; k < 3 + r.nextInt(4); k++) {
            int t = r.nextInt(n);
            List<Integer> nbs = neighbours(t);
            int nb = nbs.get(r.nextInt(nbs.size()));
            open[t][nb] = open[nb][t] = true;
        }
        List<String> obstacles = new ArrayList<>();
        double w = COLS * TILE, h = ROWS * TILE;
        // The rim.
        obstacles.add(wall(0, 0, w, 0));
        obstacles.add(wall(w, 0, w, h));
        obstacles.add(wall(w, h, 0, h));
        obstacles.add(wall(0, h, 0, 0));
        // Walls between tiles that are not joined; some with a narrow gap in the middle.
        for (int t = 0; t < n; t++) {
            int c = t % COLS, row = t / COLS;
            if (c + 1 < COLS && !open[t][t + 1]) edge(obstacles, r, (c + 1) * TILE, row * TILE, (c + 1) * TILE, (row + 1) * TILE);
            if (row + 1 < ROWS && !open[t][t + COLS]) edge(obstacles, r, c * TILE, (row + 1) * TILE, (c + 1) * TILE, (row + 1) * TILE);
        }
        // Diagonal walls across the outer corner of some tiles where the way turns (a bank to play off).
        List<Integer> deadEnds = new ArrayList<>();
        for (int t = 0; t < n; t++) {
            List<Integer> joined = new ArrayList<>();
            for (int nb : neighbours(t)) if (open[t][nb]) joined.add(nb);
            if (joined.size() == 1 && t != startTile && t != holeTile) deadEnds.add(t);
            if (joined.size() == 2 && t != startTile && t != holeTile && r.nextInt(3) == 0) {
                int a = joined.get(0) - t, b = joined.get(1) - t;
                boolean horizontalA = Math.abs(a) == 1, horizontalB = Math.abs(b) == 1;
                if (horizontalA != horizontalB) {
                    // The corner opposite both openings is cut.
                    int dx = horizontalA ? -Integer.signum(a) : -Integer.signum(b);
                    int dy = horizontalA ? -Integer.signum(b) : -Integer.signum(a);
                    double cx = (t % COLS + 0.5) * TILE, cy = (t / COLS + 0.5) * TILE, q = 0.5 * TILE;
                    obstacles.add(wall(cx + dx * q, cy + dy * 0.15 * TILE, cx + dx * 0.15 * TILE, cy + dy * q));
                }
            }
        }
        // Ponds in some dead ends, sand on some tiles, hills.
        boolean[] pond = new boolean[n];
        for (int t : deadEnds) if (r.nextInt(2) == 0) pond[t] = true;
        List<String> zones = new ArrayList<>();
        for (int t = 0; t < n; t++) {
            if (t == startTile || t == holeTile || pond[t] || r.nextInt(5) != 0) continue;
            double x0 = (t % COLS) * TILE + 0.2, y0 = (t / COLS) * TILE + 0.2;
            zones.add(String.format(Locale.ROOT, "{\"shape\":{\"type\":\"rect\",\"min\":[%.3f,%.3f],\"max\":[%.3f,%.3f]},"
                    + "\"kineticFriction\":%.2f,\"staticFriction\":0.9}", x0, y0, x0 + TILE - 0.4, y0 + TILE - 0.4,
                    0.3 + 0.4 * r.nextDouble()));
        }
        int hills = r.nextInt(4);
        double[][] bumps = new double[hills][];
        for (int k = 0; k < hills; k++) {
            bumps[k] = new double[] {r.nextDouble(0, w), r.nextDouble(0, h), r.nextDouble(-0.12, 0.15), r.nextDouble(0.5, 1.5)};
        }
        int gx = (int) Math.round(w / SPACING) + 1, gy = (int) Math.round(h / SPACING) + 1;
        StringBuilder heights = new StringBuilder("[");
        for (int j = 0; j < gy; j++) {
            heights.append(j > 0 ? ",[" : "[");
            for (int i = 0; i < gx; i++) {
                double x = i * SPACING, y = j * SPACING, z = 0.3;
                for (double[] b : bumps) z += b[2] * Math.exp(-((x - b[0]) * (x - b[0]) + (y - b[1]) * (y - b[1])) / (b[3] * b[3]));
                int t = Math.min((int) (y / TILE), ROWS - 1) * COLS + Math.min((int) (x / TILE), COLS - 1);
                double fx = x / TILE - Math.floor(x / TILE), fy = y / TILE - Math.floor(y / TILE);
                if (pond[t] && fx > 0.2 && fx < 0.8 && fy > 0.2 && fy < 0.8) z = -0.2;
                heights.append(i > 0 ? "," : "").append(String.format(Locale.ROOT, "%.4f", z));
            }
            heights.append(']');
        }
        heights.append(']');
        double sx = (startTile % COLS + 0.5) * TILE, sy = (startTile / COLS + 0.5) * TILE;
        double hx = (holeTile % COLS + 0.5) * TILE, hy = (holeTile / COLS + 0.5) * TILE;
        return String.format(Locale.ROOT, "{\"format\":1,\"name\":\"%s\",\"terrain\":{\"grid\":{\"origin\":[0,0],\"spacing\":%s,"
                + "\"heights\":%s}},\"bounds\":{\"min\":[-0.2,-0.2],\"max\":[%.3f,%.3f]},\"physics\":{\"kineticFriction\":0.1,"
                + "\"staticFriction\":0.2,\"maxSpeed\":5},\"start\":[%.3f,%.3f],\"hole\":{\"position\":[%.3f,%.3f],\"radius\":0.1,"
                + "\"rule\":\"rest\"},\"zones\":[%s],\"obstacles\":[%s]}", name, SPACING, heights, w + 0.2, h + 0.2, sx, sy, hx, hy,
                String.join(",", zones), String.join(",", obstacles));
    }

    private static List<Integer> neighbours(int t) {
        int c = t % COLS, row = t / COLS;
        List<Integer> list = new ArrayList<>();
        if (c > 0) list.add(t - 1);
        if (c + 1 < COLS) list.add(t + 1);
        if (row > 0) list.add(t - COLS);
        if (row + 1 < ROWS) list.add(t + COLS);
        return list;
    }

    /** A wall along a tile edge; one in five has a gap of 0.12-0.25 m in the middle. */
    private static void edge(List<String> obstacles, SplittableRandom r, double x0, double y0, double x1, double y1) {
        if (r.nextInt(5) != 0) {
            obstacles.add(wall(x0, y0, x1, y1));
            return;
        }
        double gap = r.nextDouble(0.12, 0.25), mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
        double ux = (x1 - x0) / TILE, uy = (y1 - y0) / TILE;
        obstacles.add(wall(x0, y0, mx - ux * gap / 2, my - uy * gap / 2));
        obstacles.add(wall(mx + ux * gap / 2, my + uy * gap / 2, x1, y1));
    }

    private static String wall(double x0, double y0, double x1, double y1) {
        return String.format(Locale.ROOT, "{\"type\":\"wall\",\"from\":[%.3f,%.3f],\"to\":[%.3f,%.3f],\"thickness\":0.08,"
                + "\"height\":0.15,\"restitution\":0.7}", x0, y0, x1, y1);
    }
}
