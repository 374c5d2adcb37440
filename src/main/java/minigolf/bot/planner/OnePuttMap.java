package minigolf.bot.planner;

import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;
import java.util.ArrayList;
import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsSettings;
import minigolf.physics.StrokeEvent;
import minigolf.physics.TrajectoryListener;
import minigolf.physics.World;

/**
 * Where one putt may hole from, found backwards: rays from the hole all round at the maximum
 * speed ({@link #RAYS} of them), their paths traced through the real walls, banks and gaps. On
 * flat ground a ball's path does not depend on its speed, so a putt from a point of a ray's path
 * along the reversed direction follows the ray back to the hole: exactly before the ray's first
 * cushion, nearly after it (the restitution turns a reversed bounce a little differently). Each
 * cell of a 0.1 m grid keeps the easiest putt a ray gives it (fewest cushions, then shortest) and
 * the putt's speed guess from the ray's energy: v² = v0² - v² there - 4 g (h there - h hole) (the
 * work done on the way, with the height difference turned round). On hills the map is a guess
 * that the look-ahead's Broyden corrects. Built once per course (it depends on the hole only).
 */
final class OnePuttMap {
    static final int RAYS = 720;
    static final double CELL = 0.1;
    /** A cushion counts as this many metres of putt when cells compare their putts. */
    static final double CUSHION_COST = 1.5;
    /** Putts with more cushions than this are not kept. */
    static final int MAX_CUSHIONS = 4;
    /** The rays' speed, a multiple of the course's limit (see {@link #faster}). */
    static final double RAY_SPEED = 1.6;
    /** The rays bounce with the inverse of each obstacle's restitution, at most this. */
    static final double MAX_INVERSE_RESTITUTION = 4;
    /** The ray world's speed limit, per the course's: no bounce there is ever capped. */
    private static final double UNCAPPED = 1e6;

    private final double minX, minY;
    private final int cols, rows;
    /** Per cell: the putt's cost (NaN: none), direction, speed guess, cushions. */
    private final double[] cost, ux, uy, speed;
    private final int[] cushions;
    private final long simulations;
    private double maxSpeed;

    private OnePuttMap(Bounds b) {
        minX = b.minX();
        minY = b.minY();
        cols = Math.max(1, (int) Math.ceil(b.width() / CELL));
        rows = Math.max(1, (int) Math.ceil(b.depth() / CELL));
        int n = cols * rows;
        cost = new double[n];
        java.util.Arrays.fill(cost, Double.NaN);
        ux = new double[n];
        uy = new double[n];
        speed = new double[n];
        cushions = new int[n];
        simulations = RAYS;
    }

    /** Traces the rays on {@code sim} (RAYS simulations). */
    static OnePuttMap build(CountingSimulator sim) {
        World w = sim.world();
        OnePuttMap map = new OnePuttMap(w.bounds());
        double hx = w.hole().position().x(), hy = w.hole().position().y();
        double hh = w.terrain().height(hx, hy), g = w.physics().gravity();
        CountingSimulator fast = sim.variant(faster(w), false);
        double v0 = RAY_SPEED * sim.maxSpeed() * (1 - 1e-9);
        map.maxSpeed = sim.maxSpeed();
        for (int i = 0; i < RAYS; i++) {
            double a = 2 * Math.PI * i / RAYS;
            Ray ray = map.new Ray(hx, hy, v0, hh, g, w);
            fast.simulate(hx, hy, Shot.polar(a, v0), ray);
        }
        return map;
    }

    /**
     * The world with a higher speed limit ({@link #RAY_SPEED}) and the rest rule: a ray slows at a
     * cushion by a fraction of its speed there, and it is faster there than the putt it stands for,
     * so a ray at the putt's own limit stops short of places a maximum-speed putt holes from.
     */
    static World faster(World w) {
        Course c = w.course();
        PhysicsSettings p = c.physics();
        // The rays are shot at RAY_SPEED times the course's limit; the world's own limit is far above
        // it, so that the bounce cap of bumpers (docs/course-format.md) never binds on the inverse
        // restitutions above 1 that trace the rays backwards.
        PhysicsSettings quick = new PhysicsSettings(p.gravity(), p.kineticFriction(), p.staticFriction(),
                UNCAPPED * p.maxSpeed(), p.model(), p.ballRadius(), p.ballMass(), p.dragCoefficient(), p.airDensity(),
                p.groundRestitution(), p.puttsOnly());
        Hole h = c.hole();
        List<Obstacle> inverse = new ArrayList<>();
        for (Obstacle o : c.obstacles()) {
            double e = Math.min(1 / Math.max(o.restitution(), 1e-3), MAX_INVERSE_RESTITUTION);
            if (o instanceof Obstacle.Wall x) {
                inverse.add(new Obstacle.Wall(x.from(), x.to(), x.thickness(), x.height(), e));
            } else if (o instanceof Obstacle.Tree x) {
                inverse.add(new Obstacle.Tree(x.position(), x.radius(), x.height(), e));
            } else if (o instanceof Obstacle.Box x) {
                inverse.add(new Obstacle.Box(x.min(), x.max(), x.rotationDeg(), e));
            } else if (o instanceof Obstacle.Model x) {
                inverse.add(new Obstacle.Model(x.file(), x.position(), x.rotationDeg(), x.scale(), e, x.mesh()));
            }
        }
        Course course = new Course(c.format(), c.name(), c.terrain(), c.bounds(), quick, c.start(),
                new Hole(h.position(), h.radius(), HoleRule.REST, null), c.zones(), inverse);
        return new World(course, w.terrain());
    }

