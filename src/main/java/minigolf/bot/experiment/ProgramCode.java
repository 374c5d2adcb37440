package minigolf.bot.experiment;

import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Stream;

/**
 * A hash of the program's own classes (minigolf/**.class, by name and content). The version
 * number alone stays the same while the code changes between builds; shards computed by
 * different code must not be merged, so the experiment's fingerprint includes this hash.
 */
final class ProgramCode {
    private static String cached;

    private ProgramCode() {
    }

    static synchronized String hash() {
        if (cached == null) cached = compute();
        return cached;
    }

    private static String compute() {
        try {
            Path location = Path.of(ProgramCode.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            MessageDigest digest = MessageDigest.getInstance("SHA-256");
            if (Files.isDirectory(location)) {
                List<Path> classes;
                try (Stream<Path> walk = Files.walk(location.resolve("minigolf"))) {
                    classes = new ArrayList<>(walk.filter(p -> p.toString().endsWith(".class")).toList());
                }
                classes.sort(null);
                for (Path c : classes) add(digest, location.relativize(c).toString().replace('\\', '/'), Files.readAllBytes(c));
            } else {
                try (JarFile jar = new JarFile(location.toFile())) {
                    List<JarEntry> entries = new ArrayList<>(jar.stream()
                            .filter(e -> e.getName().startsWith("minigolf/") && e.getName().endsWith(".class")).toList());
                    entries.sort((a, b) -> a.getName().compareTo(b.getName()));
                    for (JarEntry e : entries) {
                        try (InputStream in = jar.getInputStream(e)) {
                            add(digest, e.getName(), in.readAllBytes());
                        }
                    }
                }
            }
            return HexFormat.of().formatHex(digest.digest());
        } catch (IOException | URISyntaxException | RuntimeException | NoSuchAlgorithmException e) {
            // No readable code source (an unusual class loader): the version number must do.
            return "unknown";
        }
    }

    private static void add(MessageDigest digest, String name, byte[] content) {
        digest.update(name.getBytes(java.nio.charset.StandardCharsets.UTF_8));
        digest.update((byte) 0);
        digest.update(Long.toString(content.length).getBytes(java.nio.charset.StandardCharsets.UTF_8));
        digest.update((byte) 0);
        digest.update(content);
    }
}
