package minigolf.classic;

/**
 * How a classic track's pixels and ticks become metres and seconds (docs/classic-tracks.md).
 *
 * <p>The original moves the ball in ticks: position += velocity (px/tick), then velocity *= f, with
 * f = a + (1 - a) * 0.75 * speed / 6.5 and a per element (grass 0.9935); the fastest shot is 6.5
 * px/tick and a ball slower than 0.075 px/tick stops. Lengths scale with the tile ({@code tile}
 * metres for 15 px); one tick is {@link #TICK} seconds at every scale, so speeds, friction and
 * pushes scale with the tile too and a track plays alike at any size. Our friction is Coulomb's
 * (constant deceleration μg), the original's falls with speed: μ is chosen so that the fastest shot
 * rolls as far as in the original (ln 4 / (0.75/6.5 · (1 - a)) px on an element).
 */
public record ClassicScale(double tile) {
    public static final double DEFAULT_TILE = 0.25;
    /** Seconds per tick: the fastest shot (6.5 px/tick) is 5 m/s at the default tile. */
    public static final double TICK = 6.5 * (DEFAULT_TILE / 15) / 5.0;
    public static final double GRAVITY = 9.81;
    /** The original's fastest shot, px/tick. */
    public static final double MAX_TICK_SPEED = 6.5;
    /** The original's push of a downhill tile, px/tick per tick. */
    public static final double DOWNHILL_PUSH = 0.025;
    /** The original's magnet: its reach (px) and pull per px inside the rim (px/tick² per px). */
    public static final double MAGNET_PIXELS = 127, MAGNET_PULL = 0.0005;
    /** The ball's diameter in pixels. */
    public static final double BALL_PIXELS = 13;
    /** Distance (in px, times (1 - a)) the fastest shot rolls: ln 4 / (0.75 / 6.5). */
    private static final double FULL_SHOT_ROLL = Math.log(4) / (0.75 / 6.5);

    public ClassicScale {
        if (!(tile > 0) || tile > 100) throw new IllegalArgumentException("the tile size must be in (0, 100] m, got " + tile);
    }

    public static ClassicScale standard() {
        return new ClassicScale(DEFAULT_TILE);
    }

    /** Metres per pixel. */
    public double pixel() {
        return tile / 15;
    }

    /** The fastest shot, m/s. */
    public double maxSpeed() {
        return MAX_TICK_SPEED * pixel() / TICK;
    }

    public double ballRadius() {
        return BALL_PIXELS / 2 * pixel();
    }

    /** Coulomb friction for an element whose per-tick factor is a (1 - a = {@code loss}). */
    public double friction(double loss) {
        if (loss <= 0) return 0;
        double v = maxSpeed();
        return v * v * loss / (2 * GRAVITY * FULL_SHOT_ROLL * pixel());
    }

    /** A downhill tile's push, m/s². */
    public double downhillPush() {
        return DOWNHILL_PUSH * pixel() / (TICK * TICK);
    }

    /**
     * The strength (m/s², {@link minigolf.course.Magnet}) of a magnet as deep as the original's:
     * the original pulls with 0.0005 (127 - d) px/tick² per px of distance d left to the rim,
     * split between the axes as (|cos|, 1 - |cos|) of the direction, (1/2 + 1/π) of that towards
     * the centre on average; a ball climbing out from the centre loses (1/2 + 1/π) 0.0005 127² / 2
     * px²/tick² of speed squared over two. Our magnet's profile (zero at the centre, strongest at R/3)
     * loses strength R 9/16 of it, so the two hold a ball alike (docs/classic-tracks.md).
     */
    public double magnetStrength() {
        double depth = (0.5 + 1 / Math.PI) * MAGNET_PULL * MAGNET_PIXELS * MAGNET_PIXELS / 2; // px²/tick²
        return depth / (MAGNET_PIXELS * 9.0 / 16) * pixel() / (TICK * TICK);
    }

    public double width() {
        return TileMap.WIDTH * tile;
    }

    public double height() {
        return TileMap.HEIGHT * tile;
    }
}
