package minigolf.online.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import minigolf.online.ClientMessage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The server's web page in a real headless browser (Debian's Chromium; CI's .ci/online.sh installs
 * it and names it in MINIGOLF_TEST_CHROMIUM): the rooms and their live scorecards after the page's
 * own script has refreshed them, names escaped, the leaderboard, and a phone-sized screenshot
 * (build/screenshots/online-page-phone.png).
 */
class WebPageBrowserTest {
    @TempDir
    Path dir;

    static Path chromium() {
        String named = System.getenv("MINIGOLF_TEST_CHROMIUM");
        for (String c : new String[]{named, "/usr/bin/chromium", "/usr/bin/chromium-browser"}) {
            if (c != null && !c.isBlank() && Files.isExecutable(Path.of(c))) return Path.of(c);
        }
        if ("1".equals(System.getenv("MINIGOLF_TEST_REQUIRE"))) throw new AssertionError("no Chromium found (MINIGOLF_TEST_REQUIRE=1)");
        return null;
    }

    /** Chromium headless with the flags for a machine without network or GPU, a fresh profile. */
    private String browser(Path chromium, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(chromium.toString(), "--headless", "--no-sandbox", "--disable-gpu",
                "--disable-quic", "--no-first-run", "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--user-data-dir=" + Files.createTempDirectory(dir, "profile")));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectError(dir.resolve("chromium.err").toFile()).start();
        byte[] out = p.getInputStream().readAllBytes();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "chromium did not finish");
        return new String(out, StandardCharsets.UTF_8);
    }

    @Test
    void theRoomsAndTheLeaderboardShowInARealBrowser() throws Exception {
        Path chromium = chromium();
        assumeTrue(chromium != null, "no Chromium here (CI's .ci/online.sh installs Debian's)");
        try (GameServer server = TestServers.start(dir.resolve("s.db").toString());
             TestClient eve = TestClient.to(server); TestClient bob = TestClient.to(server)) {
            eve.send(new ClientMessage.Create("<b>Eve</b>", "flat", 2, List.of(), true, 10));
            String code = eve.await("joined").get("room").asText();
            bob.send(new ClientMessage.Join(code, "Bob"));
            eve.awaitState(() -> "playing".equals(eve.mirror.status()), "the start");
            eve.putt(0.5, 0);
            bob.putt(0.6, 0);
            // A private room is not listed.
            try (TestClient hidden = TestClient.to(server)) {
                hidden.send(new ClientMessage.Create("Hidden", "flat", 2, List.of(), false, 10));
                String secret = hidden.await("joined").get("room").asText();

                String base = "http://127.0.0.1:" + server.port();
                String dom = browser(chromium, "--virtual-time-budget=8000", "--dump-dom", base + "/");
                assertTrue(dom.contains(code), dom);
                assertFalse(dom.contains(secret), "a private room is not on the page");
                assertTrue(dom.contains("&lt;b&gt;Eve&lt;/b&gt;"), "the name is shown as typed, not as markup: " + dom);
                assertFalse(dom.contains("<b>Eve</b>"), dom);
                assertTrue(dom.contains("Bob"), dom);
                Matcher refreshed = Pattern.compile("data-refreshed=\"(\\d+)\"").matcher(dom);
                assertTrue(refreshed.find() && Integer.parseInt(refreshed.group(1)) >= 1, "the page's script refreshed the rooms");
                assertTrue(dom.contains("hole 1 of 1"), dom);
                assertTrue(dom.contains("name=\"viewport\""), "readable on a phone: " + dom);

                Path shots = Path.of(System.getProperty("minigolf.projectDir", "."), "build", "screenshots");
                Files.createDirectories(shots);
                Path phone = shots.resolve("online-page-phone.png");
                Files.deleteIfExists(phone);
                browser(chromium, "--virtual-time-budget=4000", "--window-size=390,844", "--hide-scrollbars",
                        "--screenshot=" + phone, base + "/");
                assertTrue(Files.size(phone) > 5000, "a screenshot of the page at a phone's width");
            }
            // Eve and Bob finish the hole (picking up at the limit): the leaderboard lists them.
            for (TestClient next; (next = TestClient.whoseTurn(eve, bob)) != null; ) next.putt(0.2, 0);
            String board = browser(chromium, "--virtual-time-budget=3000", "--dump-dom",
                    "http://127.0.0.1:" + server.port() + "/course/flat");
            assertTrue(board.contains("Leaderboard: flat"), board);
            assertTrue(board.contains("&lt;b&gt;Eve&lt;/b&gt;") && board.contains("Bob"), board);
            assertEquals(2, board.split("<td>11</td>", -1).length - 1, "both picked up at the limit of 10: 11 strokes: " + board);
        }
    }
}
