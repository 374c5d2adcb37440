package minigolf.fuzz;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import minigolf.classic.ClassicIndex;
import minigolf.classic.ClassicScale;
import minigolf.classic.ShapeMasks;
import minigolf.classic.TrackFormatException;
import minigolf.classic.TrackImporter;
import minigolf.cli.MinigolfCommand;
import minigolf.course.Bounds;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.World;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Classic track files (issue 28's {@code import-tracks}) as a stranger may send them, fuzzed with
 * seeded generators: {@link TrackMutator}'s broken tracks, imported one by one (every eighth through
 * the command line); the index an import writes, mutated ({@link Mutator}), as the game's course
 * list reads it; the sprite sheets ({@code shapes.gif}) a player points the importer at, their bytes
 * mutated. An imported track's course loads and a shot on it ends inside its bounds; a refused one
 * is named in one short line; nothing throws.
 */
class ClassicTracksFuzzTest {
    static final long SEED = 20261128L;
    static final int TRACK_CASES = 400, INDEX_CASES = 150, IMAGE_CASES = 60;
    /** A refusal longer than this echoes the file rather than naming its problem. */
    static final int MAX_REASON = 400;

    @TempDir
    Path dir;

    private final FuzzChecks checks = new FuzzChecks();

    @Test
    void everyTrackIndexAndSpriteSheetLoadsOrIsRefusedInOneLine() throws Exception {
        long seed = SEED;
        seed = tracks(seed);
        seed = indexes(seed);
        images(seed);
        checks.report("fuzz, classic tracks", TRACK_CASES + INDEX_CASES + IMAGE_CASES);
    }

    private long tracks(long seed) throws Exception {
        for (int i = 0; i < TRACK_CASES; i++, seed++) {
            checks.started();
            TrackMutator.Case c = TrackMutator.mutate(TrackMutator.track(seed), seed);
            Path folder = Files.createDirectories(dir.resolve("in-" + seed).resolve("basic"));
            Path file = folder.resolve("case-" + seed + ".track"), out = dir.resolve("out-" + seed);
            Files.write(file, c.bytes());
            String what = "track seed " + seed + " (" + c.kind() + ": " + FuzzChecks.shorten(c.detail()) + ")";
            try {
                if (i % 8 == 0) throughCommand(what, c.kind(), file, out);
                else imported(what, c.kind(), TrackImporter.run(file, out, ShapeMasks.builtIn(), ClassicScale.standard()), out);
            } catch (RuntimeException | Error e) {
                checks.failure(what + ": threw " + e);
            } finally {
                delete(dir.resolve("in-" + seed));
                delete(out);
            }
        }
        return seed;
    }

    /** {@code minigolf import-tracks FILE --out DIR --no-images}: exit 0 with the track, or 2 with one line naming it. */
    private void throughCommand(String what, String kind, Path file, Path out) throws IOException {
        StringWriter o = new StringWriter(), err = new StringWriter();
        int code = MinigolfCommand.execute(new String[]{"import-tracks", file.toString(), "--out", out.toString(), "--no-images"},
                new PrintWriter(o), new PrintWriter(err));
        checks.count("track " + kind, code == 0);
        if (code == 0) {
            checks.finiteJson(what, o.toString());
            playable(what, ClassicIndex.read(out));
        } else if (code == 2) {
            String e = err.toString();
            checks.oneLine(what, e, "minigolf: not imported: ");
            if (e.length() > MAX_REASON + 60) checks.failure(what + ": a message of " + e.length() + " characters");
        } else {
            checks.failure(what + ": exit " + code + ": " + FuzzChecks.shorten(err.toString()));
        }
    }

    private void imported(String what, String kind, TrackImporter.Result r, Path out) throws IOException {
        if (r.imported().size() + r.failed().size() != 1) {
            checks.failure(what + ": " + r.imported().size() + " imported and " + r.failed().size() + " failed from one file");
            return;
        }
        checks.count("track " + kind, r.failed().isEmpty());
        if (!r.failed().isEmpty()) {
            String reason = r.failed().get(0).reason();
            checks.oneLine(what, reason, "");
            if (reason.length() > MAX_REASON) checks.failure(what + ": a reason of " + reason.length() + " characters");
            if (reason.chars().anyMatch(ch -> Character.isISOControl(ch))) checks.failure(what + ": a control character in " + reason);
            return;
        }
        playable(what, ClassicIndex.read(out));
    }

    /** The index lists the one track, its name fits the screen, its course loads and shots on it end inside. */
    private void playable(String what, ClassicIndex.Index index) {
        if (index.tracks().size() != 1) {
            checks.failure(what + ": the index lists " + index.tracks().size() + " tracks");
            return;
        }
        ClassicIndex.Entry e = index.tracks().get(0);
        if (e.name().length() > 128 || e.author().length() > 128) checks.failure(what + ": a name of " + e.name().length());
        try {
            World w = World.load(e.course());
            Simulator sim = new Simulator(w, SimulationSettings.DEFAULT);
            double x = w.course().start().x(), y = w.course().start().y(), v = w.physics().maxSpeed();
            for (double angle : new double[]{0, 2.3}) {
                ShotResult s = sim.simulate(x, y, v * Math.cos(angle), v * Math.sin(angle));
                Bounds b = w.bounds();
                if (!(b.contains(s.endX(), s.endY()))) {
                    checks.failure(what + ": a shot ends at (" + s.endX() + ", " + s.endY() + "), outside " + b);
                }
            }
        } catch (minigolf.course.CourseException ex) {
            checks.failure(what + ": the imported course does not load: " + ex.getMessage());
        }
    }

