package minigolf.classic;

import java.util.ArrayList;
import java.util.List;
import minigolf.course.Magnet;
import minigolf.course.Obstacle;
import minigolf.course.PushZone;
import minigolf.course.Shape;
import minigolf.course.Teleport;
import minigolf.course.Vec2;

/**
 * A classic track's special blocks as our course elements (docs/classic-tracks.md, "Special
 * blocks"): downhill tiles as push zones, magnets and repellers as magnets, teleport starts and
 * exits as seeded teleports, one-way blocks as one-way gates on the faces they close. Plain Java.
 */
final class ClassicElements {
    /** The points the original tests round the ball's centre (px): 6 px out, the diagonals rounded to 4. */
    static final int[][] PROBES = {{0, -6}, {4, -4}, {6, 0}, {4, 4}, {0, 6}, {-4, 4}, {-6, 0}, {-4, -4}};
    /** Push directions of the downhill elements 4..11 (N, NE, ..., NW) in course coordinates (+y is north). */
    private static final double D = Math.sqrt(0.5);
    private static final double[][] DOWNHILL = {{0, 1}, {D, D}, {1, 0}, {D, -D}, {0, -1}, {-D, -D}, {-1, 0}, {-D, D}};
    /** The one-way blocks 20..23 let the ball through going N, E, S, W: that face's outward step in pixels. */
    private static final int[][] ONE_WAY = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    static final double ONE_WAY_RESTITUTION = 0.82;
    private static final String[] COLOURS = {"blue", "red", "yellow", "green"};

    final List<PushZone> pushZones = new ArrayList<>();
    final List<Magnet> magnets = new ArrayList<>();
    final List<Teleport> teleports = new ArrayList<>();
    final List<Obstacle> gates = new ArrayList<>();
    final List<String> notes = new ArrayList<>();

    private final ClassicTrack track;
    private final PixelMap map;
    private final ClassicScale scale;

    private ClassicElements(ClassicTrack track, PixelMap map, ClassicScale scale) {
        this.track = track;
        this.map = map;
        this.scale = scale;
    }

    /** The elements of the track; {@code avoid} are points no teleport entry may hold (the start, the holes). */
    static ClassicElements of(ClassicTrack track, PixelMap map, ClassicScale scale, double wallTop, List<Vec2> avoid) {
        ClassicElements e = new ClassicElements(track, map, scale);
        e.downhill();
        e.magnets();
        e.teleports(avoid);
        e.oneWay(wallTop);
        return e;
    }

    private Shape.Cells cells(boolean[] set) {
        return new Shape.Cells(new Vec2(0, 0), scale.pixel(), PixelMap.WIDTH, PixelMap.HEIGHT, spans(set));
    }

    private void downhill() {
        double push = scale.downhillPush();
        for (int d = 0; d < DOWNHILL.length; d++) {
            Shape.Cells zone = cells(map.where(PixelMap.DOWNHILL_N + d));
            if (zone.spanCount() > 0) pushZones.add(new PushZone(zone, new Vec2(push * DOWNHILL[d][0], push * DOWNHILL[d][1])));
        }
    }

    private void magnets() {
        double radius = ClassicScale.MAGNET_PIXELS * scale.pixel(), strength = scale.magnetStrength();
        for (int ty = 0; ty < TileMap.HEIGHT; ty++) {
            for (int tx = 0; tx < TileMap.WIDTH; tx++) {
                int s = special(tx, ty);
                if (s == PixelMap.MAGNET) magnets.add(new Magnet(centre(tx, ty), radius, strength));
                if (s == PixelMap.REPELLER) magnets.add(new Magnet(centre(tx, ty), radius, -strength));
            }
        }
    }