    long simulations() {
        return simulations;
    }

    private int index(double x, double y) {
        int c = (int) Math.floor((x - minX) / CELL), r = (int) Math.floor((y - minY) / CELL);
        if (c < 0 || r < 0 || c >= cols || r >= rows) return -1;
        return r * cols + c;
    }

    /**
     * The cell of (x, y) if a ray marked it, else the cheapest marked cell round it (rays fan out
     * after a cushion and leave single cells between them unmarked), else -1.
     */
    private int lookup(double x, double y) {
        int i = index(x, y);
        if (i < 0) return -1;
        if (!Double.isNaN(cost[i])) return i;
        int c = i % cols, r = i / cols, best = -1;
        for (int dc = -1; dc <= 1; dc++) {
            for (int dr = -1; dr <= 1; dr++) {
                int cc = c + dc, rr = r + dr;
                if (cc < 0 || rr < 0 || cc >= cols || rr >= rows) continue;
                int j = rr * cols + cc;
                if (!Double.isNaN(cost[j]) && (best < 0 || cost[j] < cost[best])) best = j;
            }
        }
        return best;
    }

    /** Whether a ray marked the cell of (x, y) or one next to it. */
    boolean marked(double x, double y) {
        return lookup(x, y) >= 0;
    }

    /** The putt's cost at (x, y) (metres, cushions counted), or +infinity. */
    double cost(double x, double y) {
        int i = lookup(x, y);
        return i < 0 ? Double.POSITIVE_INFINITY : cost[i];
    }

    /** The cushions of the putt at (x, y); -1 when none is marked. */
    int cushions(double x, double y) {
        int i = lookup(x, y);
        return i < 0 ? -1 : cushions[i];
    }

    /** How many of the 3 x 3 cells round (x, y) a ray marked itself: a landing there forgives a small error. */
    int markedAround(double x, double y) {
        int n = 0;
        for (int dx = -1; dx <= 1; dx++) {
            for (int dy = -1; dy <= 1; dy++) {
                int i = index(x + dx * CELL, y + dy * CELL);
                if (i >= 0 && !Double.isNaN(cost[i])) n++;
            }
        }
        return n;
    }

    /** The map's putt from (x, y): back along the ray at the guessed speed; null when unmarked. */
    Shot putt(double x, double y) {
        int i = lookup(x, y);
        if (i < 0) return null;
        return Shot.polar(Math.atan2(uy[i], ux[i]), speed[i]);
    }

    /**
     * Follows one ray from the hole: its travelled length, cushions, and the speed² a putt from
     * each point back along it needs, worked out backwards from the hole (a putt that arrives at
     * rest): each metre adds 2 g (mu_k - the rise towards the hole), each cushion divides by the
     * square of the ray's speed ratio there (the putt bounces at nearly the reversed angle).
     */
    private final class Ray implements TrajectoryListener {
        private final double g;
        private final World w;
        private double lastX, lastY, lastH, length, need;
        private int hits;

        Ray(double x, double y, double v0, double hh, double g, World w) {
            this.lastX = x;
            this.lastY = y;
            this.lastH = hh;
            this.g = g;
            this.w = w;
        }

        @Override
        public void onStep(double t, double x, double y, double vx, double vy) {
            double ds = Math.hypot(x - lastX, y - lastY);
            double h = w.terrain().height(x, y);
            length += ds;
            need += 2 * g * (w.friction().kinetic(x, y) * ds - (h - lastH));
            lastX = x;
            lastY = y;
            lastH = h;
            double v = Math.hypot(vx, vy);
            if (hits > MAX_CUSHIONS || v < 1e-6) return;
            int i = index(x, y);
            if (i < 0) return;
            double c = length + CUSHION_COST * hits;
            if (!Double.isNaN(cost[i]) && cost[i] <= c) return;
            double v2 = Math.max(need, 0.01);
            if (v2 > maxSpeed * maxSpeed) return;
            cost[i] = c;
            ux[i] = -vx / v;
            uy[i] = -vy / v;
            speed[i] = Math.sqrt(v2);
            cushions[i] = hits;
        }

        @Override
        public void onEvent(StrokeEvent event) {
            if (event.type() != StrokeEvent.Type.COLLISION) return;
            hits++;
            double r = event.speedAfter() / Math.max(event.speedBefore(), 1e-9);
            need *= r * r;
        }
    }
}
