package minigolf.app;

import minigolf.theme.Theme;

import java.util.Random;

/**
 * The game's sounds, synthesised (no sound files): 16-bit mono PCM at {@link #RATE} Hz. Each sound
 * is a few damped sines and filtered noise shaped by an envelope; every random part has a fixed
 * seed, so the same sound comes out every time. Plain Java, tested without an audio device.
 */
public final class SoundSynth {
    public static final int RATE = 44_100;

    /** What the game plays. */
    public enum Sound {
        /** The putter hitting the ball (played louder for a harder putt). */
        PUTT,
        /** The ball hitting a wall, a box, a tree or the windmill. */
        KNOCK,
        /** The ball landing after a hop. */
        THUD,
        /** The ball going into water. */
        SPLASH,
        /** The ball dropping into the cup. */
        CUP,
        /** A hole in one. */
        APPLAUSE,
        /** Quiet wind and the odd bird, looped (Meadowbrook's; each world has its own: {@link #ambience(Theme.Ambience)}). */
        AMBIENCE
    }

    /**
     * A world's background loop (about six seconds, seamless): Meadowbrook's wind and birds, the
     * seaside's surf and gulls, the canyon's dry wind whistling over rock, winter's hissing gusts
     * and a far-off bell; silence for {@link Theme.Ambience#NONE}.
     */
    public static short[] ambience(Theme.Ambience a) {
        return switch (a) {
            case BIRDS -> ambience();
            case WAVES -> loop(waves());
            case DESERT_WIND -> loop(desertWind());
            case WINTER_WIND -> loop(winterWind());
            case NONE -> new short[RATE];
        };
    }

    /** Surf: noise swelling and breaking every few seconds, low-passed, with two gull cries. */
    private static float[] waves() {
        int n = 6 * RATE;
        float[] out = new float[n];
        Random r = new Random(11);
        double lo = 0, lo2 = 0;
        for (int i = 0; i < n; i++) {
            double t = i / (double) RATE;
            lo += 0.05 * ((r.nextDouble() * 2 - 1) - lo);
            lo2 += 0.05 * (lo - lo2);
            // Two breakers in the loop: a quick rise, then a long hiss as the water runs back.
            double phase = (t % 3.0) / 3.0;
            double swell = phase < 0.15 ? phase / 0.15 : Math.exp(-(phase - 0.15) * 3.2);
            out[i] = (float) (2.2 * lo2 * (0.25 + 0.75 * swell) + 0.25 * lo * swell);
        }
        for (double t0 : new double[]{1.7, 4.4}) { // a gull: a falling, wavering cry
            int start = (int) (t0 * RATE);
            for (int i = 0; i < 0.35 * RATE; i++) {
                double t = i / (double) RATE, f = 1900 - 1400 * t + 120 * Math.sin(2 * Math.PI * 14 * t);
                out[start + i] += (float) (0.035 * Math.sin(2 * Math.PI * f * t) * Math.sin(Math.PI * t / 0.35));
            }
        }
        return out;
    }

    /** Dry wind: low rumbling noise with a hollow whistle that rises and falls with the gusts. */
    private static float[] desertWind() {
        int n = 6 * RATE;
        float[] out = new float[n];
        Random r = new Random(23);
        double lo = 0, lo2 = 0, bp = 0, bpv = 0;
        for (int i = 0; i < n; i++) {
            double t = i / (double) RATE;
            double noise = r.nextDouble() * 2 - 1;
            lo += 0.01 * (noise - lo);
            lo2 += 0.01 * (lo - lo2);
            double gust = 0.55 + 0.45 * Math.sin(2 * Math.PI * t / 6.0) * Math.sin(2 * Math.PI * t / 3.0);
            // A resonator (two-pole band-pass) near 420 Hz gliding with the gust: the whistle over rock.
            double f = 380 + 80 * gust, w = 2 * Math.PI * f / RATE;
            bpv += w * (noise * 0.02 - bp) - 0.004 * bpv;
            bp += w * bpv;
            out[i] = (float) (3.0 * lo2 * gust + 0.8 * bp * gust * gust);
        }
        return out;
    }

    /** Winter wind: a brighter hiss in gusts, and a church bell far away once in the loop. */
    private static float[] winterWind() {
        int n = 6 * RATE;
        float[] out = new float[n];
        Random r = new Random(37);
        double lo = 0, hi = 0, prev = 0;
        for (int i = 0; i < n; i++) {
            double t = i / (double) RATE;
            double noise = r.nextDouble() * 2 - 1;
            lo += 0.06 * (noise - lo);
            hi = 0.9 * (hi + noise - prev); // a high-pass for the hiss
            prev = noise;
            double gust = 0.4 + 0.6 * Math.pow(Math.sin(Math.PI * t / 6.0), 2);
            out[i] = (float) ((1.2 * lo + 0.08 * hi) * gust);
        }
        for (double f : new double[]{392, 784, 1176, 940}) ping(out, 2.5, f, 0.02 / Math.sqrt(f / 392), 1.4);
        return out;
    }

    /** Cross-fades the end into the start (a seamless loop) and converts to samples at a quiet peak. */
    private static short[] loop(float[] out) {
        int n = out.length, fade = RATE / 10;
        for (int i = 0; i < fade; i++) {
            double w = i / (double) fade;
            out[i] = (float) (out[i] * w + out[n - fade + i] * (1 - w));
        }
        float[] looped = new float[n - fade];
        System.arraycopy(out, 0, looped, 0, n - fade);
        return pcm(looped);
    }

    private SoundSynth() {
    }

