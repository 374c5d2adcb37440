package minigolf.docs;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Every relative link in the README and in docs/ leads somewhere: the file exists, and a
 * {@code #anchor} names a heading of that page (GitHub's rule for heading anchors). The README
 * stays a player's page: short, with how to play near the top.
 */
class DocLinksTest {

    private static final Pattern LINK = Pattern.compile("\\]\\(([^)\\s]+)\\)");

    private static Path projectDir() {
        return Path.of(System.getProperty("minigolf.projectDir", "."));
    }

    private static List<Path> pages() throws IOException {
        List<Path> out = new ArrayList<>();
        out.add(projectDir().resolve("README.md"));
        try (Stream<Path> docs = Files.list(projectDir().resolve("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(out::add);
        }
        return out;
    }

    /** GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens, repeats numbered. */
    static Set<String> anchors(String markdown) {
        Set<String> out = new LinkedHashSet<>();
        Map<String, Integer> seen = new HashMap<>();
        boolean code = false;
        for (String line : markdown.split("\n")) {
            if (line.startsWith("```")) code = !code;
            if (code || !line.startsWith("#")) continue;
            String text = line.replaceFirst("^#+\\s*", "").strip().toLowerCase(Locale.ROOT);
            String slug = text.replaceAll("[^\\p{L}\\p{N} _-]", "").replace(' ', '-');
            int n = seen.merge(slug, 1, Integer::sum);
            out.add(n == 1 ? slug : slug + "-" + (n - 1));
        }
        return out;
    }

    /** Links outside code blocks and code spans. */
    private static List<String> links(String markdown) {
        List<String> out = new ArrayList<>();
        boolean code = false;
        for (String line : markdown.split("\n")) {
            if (line.startsWith("```")) code = !code;
            if (code) continue;
            Matcher m = LINK.matcher(line.replaceAll("`[^`]*`", ""));
            while (m.find()) out.add(m.group(1));
        }
        return out;
    }

    @Test
    void everyRelativeLinkResolvesToAFileAndAHeading() throws IOException {
        List<String> broken = new ArrayList<>();
        int checked = 0;
        for (Path page : pages()) {
            String text = Files.readString(page);
            for (String link : links(text)) {
                if (link.matches("^[a-z]+:.*")) continue; // http:, https:, mailto:
                checked++;
                int hash = link.indexOf('#');
                String file = hash < 0 ? link : link.substring(0, hash);
                String anchor = hash < 0 ? null : link.substring(hash + 1);
                Path target = file.isEmpty() ? page : page.getParent().resolve(file).normalize();
                if (!Files.exists(target)) {
                    broken.add(projectDir().relativize(page) + ": " + link + " (no such file)");
                } else if (anchor != null && !anchors(Files.readString(target)).contains(anchor)) {
                    broken.add(projectDir().relativize(page) + ": " + link + " (no such heading)");
                }
            }
        }
        assertTrue(checked > 40, "links found: " + checked);
        assertTrue(broken.isEmpty(), String.join("\n", broken));
    }

    @Test
    void anchorsFollowGitHubsRule() {
        assertEquals(Set.of("files-from-others-limits-and-confinement", "the-editors-brush", "packages", "packages-1"),
                anchors("## Files from others: limits and confinement\n### The editor's brush\n## Packages\n"
                        + "```sh\n# not a heading\n```\n## Packages\n"));
    }

    @Test
    void theReadmeIsForPlayersFirst() throws IOException {
        List<String> lines = Files.readAllLines(projectDir().resolve("README.md"));
        assertTrue(lines.size() <= 300, "README has " + lines.size() + " lines; details belong in docs/");
        int howToPlay = lines.indexOf("## How to play");
        assertTrue(howToPlay >= 0 && howToPlay < 60, "How to play starts at line " + (howToPlay + 1));
        assertTrue(lines.subList(0, howToPlay).stream().anyMatch(l -> l.contains("gradle run"))
                && lines.subList(0, howToPlay).stream().anyMatch(l -> l.contains("gradle test")), "the two commands come first");
        assertTrue(lines.stream().anyMatch(l -> l.contains("build/install/minigolf/bin") && l.contains("PATH")),
                "the README says how to put minigolf on the PATH");
    }
}
