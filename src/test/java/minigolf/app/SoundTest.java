package minigolf.app;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import minigolf.app.SoundSynth.Sound;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The sounds: synthesised as intended, and really played. The game runs in its own process with
 * OpenAL Soft's {@code wave} driver (ALSOFT_CONF), which writes everything played to a WAV file;
 * a scripted putt must put non-silent samples there, starting when the putt is hit.
 */
class SoundTest {
    @TempDir
    Path dir;

    private static double seconds(short[] s) {
        return s.length / (double) SoundSynth.RATE;
    }

    private static int peak(short[] s) {
        int p = 0;
        for (short v : s) p = Math.max(p, Math.abs(v));
        return p;
    }

    @Test
    void everySoundIsSynthesisedTheSameEveryTime() {
        for (Sound s : Sound.values()) {
            short[] a = SoundSynth.make(s), b = SoundSynth.make(s);
            assertArrayEquals(a, b, s + " is deterministic");
            assertEquals(Math.round(0.9 * Short.MAX_VALUE), peak(a), 1, s + " is normalised to 0.9");
        }
        assertTrue(seconds(SoundSynth.make(Sound.PUTT)) < 0.2, "a putt is a click");
        short[] putt = SoundSynth.make(Sound.PUTT);
        int loudAt = 0;
        while (Math.abs(putt[loudAt]) < 3000) loudAt++;
        assertTrue(loudAt < SoundSynth.RATE / 1000, "the putt is loud within 1 ms, got sample " + loudAt);
        assertTrue(seconds(SoundSynth.make(Sound.APPLAUSE)) >= 2.5, "applause lasts");
        short[] amb = SoundSynth.make(Sound.AMBIENCE);
        // Looped without a click: the jump from the last sample to the first is like a step inside it.
        int seam = Math.abs(amb[amb.length - 1] - amb[0]), typical = 0;
        for (int i = 1; i < amb.length; i++) typical = Math.max(typical, Math.abs(amb[i] - amb[i - 1]));
        assertTrue(seam <= typical, "seam " + seam + " vs largest step " + typical);
    }

    /** Each world's background loop: its own, deterministic, seamless, at the same peak; Meadowbrook's is the old one. */
    @Test
    void everyWorldHasItsOwnSeamlessAmbience() {
        assertArrayEquals(SoundSynth.make(Sound.AMBIENCE), SoundSynth.ambience(minigolf.theme.Theme.Ambience.BIRDS));
        java.util.List<short[]> loops = new java.util.ArrayList<>();
        for (minigolf.theme.Theme.Ambience a : new minigolf.theme.Theme.Ambience[]{minigolf.theme.Theme.Ambience.WAVES,
                minigolf.theme.Theme.Ambience.DESERT_WIND, minigolf.theme.Theme.Ambience.WINTER_WIND}) {
            short[] x = SoundSynth.ambience(a);
            assertArrayEquals(x, SoundSynth.ambience(a), a + " is deterministic");
            assertEquals(Math.round(0.9 * Short.MAX_VALUE), peak(x), 1, a + " peak");
            assertTrue(seconds(x) > 5.5 && seconds(x) < 6.1, a + " lasts " + seconds(x));
            int seam = Math.abs(x[x.length - 1] - x[0]), typical = 0;
            for (int i = 1; i < x.length; i++) typical = Math.max(typical, Math.abs(x[i] - x[i - 1]));
            assertTrue(seam <= typical, a + ": seam " + seam + " vs largest step " + typical);
            for (short[] other : loops) assertFalse(java.util.Arrays.equals(x, other), a + " differs");
            loops.add(x);
        }
        assertEquals(0, peak(SoundSynth.ambience(minigolf.theme.Theme.Ambience.NONE)));
    }

    @Test
    void theDeviceIsOnlyOpenedWhereThereIsSomethingToPlayTo() {
        assertNull(Sounds.reasonToStaySilent(Map.of(), false), "other systems: always try");
        assertNull(Sounds.reasonToStaySilent(Map.of("ALSOFT_CONF", "/x.conf"), true));
        if (!Files.exists(Path.of("/dev/snd"))) {
            assertEquals("no sound card or sound server", Sounds.reasonToStaySilent(Map.of("XDG_RUNTIME_DIR", dir.toString()), true));
        }
    }

