package minigolf.fuzz;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import minigolf.classic.TileMap;

/**
 * Seeded classic track files (the original game's {@code .track} format, docs/classic-tracks.md),
 * made here from the format description (no real track), and seeded mutations of them: the map
 * data broken (characters changed, inserted, deleted, extreme repeat counts, cut short or too
 * long), the map repainted with random valid tiles (no hole, many holes and starts, noise), lines
 * deleted, repeated or re-keyed, numbers extreme, names long or with control characters, Latin-1
 * and random bytes, UTF-16, truncation, a file larger than any track. The same seed gives the same
 * bytes.
 */
final class TrackMutator {
    static final String LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
    static final String[] KINDS = {"map-char", "map-insert", "map-delete", "map-repeat", "map-cut", "map-extend",
            "map-tiles", "map-noise", "line-delete", "line-repeat", "line-key", "number", "long-text", "control",
            "latin1", "garbage", "utf16", "truncate", "huge"};
    /** Element indices (the original's): grass, sand, mud, ice, downhill 4-11, water 12, acid 13, ... one-way 20-23. */
    private static final int ELEMENTS = TileMap.ELEMENTS, SHAPES = TileMap.SHAPES, SPECIALS = TileMap.SPECIALS;
    private static final int BLOCK = 16, START = 0, HOLE = 1;

    private TrackMutator() {
    }

    record Case(String kind, String detail, byte[] bytes) {
    }

    /** A playable track: a frame of blocks, patches of surfaces and walls, a start and a hole; V1 or V2. */
    static String track(long seed) {
        Random r = new Random(seed);
        int[] codes = new int[TileMap.TILES];
        Arrays.fill(codes, TileMap.GRASS);
        int block = TileMap.elementTile(0, BLOCK, BLOCK);
        for (int x = 0; x < TileMap.WIDTH; x++) {
            codes[x] = block;
            codes[x + TileMap.WIDTH * (TileMap.HEIGHT - 1)] = block;
        }
        for (int y = 0; y < TileMap.HEIGHT; y++) {
            codes[TileMap.WIDTH * y] = block;
            codes[TileMap.WIDTH - 1 + TileMap.WIDTH * y] = block;
        }
        int patches = r.nextInt(8);
        for (int p = 0; p < patches; p++) {
            int x0 = 1 + r.nextInt(TileMap.WIDTH - 2), y0 = 1 + r.nextInt(TileMap.HEIGHT - 2);
            int w = 1 + r.nextInt(10), h = 1 + r.nextInt(6), e = r.nextInt(ELEMENTS), shape = r.nextInt(4) == 0 ? r.nextInt(SHAPES) : 0;
            for (int y = y0; y < Math.min(TileMap.HEIGHT - 1, y0 + h); y++) {
                for (int x = x0; x < Math.min(TileMap.WIDTH - 1, x0 + w); x++) {
                    codes[x + TileMap.WIDTH * y] = TileMap.elementTile(shape, e, shape == 0 ? e : r.nextInt(ELEMENTS));
                }
            }
        }
        codes[4 + TileMap.WIDTH * 12] = TileMap.specialTile(START, 0);
        codes[44 + TileMap.WIDTH * (2 + r.nextInt(21))] = TileMap.specialTile(HOLE, 0);
        if (r.nextBoolean()) codes[20 + TileMap.WIDTH * (2 + r.nextInt(21))] = TileMap.specialTile(2 + r.nextInt(SPECIALS - 2), 0);
        String data = encode(codes);
        String name = "Fuzz " + seed, author = "Tester";
        if (r.nextBoolean()) {
            return "V 1\nA " + author + "\nN " + name + "\nT " + data + "\nI 120,900,2,3\nB someone,1100000000000\n";
        }
        return "V 2\nA " + author + "\nN " + name + "\nC " + (1 + r.nextInt(6)) + "\nT " + data + ",Ads:B0000\nI 120,900,2,3"
                + "\nB someone,1100000000000\nL other,1200000000000\nR 1,2,3,4,5,6,7,8,9,10,11\nS fttt14\n";
    }

    /** The map written as the original writes it: copies of the tile to the west (D) or north (E), counted runs. */
    static String encode(int[] codes) {
        StringBuilder sb = new StringBuilder();
        char last = 0;
        int run = 0;
        for (int t = 0; t < codes.length; t++) {
            int x = t % TileMap.WIDTH;
            String code;
            if (x > 0 && codes[t] == codes[t - 1]) code = "D";
            else if (t >= TileMap.WIDTH && codes[t] == codes[t - TileMap.WIDTH]) code = "E";
            else code = tile(codes[t]);
            if (code.length() == 1 && code.charAt(0) == last) {
                run++;
                continue;
            }
            sb.append(runOf(last, run));
            if (code.length() == 1) {
                last = code.charAt(0);
                run = 1;
            } else {
                last = 0;
                run = 0;
                sb.append(code);
            }
        }
        return sb.append(runOf(last, run)).toString();
    }