    /**
     * One teleport per colour whose starts are on the map: its entry every place of the ball's
     * centre where one of the original's probes touches a start of that colour; its exits that
     * colour's exits, else (as the original) every exit of any colour. A colour whose starts lead
     * only to its other starts, an exit inside an entry, or an entry over the start or the hole is
     * left out (the notes say so): our teleports cannot send a ball into another entry.
     */
    private void teleports(List<Vec2> avoid) {
        List<List<Vec2>> exits = new ArrayList<>();
        int[] starts = new int[4];
        for (int c = 0; c < 4; c++) exits.add(new ArrayList<>());
        for (int ty = 0; ty < TileMap.HEIGHT; ty++) {
            for (int tx = 0; tx < TileMap.WIDTH; tx++) {
                int s = special(tx, ty);
                if (s >= PixelMap.TELEPORT_BLUE && s <= PixelMap.TELEPORT_GREEN + 1) {
                    int c = (s - PixelMap.TELEPORT_BLUE) / 2;
                    if ((s - PixelMap.TELEPORT_BLUE) % 2 == 0) starts[c]++; else exits.get(c).add(centre(tx, ty));
                }
            }
        }
        List<Vec2> anyExit = new ArrayList<>();
        for (List<Vec2> e : exits) anyExit.addAll(e);
        List<Shape.Cells> entries = new ArrayList<>();
        List<List<Vec2>> targets = new ArrayList<>();
        List<Integer> colours = new ArrayList<>();
        for (int c = 0; c < 4; c++) {
            if (starts[c] == 0) continue;
            List<Vec2> to = !exits.get(c).isEmpty() ? exits.get(c) : starts[c] >= 2 ? List.of() : anyExit;
            if (to.isEmpty()) {
                notes.add("teleports: the " + COLOURS[c] + " starts lead " + (starts[c] >= 2 ? "to each other" : "nowhere")
                        + "; not played");
                continue;
            }
            entries.add(entry(PixelMap.TELEPORT_BLUE + 2 * c));
            targets.add(to);
            colours.add(c);
        }
        for (int k = 0; k < entries.size(); k++) {
            Shape.Cells entry = entries.get(k);
            String colour = COLOURS[colours.get(k)];
            if (avoid.stream().anyMatch(p -> entry.contains(p.x(), p.y()))) {
                notes.add("teleports: the " + colour + " start touches the start or the hole; not played");
                continue;
            }
            List<Teleport.Exit> out = new ArrayList<>();
            for (Vec2 p : targets.get(k)) {
                if (entries.stream().noneMatch(e -> e.contains(p.x(), p.y()))) out.add(new Teleport.Exit(p, null));
            }
            if (out.size() < targets.get(k).size()) notes.add("teleports: an exit of the " + colour + " starts lies in an entry; left out");
            if (out.size() > minigolf.course.Limits.TELEPORT_EXITS) {
                out = out.subList(0, minigolf.course.Limits.TELEPORT_EXITS);
                notes.add("teleports: the " + colour + " starts keep their first " + out.size() + " exits");
            }
            if (out.isEmpty()) continue;
            // The draw's seed: the track and the colour, so that every import of a track draws alike.
            long seed = 4L * (track.author() + "/" + track.name()).hashCode() + colours.get(k);
            teleports.add(new Teleport(entry, out, seed));
        }
    }

    /** Every pixel at which a ball's centre has one of its probes on a pixel of {@code value}. */
    private Shape.Cells entry(int value) {
        boolean[] set = new boolean[PixelMap.WIDTH * PixelMap.HEIGHT];
        for (int y = 0; y < PixelMap.HEIGHT; y++) {
            for (int x = 0; x < PixelMap.WIDTH; x++) {
                if (map.at(x, y) != value) continue;
                for (int[] p : PROBES) {
                    int cx = x - p[0], cy = y - p[1];
                    if (cx >= 0 && cy >= 0 && cx < PixelMap.WIDTH && cy < PixelMap.HEIGHT) set[cx + PixelMap.WIDTH * cy] = true;
                }
            }
        }
        return cells(set);
    }

