package minigolf.theme;

/** A linear colour, each channel 0..1 (values above 1 are allowed for lights). */
public record Rgb(float r, float g, float b) {
    public static Rgb of(double r, double g, double b) {
        return new Rgb((float) r, (float) g, (float) b);
    }

    /** From a hex triple such as 0x7FB24C. */
    public static Rgb hex(int rgb) {
        return of(((rgb >> 16) & 0xFF) / 255.0, ((rgb >> 8) & 0xFF) / 255.0, (rgb & 0xFF) / 255.0);
    }

    public float[] toArray() {
        return new float[]{r, g, b};
    }

    public Rgb times(double k) {
        return of(r * k, g * k, b * k);
    }

    /** This colour towards {@code o} by t (0: this, 1: o). */
    public Rgb mix(Rgb o, double t) {
        return of(r + (o.r - r) * t, g + (o.g - g) * t, b + (o.b - b) * t);
    }
}
