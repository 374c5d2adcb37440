package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The docs' count of the tests that open a real window (skipped without a display) is computed
 * here, from the {@link NeedsDisplay} marks on the compiled test classes, and every number the
 * README or docs/ give for it must be that count (it once said four where there were fourteen).
 */
class NeedsDisplayCountTest {
    private static final Map<String, Integer> WORDS = Map.ofEntries(Map.entry("one", 1), Map.entry("two", 2),
            Map.entry("three", 3), Map.entry("four", 4), Map.entry("five", 5), Map.entry("six", 6), Map.entry("seven", 7),
            Map.entry("eight", 8), Map.entry("nine", 9), Map.entry("ten", 10), Map.entry("eleven", 11), Map.entry("twelve", 12),
            Map.entry("thirteen", 13), Map.entry("fourteen", 14), Map.entry("fifteen", 15), Map.entry("sixteen", 16));

    /** The test methods skipped without a display: every test of a marked class, and marked test methods. */
    static List<String> windowTests() throws IOException, ClassNotFoundException {
        Path classes = Path.of(NeedsDisplayCountTest.class.getProtectionDomain().getCodeSource().getLocation().getPath());
        List<String> out = new ArrayList<>();
        try (Stream<Path> files = Files.walk(classes)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".class") && !p.toString().contains("$")).toList()) {
                String name = classes.relativize(f).toString().replace('/', '.').replaceAll("\\.class$", "");
                Class<?> c = Class.forName(name, false, NeedsDisplayCountTest.class.getClassLoader());
                boolean whole = c.isAnnotationPresent(NeedsDisplay.class);
                for (Method m : c.getDeclaredMethods()) {
                    if (m.isAnnotationPresent(Test.class) && (whole || m.isAnnotationPresent(NeedsDisplay.class))) {
                        out.add(c.getSimpleName() + "." + m.getName());
                    }
                }
            }
        }
        return out;
    }

    @Test
    void theDocsCountTheWindowTestsRight() throws Exception {
        List<String> tests = windowTests();
        System.out.println("tests that open a real window (skipped without a display): " + tests.size());
        assertTrue(tests.size() >= 10, "the game's and the editor's window tests: " + tests);
        assertTrue(tests.stream().noneMatch(t -> t.startsWith("SoundTest.every") || t.startsWith("SoundTest.theDevice")),
                "the sound synthesis needs no window: " + tests);
        Path project = Path.of(System.getProperty("minigolf.projectDir", "."));
        List<Path> docs = new ArrayList<>(List.of(project.resolve("README.md")));
        try (Stream<Path> d = Files.list(project.resolve("docs"))) {
            d.filter(p -> p.toString().endsWith(".md")).forEach(docs::add);
        }
        Pattern claim = Pattern.compile("(\\d+|" + String.join("|", WORDS.keySet()) + ") tests that open a (?:real )?window",
                Pattern.CASE_INSENSITIVE);
        for (Path doc : docs) {
            Matcher m = claim.matcher(Files.readString(doc).replaceAll("\\s+", " "));
            while (m.find()) {
                String n = m.group(1).toLowerCase();
                int said = n.matches("\\d+") ? Integer.parseInt(n) : WORDS.get(n);
                assertEquals(tests.size(), said, doc.getFileName() + " says \"" + m.group() + "\": there are " + tests.size()
                        + " (every test marked @NeedsDisplay): change the number there");
            }
        }
    }
}