    private static String runOf(char letter, int run) {
        return run == 0 ? "" : run == 1 ? String.valueOf(letter) : run + String.valueOf(letter);
    }

    private static String tile(int code) {
        char s = LETTERS.charAt(TileMap.shape(code)), f = LETTERS.charAt(TileMap.first(code));
        return switch (TileMap.kind(code)) {
            case TileMap.ELEMENT_TILE -> "B" + s + f + LETTERS.charAt(TileMap.second(code));
            case TileMap.SPECIAL_TILE -> "C" + s + f;
            default -> "A" + s + f;
        };
    }

    static Case mutate(String track, long seed) {
        Random r = new Random(seed);
        String kind = KINDS[r.nextInt(KINDS.length)];
        List<String> lines = new ArrayList<>(Arrays.asList(track.split("\n", -1)));
        int mapLine = 0;
        while (mapLine < lines.size() - 1 && !lines.get(mapLine).startsWith("T ")) mapLine++;
        String map = lines.get(mapLine).substring(2);
        String detail;
        switch (kind) {
            case "map-char", "map-insert" -> {
                String alphabet = LETTERS + "0123456789,:;- \t#é\u00ff\u2603\uffff";
                int n = 1 + r.nextInt(8);
                StringBuilder m = new StringBuilder(map);
                for (int i = 0; i < n; i++) {
                    int at = r.nextInt(m.length());
                    char c = alphabet.charAt(r.nextInt(alphabet.length()));
                    if (kind.equals("map-char")) m.setCharAt(at, c);
                    else m.insert(at, c);
                }
                map = m.toString();
                detail = n + " characters";
            }
            case "map-delete" -> {
                int a = r.nextInt(map.length()), b = Math.min(map.length(), a + 1 + r.nextInt(200));
                map = map.substring(0, a) + map.substring(b);
                detail = "characters " + a + "-" + b + " deleted";
            }
            case "map-repeat" -> {
                String[] counts = {"0", "1", "2", "4900", "4901", "1225", "99999999999", "2147483648", "00007", "-3"};
                String count = counts[r.nextInt(counts.length)];
                int at = r.nextInt(map.length());
                while (at > 0 && Character.isDigit(map.charAt(at - 1))) at--;
                map = map.substring(0, at) + count + map.substring(at);
                detail = count + " at " + at;
            }
            case "map-cut" -> {
                int cut = r.nextInt(map.length());
                map = map.substring(0, cut);
                detail = "map cut at " + cut;
            }
            case "map-extend" -> {
                String[] more = {"BAAA", "D", "49D", "E", "AAA", "CBA", "4900D"};
                String m = more[r.nextInt(more.length)];
                map = map.contains(",") ? map.replaceFirst(",", m + ",") : map + m;
                detail = "map + " + m;
            }
            case "map-tiles", "map-noise" -> {
                int[] codes = new int[TileMap.TILES];
                Arrays.fill(codes, TileMap.GRASS);
                int n = kind.equals("map-noise") ? TileMap.TILES : 1 + r.nextInt(400);
                int holes = r.nextInt(4) == 0 ? 0 : 1 + r.nextInt(r.nextBoolean() ? 2 : 30);
                int starts = r.nextInt(4) == 0 ? 0 : 1 + r.nextInt(r.nextBoolean() ? 2 : 30);
                for (int i = 0; i < n; i++) codes[r.nextInt(TileMap.TILES)] = randomTile(r);
                for (int i = 0; i < holes; i++) codes[r.nextInt(TileMap.TILES)] = TileMap.specialTile(HOLE, r.nextInt(ELEMENTS));
                for (int i = 0; i < starts; i++) codes[r.nextInt(TileMap.TILES)] = TileMap.specialTile(r.nextBoolean() ? START : 24, 0);
                map = encode(codes);
                detail = n + " random tiles, " + holes + " holes, " + starts + " starts";
            }
            case "line-delete" -> {
                int at = r.nextInt(lines.size());
                detail = "line " + (at + 1) + " deleted";
                lines.remove(at);
                return text(kind, detail, lines);
            }
            case "line-repeat" -> {
                int at = r.nextInt(lines.size()), n = 1 + r.nextInt(r.nextBoolean() ? 2 : 200);
                for (int i = 0; i < n; i++) lines.add(at, lines.get(at));
                return text(kind, "line " + (at + 1) + " x" + n, lines);
            }
            case "line-key" -> {
                int at = r.nextInt(lines.size());
                String keys = "VANTCIBLRSXvt# 1";
                char k = keys.charAt(r.nextInt(keys.length()));
                String l = lines.get(at);
                lines.set(at, l.isEmpty() ? String.valueOf(k) : k + l.substring(1));
                return text(kind, "line " + (at + 1) + " key " + k, lines);
            }
            case "number" -> {
                String[] words = {"-1", "0", "99999999999999999999", "9223372036854775807", "2147483648", "1e9", "", "NaN",
                        " 1 , 2", "1,,2", "0x10", "١٢"};
                String w = words[r.nextInt(words.length)];
                String[] keys = {"V ", "I ", "R ", "C ", "S "};
                String key = keys[r.nextInt(keys.length)];
                boolean found = false;
                for (int i = 0; i < lines.size() && !found; i++) {
                    if (!lines.get(i).startsWith(key)) continue;
                    String[] parts = lines.get(i).substring(2).split(",", -1);
                    parts[r.nextInt(parts.length)] = w;
                    lines.set(i, key + String.join(",", parts));
                    found = true;
                }
                if (!found) lines.add(1, key + w);
                return text(kind, key + "'" + w + "'", lines);
            }
            case "long-text" -> {
                String key = r.nextBoolean() ? "N " : r.nextBoolean() ? "A " : "B ";
                int n = 150 + r.nextInt(r.nextBoolean() ? 200 : 200_000);
                for (int i = 0; i < lines.size(); i++) {
                    if (lines.get(i).startsWith(key)) lines.set(i, key + "x".repeat(n));
                }
                return text(kind, key + n + " characters", lines);
            }
            case "control" -> {
                String[] controls = {"\u0000", "\u0007", "\r", "\u001b[2J", "\ufeff", "\u202e", "\u0085", "\t"};
                String c = controls[r.nextInt(controls.length)];
                int at = r.nextInt(lines.size());
                String l = lines.get(at);
                int pos = Math.min(l.length(), 2 + r.nextInt(Math.max(1, l.length())));
                lines.set(at, l.substring(0, pos) + c + l.substring(pos));
                return text(kind, "U+" + Integer.toHexString(c.charAt(0)) + " in line " + (at + 1), lines);
            }
            case "latin1" -> {
                for (int i = 0; i < lines.size(); i++) {
                    if (lines.get(i).startsWith("A ")) lines.set(i, "A J\u00e4rvinen \u00f6\u00fc");
                }
                return new Case(kind, "Latin-1", String.join("\n", lines).getBytes(StandardCharsets.ISO_8859_1));
            }
            case "garbage" -> {
                byte[] b = track.getBytes(StandardCharsets.UTF_8);
                int n = 1 + r.nextInt(16);
                for (int i = 0; i < n; i++) b[r.nextInt(b.length)] = (byte) r.nextInt(256);
                return new Case(kind, n + " random bytes", b);
            }
            case "utf16" -> {
                return new Case(kind, "UTF-16", track.getBytes(r.nextBoolean() ? StandardCharsets.UTF_16 : StandardCharsets.UTF_16LE));
            }
            case "truncate" -> {
                int cut = r.nextInt(track.length());
                return new Case(kind, "cut at " + cut, track.substring(0, cut).getBytes(StandardCharsets.UTF_8));
            }
            case "huge" -> {
                int n = 256 * 1024 + r.nextInt(64 * 1024);
                lines.add(r.nextInt(lines.size()), "X " + "y".repeat(n));
                return text(kind, "a line of " + n + " characters", lines);
            }
            default -> throw new IllegalArgumentException(kind);
        }
        lines.set(mapLine, "T " + map);
        return text(kind, detail, lines);
    }

    /** Any tile the format can write: an element tile, a special block on an element, rarely an empty tile. */
    private static int randomTile(Random r) {
        return switch (r.nextInt(5)) {
            case 0, 1 -> TileMap.elementTile(0, r.nextInt(ELEMENTS), 0);
            case 2 -> TileMap.elementTile(r.nextInt(SHAPES), r.nextInt(ELEMENTS), r.nextInt(ELEMENTS));
            case 3 -> TileMap.specialTile(r.nextInt(SPECIALS), r.nextInt(ELEMENTS));
            default -> r.nextInt(SHAPES) << 16 | r.nextInt(ELEMENTS) << 8; // 'A': an empty tile
        };
    }

    private static Case text(String kind, String detail, List<String> lines) {
        return new Case(kind, detail, String.join("\n", lines).getBytes(StandardCharsets.UTF_8));
    }
}
