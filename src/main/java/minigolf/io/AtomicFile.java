package minigolf.io;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFileAttributeView;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Writes a file so that readers see either the old content or the new, never a torn file: the
 * bytes go to a temporary file beside the target, are forced to disk, and the temporary file is
 * renamed over the target (atomically where the file system can). If anything fails the old file
 * is untouched and the temporary file removed. A symbolic link is kept: its target is replaced.
 */
public final class AtomicFile {
    private AtomicFile() {
    }

    /**
     * @throws IOException with a one-line message naming the step that failed and the system's
     *                     reason, e.g. "cannot replace the file: Is a directory"
     */
    public static void write(Path file, byte[] content) throws IOException {
        Path temporary = null;
        String step = "cannot resolve the path";
        try {
            Path target = file.toAbsolutePath();
            if (Files.isSymbolicLink(target)) target = target.toRealPath();
            Path directory = target.getParent();
            step = "cannot create a temporary file in " + directory;
            temporary = createTemporary(directory, target.getFileName().toString());
            copyPermissions(target, temporary);
            step = "cannot write " + temporary.getFileName();
            try (FileChannel channel = FileChannel.open(temporary, StandardOpenOption.WRITE)) {
                ByteBuffer buffer = ByteBuffer.wrap(content);
                while (buffer.hasRemaining()) channel.write(buffer);
                channel.force(true);
            }
            step = "cannot replace the file";
            try {
                Files.move(temporary, target, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING);
            }
            temporary = null;
            syncDirectory(directory);
        } catch (IOException | RuntimeException e) {
            throw new IOException(step + ": " + reason(e), e);
        } finally {
            if (temporary != null) {
                try {
                    Files.deleteIfExists(temporary);
                } catch (IOException | RuntimeException ignored) {
                    // nothing more to do; the original file is untouched either way
                }
            }
        }
    }

    /** Temporary files older than this are left over from a killed process; younger ones may be in use. */
    public static final long STALE_AFTER_MILLIS = 60_000;

    /**
     * Removes the temporary files ({@code .name.<hex>.tmp}) that a process killed while writing left
     * in {@code directory}, if they are older than {@link #STALE_AFTER_MILLIS}. Returns how many it
     * removed; a missing or unreadable folder removes nothing.
     */
    public static int removeStaleTemporaries(Path directory) {
        int removed = 0;
        long now = System.currentTimeMillis();
        try (java.nio.file.DirectoryStream<Path> files = Files.newDirectoryStream(directory, ".*.tmp")) {
            for (Path f : files) {
                String name = f.getFileName().toString();
                if (!name.matches("\\..+\\.[0-9a-f]{1,16}\\.tmp")) continue;
                try {
                    if (!Files.isRegularFile(f, java.nio.file.LinkOption.NOFOLLOW_LINKS)) continue;
                    if (now - Files.getLastModifiedTime(f).toMillis() < STALE_AFTER_MILLIS) continue;
                    Files.delete(f);
                    removed++;
                } catch (IOException | RuntimeException ignored) {
                    // someone else removed it, or it cannot be removed: nothing is lost either way
                }
            }
        } catch (IOException | RuntimeException ignored) {
            // no folder yet
        }
        return removed;
    }

    /**
     * The temporary files a write of {@code file} left behind ({@code .name.<hex>.tmp} beside it),
     * last modified at least {@code olderThanMillis} ago, the newest first. A process killed while
     * writing leaves the new content there, complete or cut short; the file itself still holds the old.
     */
    public static java.util.List<Path> temporariesOf(Path file, long olderThanMillis) {
        Path target = file.toAbsolutePath();
        Path directory = target.getParent();
        String prefix = "." + target.getFileName() + ".";
        long now = System.currentTimeMillis();
        java.util.List<Path> out = new java.util.ArrayList<>();
        java.util.Map<Path, Long> modified = new java.util.HashMap<>();
        try (java.nio.file.DirectoryStream<Path> files = Files.newDirectoryStream(directory, ".*.tmp")) {
            for (Path f : files) {
                String name = f.getFileName().toString();
                if (!name.startsWith(prefix) || !name.substring(prefix.length()).matches("[0-9a-f]{1,16}\\.tmp")) continue;
                try {
                    if (!Files.isRegularFile(f, java.nio.file.LinkOption.NOFOLLOW_LINKS)) continue;
                    long m = Files.getLastModifiedTime(f).toMillis();
                    if (now - m < olderThanMillis) continue;
                    modified.put(f, m);
                    out.add(f);
                } catch (IOException | RuntimeException ignored) {
                    // gone meanwhile
                }
            }
        } catch (IOException | RuntimeException ignored) {
            // no folder: nothing left behind
        }
        out.sort(java.util.Comparator.comparing((Path f) -> modified.get(f)).reversed());
        return out;
    }

    /** The operating system's reason without the file names ("permission denied", "Is a directory"). */
    private static String reason(Exception e) {
        if (e instanceof NoSuchFileException) return "no such file or directory";
        if (e instanceof AccessDeniedException) return "permission denied";
        if (e instanceof FileSystemException f && f.getReason() != null) return f.getReason();
        String m = e.getMessage();
        return m == null || m.isBlank() ? e.getClass().getSimpleName() : m.lines().findFirst().orElse(m);
    }

    /** A new empty file ".name.<random>.tmp" next to the target. */
    private static Path createTemporary(Path directory, String name) throws IOException {
        for (int attempt = 0; ; attempt++) {
            String suffix = Long.toHexString(ThreadLocalRandom.current().nextLong() >>> 1);
            Path temporary = directory.resolve("." + name + "." + suffix + ".tmp");
            try {
                Files.newByteChannel(temporary, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
                return temporary;
            } catch (FileAlreadyExistsException e) {
                if (attempt >= 10) throw e;
            }
        }
    }

    /** The new file keeps the old one's permissions; best effort. */
    private static void copyPermissions(Path from, Path to) {
        try {
            PosixFileAttributeView source = Files.getFileAttributeView(from, PosixFileAttributeView.class);
            PosixFileAttributeView destination = Files.getFileAttributeView(to, PosixFileAttributeView.class);
            if (source == null || destination == null || !Files.exists(from)) return;
            destination.setPermissions(source.readAttributes().permissions());
        } catch (IOException | RuntimeException ignored) {
            // the file keeps the default permissions
        }
    }

    /** Makes the rename itself durable where the platform allows it (Linux, macOS); best effort. */
    private static void syncDirectory(Path directory) {
        try (FileChannel channel = FileChannel.open(directory, StandardOpenOption.READ)) {
            channel.force(true);
        } catch (IOException | RuntimeException ignored) {
            // not supported on this platform (e.g. Windows)
        }
    }
}
