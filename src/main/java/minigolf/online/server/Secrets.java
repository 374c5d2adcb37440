package minigolf.online.server;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.HexFormat;
import minigolf.online.Protocol;

/**
 * Room codes and seat tokens, drawn from {@link SecureRandom}: a code is 8 of 31 symbols (about
 * 2^40, so guessing one open room among thousands takes on the order of 10^8 tries, far beyond
 * the rate limits); a token is 128 bits. The server keeps only a token's SHA-256.
 */
final class Secrets {
    private static final SecureRandom RANDOM = new SecureRandom();

    private Secrets() {
    }

    static String roomCode() {
        StringBuilder sb = new StringBuilder(Protocol.CODE_LENGTH);
        for (int i = 0; i < Protocol.CODE_LENGTH; i++) {
            sb.append(Protocol.CODE_ALPHABET.charAt(RANDOM.nextInt(Protocol.CODE_ALPHABET.length())));
        }
        return sb.toString();
    }

    static String token() {
        byte[] b = new byte[16];
        RANDOM.nextBytes(b);
        return Base64.getUrlEncoder().withoutPadding().encodeToString(b);
    }

    static String hash(String token) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(token.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this Java", e);
        }
    }

    /** Whether {@code token} is the one whose hash is {@code hash}, in time independent of where they differ. */
    static boolean matches(String token, String hash) {
        return hash != null && MessageDigest.isEqual(hash(token).getBytes(StandardCharsets.US_ASCII),
                hash.getBytes(StandardCharsets.US_ASCII));
    }
}
