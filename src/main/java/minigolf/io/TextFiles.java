package minigolf.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * Reads the game's text files (courses, models, saves, settings) defensively: only regular files
 * (a FIFO or a link to {@code /dev/zero} would block or never end), never more than a size limit
 * (checked before reading and again while reading, since a file may grow), and only UTF-8 text,
 * with a message that says what the file is instead (binary, UTF-16). Problems are one line and
 * never quote the file's content.
 */
public final class TextFiles {
    private TextFiles() {
    }

    /** A file that cannot be read as text; the message is one line without the file name. */
    public static final class TextFileException extends IOException {
        private static final long serialVersionUID = 1L;

        public TextFileException(String problem) {
            super(problem);
        }
    }

    /**
     * The file's text (UTF-8, a leading byte-order mark removed).
     *
     * @param maxBytes the largest file accepted
     * @throws TextFileException e.g. "no such file", "is a directory", "not a regular file (a FIFO,
     *                           device or socket)", "too large: 3000000 bytes (the limit is 1048576)",
     *                           "UTF-16 text: save it as UTF-8", "binary data (a NUL byte at byte 17)"
     */
    public static String read(Path file, long maxBytes) throws TextFileException {
        return decode(readBytes(file, maxBytes));
    }

    /** The file's bytes, with the checks of {@link #read} but no decoding. */
    public static byte[] readBytes(Path file, long maxBytes) throws TextFileException {
        BasicFileAttributes attributes;
        try {
            attributes = Files.readAttributes(file, BasicFileAttributes.class); // follows links
        } catch (IOException | RuntimeException e) {
            throw new TextFileException(reason(e));
        }
        if (attributes.isDirectory()) throw new TextFileException("is a directory, not a file");
        if (!attributes.isRegularFile()) {
            throw new TextFileException("not a regular file (a FIFO, device or socket): refused");
        }
        if (attributes.size() > maxBytes) throw new TextFileException(tooLarge(attributes.size(), maxBytes));
        try (InputStream in = Files.newInputStream(file)) {
            byte[] bytes = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 16, maxBytes + 1));
            if (bytes.length > maxBytes) throw new TextFileException(tooLarge(bytes.length, maxBytes) + " (it grew while read)");
            return bytes;
        } catch (TextFileException e) {
            throw e;
        } catch (IOException | RuntimeException e) {
            throw new TextFileException(reason(e));
        }
    }

    /** UTF-8 bytes to text, or a message naming what the bytes are instead. */
    public static String decode(byte[] bytes) throws TextFileException {
        int n = bytes.length;
        if (n >= 2 && ((bytes[0] == (byte) 0xFE && bytes[1] == (byte) 0xFF) || (bytes[0] == (byte) 0xFF && bytes[1] == (byte) 0xFE))) {
            throw new TextFileException("UTF-16 text (it starts with a UTF-16 byte-order mark): save it as UTF-8");
        }
        int start = n >= 3 && bytes[0] == (byte) 0xEF && bytes[1] == (byte) 0xBB && bytes[2] == (byte) 0xBF ? 3 : 0;
        for (int i = start; i < n; i++) {
            if (bytes[i] == 0) {
                boolean utf16 = looksLikeUtf16(bytes, start);
                throw new TextFileException(utf16 ? "UTF-16 text (zero bytes between the characters): save it as UTF-8"
                        : "binary data (a zero byte at byte " + i + "), not a text file");
            }
        }
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, start, n - start);
        try {
            return decoder.decode(in).toString();
        } catch (CharacterCodingException e) {
            throw new TextFileException("not UTF-8 text (an invalid byte sequence at byte " + in.position()
                    + "): binary data or another encoding");
        }
    }

    /** UTF-16 without a mark: in its first characters, every other byte is zero and the others are not. */
    private static boolean looksLikeUtf16(byte[] bytes, int start) {
        int end = Math.min(bytes.length, start + 64) & ~1;
        if (end - start < 4) return false;
        boolean evenZero = true, oddZero = true, evenSet = true, oddSet = true;
        for (int i = start; i + 1 < end; i += 2) {
            evenZero &= bytes[i] == 0;
            evenSet &= bytes[i] != 0;
            oddZero &= bytes[i + 1] == 0;
            oddSet &= bytes[i + 1] != 0;
        }
        return (evenZero && oddSet) || (oddZero && evenSet);
    }

    /** "the file is empty" or "the file holds only whitespace (N characters)", or null for text with content. */
    public static String blankProblem(String text) {
        if (text.isEmpty()) return "the file is empty";
        if (text.isBlank()) return "the file holds only whitespace (" + text.length() + " characters), no content";
        return null;
    }

    private static String tooLarge(long size, long limit) {
        return "too large: " + size + " bytes (the limit is " + limit + " bytes)";
    }

    /** The operating system's reason, one line, without file names that the caller already gives. */
    private static String reason(Exception e) {
        if (e instanceof NoSuchFileException) return "no such file";
        if (e instanceof AccessDeniedException) return "permission denied";
        if (e instanceof FileSystemException f && f.getReason() != null) return f.getReason();
        String m = e.getMessage();
        if (m == null || m.isBlank()) return e.getClass().getSimpleName();
        int nl = m.indexOf('\n');
        return nl >= 0 ? m.substring(0, nl) : m;
    }
}