    /** Mono or multi-channel samples of a WAV file as doubles in [-1, 1] (16-bit, 32-bit int or float; extensible too). */
    static double[] readWav(Path file, int[] rateOut) throws Exception {
        ByteBuffer b = ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals("RIFF", tag(b, 0));
        assertEquals("WAVE", tag(b, 8));
        int pos = 12, format = 0, channels = 0, bits = 0;
        while (pos + 8 <= b.limit()) {
            String id = tag(b, pos);
            int size = b.getInt(pos + 4);
            if (id.equals("fmt ")) {
                format = b.getShort(pos + 8) & 0xffff;
                channels = b.getShort(pos + 10);
                rateOut[0] = b.getInt(pos + 12);
                bits = b.getShort(pos + 22);
                if (format == 0xFFFE) format = b.getShort(pos + 8 + 24) & 0xffff; // WAVE_FORMAT_EXTENSIBLE: the sub-format GUID
            } else if (id.equals("data")) {
                int bytes = bits / 8, n = Math.min(size, b.limit() - pos - 8) / (bytes * channels);
                double[] out = new double[n];
                for (int i = 0; i < n; i++) {
                    int at = pos + 8 + i * bytes * channels; // the first channel
                    out[i] = format == 3 ? b.getFloat(at)
                            : bits == 16 ? b.getShort(at) / 32768.0
                            : bits == 32 ? b.getInt(at) / 2147483648.0
                            : ((b.get(at) & 0xff) - 128) / 128.0;
                }
                return out;
            }
            pos += 8 + size + (size & 1);
        }
        fail("no data chunk in " + file);
        return null;
    }

    private static String tag(ByteBuffer b, int at) {
        byte[] t = new byte[4];
        for (int i = 0; i < 4; i++) t[i] = b.get(at + i);
        return new String(t, java.nio.charset.StandardCharsets.US_ASCII);
    }

    /** The only one of these that opens a window: the synthesis and the device rule run without a display. */
    @Test
    @minigolf.render.NeedsDisplay
    void aScriptedPuttIsHeard() throws Exception {
        Path wav = dir.resolve("out.wav"), conf = dir.resolve("alsoft.conf"), config = Files.createDirectories(dir.resolve("config"));
        Files.writeString(conf, "[general]\ndrivers = wave\n[wave]\nfile = " + wav + "\n");
        Files.writeString(config.resolve("audio.json"), "{\"master\": 1, \"effects\": 1, \"ambience\": 0}");
        Path flat = Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "flat.json");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx512m", "-Dminigolf.configDir=" + config, "-cp", System.getProperty("java.class.path"), "minigolf.Main",
                "play", flat.toString(), "--players", "Ann", "--shots", "1.2:0", "--frames", "150"));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve("log.txt").toFile());
        pb.environment().put("ALSOFT_CONF", conf.toString());
        pb.environment().remove("WAYLAND_DISPLAY");
        Process p = pb.start();
        assertTrue(p.waitFor(240, TimeUnit.SECONDS), "the game finished");
        String log = Files.readString(dir.resolve("log.txt"));
        assertEquals(0, p.exitValue(), log);
        assertFalse(log.contains("no sound"), log);
        int[] rate = new int[1];
        double[] x = readWav(wav, rate);
        assertTrue(x.length > rate[0] / 2, "at least half a second written, got " + x.length + " samples");
        int first = -1;
        double peak = 0;
        for (int i = 0; i < x.length; i++) {
            if (first < 0 && Math.abs(x[i]) > 0.02) first = i;
            peak = Math.max(peak, Math.abs(x[i]));
        }
        assertTrue(first >= 0, "non-silent samples (peak " + peak + ")");
        // With the ambience off nothing sounds before the putt: the samples before the first loud one are silent,
        // and the putt's click is loud (over a tenth of full scale) within 20 ms of its start.
        for (int i = 0; i < first; i++) assertTrue(Math.abs(x[i]) < 0.02);
        double clickPeak = 0;
        for (int i = first; i < Math.min(x.length, first + rate[0] / 50); i++) clickPeak = Math.max(clickPeak, Math.abs(x[i]));
        assertTrue(clickPeak > 0.1, "the putt's click peaks at " + clickPeak);
    }
}