    /** The index the game's "Classic tracks" list reads, mutated: read, or refused in one line naming it. */
    private long indexes(long seed) throws Exception {
        Path in = Files.createDirectories(dir.resolve("index-in/basic")), folder = dir.resolve("classic");
        for (int k = 0; k < 3; k++) Files.writeString(in.resolve("t" + k + ".track"), TrackMutator.track(k));
        TrackImporter.run(in, folder, ShapeMasks.builtIn(), ClassicScale.standard());
        Path index = folder.resolve(TrackImporter.INDEX);
        String json = Files.readString(index);
        for (int i = 0; i < INDEX_CASES; i++, seed++) {
            checks.started();
            Mutator.Case c = Mutator.mutate(json, seed);
            Files.write(index, c.bytes());
            String what = FuzzChecks.describe("classic index", seed, c);
            try {
                ClassicIndex.Index read = ClassicIndex.read(folder);
                checks.count("index " + c.kind(), true);
                Path base = folder.toAbsolutePath().normalize();
                for (ClassicIndex.Entry e : read.tracks()) {
                    if (!e.course().startsWith(base)) checks.failure(what + ": a course outside the folder: " + e.course());
                    if (e.name().length() > 128 || e.author().length() > 128) checks.failure(what + ": a name too long to show");
                }
                for (String f : read.failed()) {
                    if (f.length() > MAX_REASON || f.contains("\n")) checks.failure(what + ": a failure line of " + f.length() + " characters");
                }
            } catch (IOException e) {
                checks.count("index " + c.kind(), false);
                checks.oneLine(what, e.getMessage(), index + ": ");
            } catch (RuntimeException | Error e) {
                checks.failure(what + ": threw " + e);
            }
        }
        return seed;
    }

    /** Sprite sheets with mutated bytes (random bytes, cut short, sizes in the header made huge). */
    private void images(long seed) throws Exception {
        byte[] sheet = sheet();
        Path file = dir.resolve("shapes.gif");
        for (int i = 0; i < IMAGE_CASES; i++, seed++) {
            checks.started();
            Random r = new Random(seed);
            byte[] b = sheet.clone();
            String kind;
            switch (r.nextInt(3)) {
                case 0 -> {
                    kind = "image garbage";
                    for (int k = 0, n = 1 + r.nextInt(16); k < n; k++) b[r.nextInt(b.length)] = (byte) r.nextInt(256);
                }
                case 1 -> {
                    kind = "image truncate";
                    b = java.util.Arrays.copyOf(b, r.nextInt(b.length));
                }
                default -> {
                    kind = "image huge";
                    hugeSizes(b, r);
                }
            }
            Files.write(file, b);
            String what = "sprite sheet seed " + seed + " (" + kind + ")";
            try {
                ShapeMasks.readSheet(file);
                checks.count(kind, true);
            } catch (TrackFormatException e) {
                checks.count(kind, false);
                checks.oneLine(what, e.getMessage(), file + ": ");
            } catch (RuntimeException | Error e) {
                checks.failure(what + ": threw " + e);
            }
        }
    }

    /** A GIF sprite sheet of the right size, a mask pattern drawn in the key colour. */
    static byte[] sheet() throws IOException {
        BufferedImage image = new BufferedImage(ShapeMasks.SHEET_WIDTH, ShapeMasks.SHEET_HEIGHT, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) image.setRGB(x, y, (x * 7 + y * 3) % 5 == 0 ? ShapeMasks.MASK_COLOUR : 0x336633);
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(image, "gif", out);
        return out.toByteArray();
    }

    /** The logical screen's and the first image's width or height (little-endian 16-bit) set to a large value. */
    private static void hugeSizes(byte[] gif, Random r) {
        int[] sizes = {0xFFFF, 0x8000, 0x4000, 0};
        int v = sizes[r.nextInt(sizes.length)];
        int descriptor = -1;
        for (int k = 13; k < gif.length - 9 && descriptor < 0; k++) if (gif[k] == 0x2C) descriptor = k;
        int at = r.nextBoolean() || descriptor < 0 ? 6 + 2 * r.nextInt(2) : descriptor + 5 + 2 * r.nextInt(2);
        gif[at] = (byte) v;
        gif[at + 1] = (byte) (v >> 8);
    }

    private static void delete(Path p) throws IOException {
        if (!Files.exists(p)) return;
        try (Stream<Path> walk = Files.walk(p)) {
            for (Path f : walk.sorted(Comparator.reverseOrder()).toList()) Files.delete(f);
        }
    }

    @Test
    void theGeneratedTracksImportAndTheGeneratorIsDeterministic() throws Exception {
        Path in = Files.createDirectories(dir.resolve("plain/basic"));
        for (int k = 0; k < 12; k++) Files.writeString(in.resolve("t" + k + ".track"), TrackMutator.track(SEED + k));
        TrackImporter.Result r = TrackImporter.run(in, dir.resolve("out"), ShapeMasks.builtIn(), ClassicScale.standard());
        assertEquals(List.of(), r.failed());
        assertEquals(12, r.imported().size());
        for (long s = 0; s < 40; s++) {
            assertArrayEquals(TrackMutator.mutate(TrackMutator.track(s), s).bytes(), TrackMutator.mutate(TrackMutator.track(s), s).bytes());
        }
    }
}