    /**
     * A one-way block lets the ball through in its direction and stops it coming back: a gate on
     * each face of its pixels that looks the way it lets the ball go (the face a returning ball
     * meets), merged along runs of pixels, except where a wall lies beyond.
     */
    private void oneWay(double top) {
        double px = scale.pixel();
        for (int d = 0; d < ONE_WAY.length; d++) {
            int value = PixelMap.ONE_WAY_N + d, ox = ONE_WAY[d][0], oy = ONE_WAY[d][1];
            boolean horizontal = oy != 0;
            int lines = horizontal ? PixelMap.HEIGHT : PixelMap.WIDTH, along = horizontal ? PixelMap.WIDTH : PixelMap.HEIGHT;
            for (int l = 0; l < lines; l++) {
                for (int a = 0; a < along; ) {
                    if (!face(horizontal ? a : l, horizontal ? l : a, value, ox, oy)) {
                        a++;
                        continue;
                    }
                    int start = a;
                    while (a < along && face(horizontal ? a : l, horizontal ? l : a, value, ox, oy)) a++;
                    gates.add(gate(horizontal, l, start, a, ox, oy, px, top));
                }
            }
        }
    }

    private boolean face(int x, int y, int value, int ox, int oy) {
        if (map.at(x, y) != value) return false;
        int beyond = map.at(x + ox, y + oy);
        return beyond != value && !PixelMap.solid(beyond);
    }

    /**
     * The gate on the faces of pixels start..end-1 of line l, facing (ox, oy) in pixels (y down);
     * the ball passes to that side (the left of from→to).
     */
    private static Obstacle.Gate gate(boolean horizontal, int l, int start, int end, int ox, int oy, double px, double top) {
        double h = PixelMap.HEIGHT;
        Vec2 a, b;
        if (horizontal) {
            // The north (oy -1) or south face of row l, in course y (north up).
            double y = (oy < 0 ? h - l : h - l - 1) * px;
            a = new Vec2(start * px, y);
            b = new Vec2(end * px, y);
            if (oy > 0) { Vec2 t = a; a = b; b = t; } // passing south: from east to west keeps south on the left
        } else {
            double x = (ox > 0 ? l + 1 : l) * px;
            a = new Vec2(x, (h - start) * px);
            b = new Vec2(x, (h - end) * px);
            if (ox < 0) { Vec2 t = a; a = b; b = t; } // passing west: from south to north keeps west on the left
        }
        return new Obstacle.Gate(a, b, top, Obstacle.Side.LEFT, ONE_WAY_RESTITUTION);
    }

    private int special(int tx, int ty) {
        int code = track.tiles().code(tx, ty);
        return TileMap.kind(code) == TileMap.SPECIAL_TILE ? PixelMap.SPECIAL + TileMap.shape(code) : -1;
    }

    private Vec2 centre(int tx, int ty) {
        return new Vec2((tx + 0.5) * scale.tile(), (TileMap.HEIGHT - ty - 0.5) * scale.tile());
    }

    /** The set pixels (index x + WIDTH y, y down) as cell spans {row, start, end}, row 0 at the bottom. */
    static int[] spans(boolean[] set) {
        List<int[]> out = new ArrayList<>();
        for (int py = 0; py < PixelMap.HEIGHT; py++) {
            int row = PixelMap.HEIGHT - 1 - py;
            for (int x = 0; x < PixelMap.WIDTH; ) {
                if (!set[x + PixelMap.WIDTH * py]) {
                    x++;
                    continue;
                }
                int s = x;
                while (x < PixelMap.WIDTH && set[x + PixelMap.WIDTH * py]) x++;
                out.add(new int[] {row, s, x});
            }
        }
        int[] spans = new int[3 * out.size()];
        for (int i = 0; i < out.size(); i++) System.arraycopy(out.get(i), 0, spans, 3 * i, 3);
        return spans;
    }
}
