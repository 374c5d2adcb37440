package minigolf.bot.experiment;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Objects;
import minigolf.io.AtomicFile;

/**
 * experiment.json, written into every shard's folder and the merged result: what the experiment
 * is (program, options, course files) and its fingerprint, a SHA-256 over exactly those. Two
 * folders with the same fingerprint computed the same runs with the same code on the same
 * courses, so their rows can be merged or resumed; anything else is refused.
 *
 * @param program the program's name and version ("minigolf 0.1.0")
 * @param code    a hash of the program's classes (see {@link ProgramCode})
 * @param runs    the number of runs in the whole experiment (all shards)
 * @param shard   which shard the folder holds; null for a whole experiment
 */
@JsonInclude(JsonInclude.Include.NON_NULL)
public record Manifest(int format, String program, String code, Options options, List<CourseFile> courses, int runs,
                       String fingerprint, Shard shard) {
    public static final String FILE_NAME = "experiment.json";
    static final int FORMAT = 1;

    /**
     * The options that change results; --threads, --out and the shard do not. The noise lists span
     * the plan's noise grid ({@link RunPlan#grid}); absent (an older manifest) they mean no noise.
     */
    public record Options(List<String> bots, int seeds, long budget, int maxStrokes, List<Double> noisePositions,
                          List<Double> noiseVelocities, boolean hideFriction) {
        public Options {
            noisePositions = noisePositions == null ? List.of(0.0) : List.copyOf(noisePositions);
            noiseVelocities = noiseVelocities == null ? List.of(0.0) : List.copyOf(noiseVelocities);
        }

        /** Options without noise, friction known. */
        public static Options of(List<String> bots, int seeds, long budget, int maxStrokes) {
            return new Options(bots, seeds, budget, maxStrokes, List.of(0.0), List.of(0.0), false);
        }
    }

    /** A course of the suite: its name (the file name without .json) and the SHA-256 of the file's bytes. */
    public record CourseFile(String name, String sha256) {
    }

    private record Identity(int format, String program, String code, Options options, List<CourseFile> courses) {
    }

    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    /** A whole experiment's manifest for these options and course files, run by this program. */
    public static Manifest of(String program, Options options, List<CourseFile> courses) {
        RunPlan plan = planOf(options, courses);
        Identity identity = new Identity(FORMAT, program, ProgramCode.hash(), options, List.copyOf(courses));
        return new Manifest(FORMAT, program, identity.code(), options, identity.courses(), plan.size(),
                fingerprint(identity), null);
    }

    public static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }

    public Manifest forShard(Shard s) {
        return new Manifest(format, program, code, options, courses, runs, fingerprint, s);
    }

    public RunPlan plan() {
        return planOf(options, courses);
    }

    private static RunPlan planOf(Options options, List<CourseFile> courses) {
        return new RunPlan(courses.stream().map(CourseFile::name).toList(), options.bots(), options.seeds(),
                RunPlan.grid(options.noisePositions(), options.noiseVelocities()));
    }

    /** Says in words how another manifest's experiment differs from this one ("" when it does not). */
    public String differences(Manifest other) {
        List<String> d = new ArrayList<>();
        if (!Objects.equals(program, other.program)) d.add("program " + other.program + " against " + program);
        if (!Objects.equals(code, other.code)) d.add("a different build of the program");
        if (!Objects.equals(options, other.options)) d.add("options " + describe(other.options) + " against " + describe(options));
        if (!Objects.equals(courses, other.courses)) {
            List<String> names = courses.stream().map(CourseFile::name).toList();
            List<String> otherNames = other.courses.stream().map(CourseFile::name).toList();
            if (!names.equals(otherNames)) {
                d.add("courses " + otherNames + " against " + names);
            } else {
                List<String> changed = new ArrayList<>();
                for (int i = 0; i < courses.size(); i++) {
                    if (!courses.get(i).sha256().equals(other.courses.get(i).sha256())) changed.add(courses.get(i).name());
                }
                d.add("different contents of course file(s) " + String.join(", ", changed));
            }
        }
        if (d.isEmpty() && !Objects.equals(fingerprint, other.fingerprint)) d.add("fingerprint " + other.fingerprint);
        return String.join("; ", d);
    }

    private static String describe(Options o) {
        return "--bots " + String.join(",", o.bots()) + " --seeds " + o.seeds() + " --budget " + o.budget()
                + " --max-strokes " + o.maxStrokes() + noise(o);
    }

    /** The noise options, when they are not the defaults. */
    private static String noise(Options o) {
        List<Double> none = List.of(0.0);
        if (o.noisePositions().equals(none) && o.noiseVelocities().equals(none) && !o.hideFriction()) return "";
        return " --noise-position " + join(o.noisePositions()) + " --noise-velocity " + join(o.noiseVelocities())
                + (o.hideFriction() ? " --hide-friction" : "");
    }

    private static String join(List<Double> values) {
        return String.join(",", values.stream().map(String::valueOf).toList());
    }

    public void write(Path directory) throws IOException {
        AtomicFile.write(directory.resolve(FILE_NAME), JSON.writeValueAsBytes(this));
    }

    /** The manifest in {@code directory}, or null when it has none. */
    public static Manifest read(Path directory) {
        Path file = directory.resolve(FILE_NAME);
        Manifest m;
        try {
            m = JSON.readValue(Files.readAllBytes(file), Manifest.class);
        } catch (NoSuchFileException e) {
            return null;
        } catch (IOException | RuntimeException e) {
            String why = e.getMessage() == null ? e.toString() : e.getMessage().lines().findFirst().orElse("");
            throw new ExperimentException(file + ": not a readable experiment manifest: " + why);
        }
        if (m.format != FORMAT || m.options == null || m.courses == null || m.program == null || m.fingerprint == null
                || m.options.bots() == null) {
            throw new ExperimentException(file + ": not an experiment manifest of format " + FORMAT);
        }
        Identity identity = new Identity(m.format, m.program, m.code, m.options, m.courses);
        if (!fingerprint(identity).equals(m.fingerprint) || m.plan().size() != m.runs) {
            throw new ExperimentException(file + ": the fingerprint does not match the contents (edited by hand?)");
        }
        return m;
    }

    private static String fingerprint(Identity identity) {
        try {
            return sha256(new ObjectMapper().writeValueAsString(identity).getBytes(StandardCharsets.UTF_8));
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("plain records always serialize", e);
        }
    }
}