    public static short[] make(Sound s) {
        return switch (s) {
            case PUTT -> putt();
            case KNOCK -> knock();
            case THUD -> thud();
            case SPLASH -> splash();
            case CUP -> cup();
            case APPLAUSE -> applause();
            case AMBIENCE -> ambience();
        };
    }

    private static float[] buffer(double seconds) {
        return new float[(int) Math.round(seconds * RATE)];
    }

    /** Adds a sine of frequency f starting at t0 with amplitude a, decaying with time constant tau. */
    private static void ping(float[] out, double t0, double f, double a, double tau) {
        int start = (int) (t0 * RATE);
        for (int i = start; i < out.length; i++) {
            double t = (i - start) / (double) RATE;
            double env = Math.exp(-t / tau) * Math.min(1, t * RATE / 16.0); // 16-sample attack: no click
            if (env < 1e-4 && t > tau) break;
            out[i] += (float) (a * env * Math.sin(2 * Math.PI * f * t));
        }
    }

    /** Adds low-passed noise (one-pole, coefficient k: smaller is darker) with an exponential decay. */
    private static void noise(float[] out, Random r, double t0, double a, double tau, double k) {
        int start = (int) (t0 * RATE);
        double y = 0;
        for (int i = start; i < out.length; i++) {
            double t = (i - start) / (double) RATE;
            y += k * ((r.nextDouble() * 2 - 1) - y);
            out[i] += (float) (a * y * Math.exp(-t / tau) * Math.min(1, t * RATE / 16.0));
        }
    }

    private static short[] putt() {
        float[] out = buffer(0.18);
        Random r = new Random(1);
        noise(out, r, 0, 0.9, 0.006, 0.9);
        ping(out, 0, 1850, 0.5, 0.025);
        ping(out, 0, 3100, 0.25, 0.012);
        return pcm(out);
    }

    private static short[] knock() {
        float[] out = buffer(0.15);
        Random r = new Random(2);
        noise(out, r, 0, 0.6, 0.008, 0.5);
        ping(out, 0, 620, 0.6, 0.03);
        ping(out, 0, 1340, 0.25, 0.015);
        return pcm(out);
    }

    private static short[] thud() {
        float[] out = buffer(0.2);
        Random r = new Random(3);
        noise(out, r, 0, 0.5, 0.02, 0.08);
        ping(out, 0, 140, 0.6, 0.05);
        return pcm(out);
    }

    private static short[] splash() {
        float[] out = buffer(0.9);
        Random r = new Random(4);
        noise(out, r, 0, 0.9, 0.18, 0.35);
        for (int b = 0; b < 14; b++) ping(out, 0.05 + r.nextDouble() * 0.5, 500 + r.nextDouble() * 900, 0.12, 0.03);
        return pcm(out);
    }

    private static short[] cup() {
        float[] out = buffer(0.5);
        Random r = new Random(5);
        double t = 0;
        for (int k = 0; k < 4; k++) { // the ball rattling down the cup: faster, softer clicks
            noise(out, r, t, 0.5 / (k + 1), 0.004, 0.7);
            ping(out, t, 900 + 80 * k, 0.4 / (k + 1), 0.04);
            t += 0.07 / (k + 1);
        }
        ping(out, t, 420, 0.5, 0.08); // and landing on the bottom
        return pcm(out);
    }

    private static short[] applause() {
        float[] out = buffer(3.0);
        Random r = new Random(6);
        for (int c = 0; c < 420; c++) {
            double t0 = Math.pow(r.nextDouble(), 1.6) * 2.6; // denser at first, then dying away
            noise(out, r, t0, 0.25 * (1 - t0 / 3.0), 0.004 + r.nextDouble() * 0.004, 0.6 + 0.3 * r.nextDouble());
        }
        return pcm(out);
    }

    private static short[] ambience() {
        int n = 6 * RATE;
        float[] out = new float[n];
        Random r = new Random(7);
        double y = 0, y2 = 0;
        for (int i = 0; i < n; i++) { // wind: twice low-passed noise, swelling slowly
            y += 0.02 * ((r.nextDouble() * 2 - 1) - y);
            y2 += 0.02 * (y - y2);
            double swell = 0.6 + 0.4 * Math.sin(2 * Math.PI * i / n);
            out[i] = (float) (2.5 * y2 * swell);
        }
        for (double t : new double[]{1.1, 1.25, 3.9}) { // a bird: two falling chirps
            int start = (int) (t * RATE);
            for (int i = 0; i < 0.09 * RATE; i++) {
                double tt = i / (double) RATE, f = 3600 - 9000 * tt;
                out[start + i] += (float) (0.05 * Math.sin(2 * Math.PI * f * tt) * Math.sin(Math.PI * tt / 0.09));
            }
        }
        int fade = RATE / 10; // the loop's seam: cross-fade the end into the start
        for (int i = 0; i < fade; i++) {
            double w = i / (double) fade;
            out[i] = (float) (out[i] * w + out[n - fade + i] * (1 - w));
        }
        float[] looped = new float[n - fade];
        System.arraycopy(out, 0, looped, 0, n - fade);
        return pcm(looped);
    }

    /** Scales to a peak of 0.9 and converts to 16-bit samples. */
    private static short[] pcm(float[] x) {
        float peak = 1e-9f;
        for (float v : x) peak = Math.max(peak, Math.abs(v));
        short[] out = new short[x.length];
        for (int i = 0; i < x.length; i++) out[i] = (short) Math.round(x[i] / peak * 0.9 * Short.MAX_VALUE);
        return out;
    }
}
