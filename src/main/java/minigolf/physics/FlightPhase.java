package minigolf.physics;


/**
 * The flying pieces of a stroke: a step of {@link FlightStep}, cut where the ball comes down
 * (located by bisection) or meets an obstacle (swept in 3-D), then the landing: out, water, the
 * hole, or a bounce or a settling into rolling ({@link GroundImpact}).
 */
final class FlightPhase {
    private final BallState ball;
    private final StrokeReports reports;
    private final FlightStep flight;
    private final GroundImpact impact;
    private final HoleRules hole;
    private final RestRule rest;
    private final PlayArea area;
    /** The obstacles; null without them. */
    private final Solids scene;
    private final PathSweep paths;
    private final ObstacleContact contact;
    private final double ballRadius;
    /** The longest flying step: the base step dt (a flight's landing is looked for at each step's end). */
    private final double dt;
    private final double maxTime;
    // The state a flight sub-step produced.
    private double fx, fy, fz, fvx, fvy, fvz;

    FlightPhase(BallState ball, StrokeReports reports, FlightStep flight, GroundImpact impact, HoleRules hole,
                RestRule rest, PlayArea area, Solids scene, PathSweep paths, ObstacleContact contact,
                double ballRadius, double dt, double maxTime) {
        this.ball = ball;
        this.reports = reports;
        this.flight = flight;
        this.impact = impact;
        this.hole = hole;
        this.rest = rest;
        this.area = area;
        this.scene = scene;
        this.paths = paths;
        this.contact = contact;
        this.ballRadius = ballRadius;
        this.dt = dt;
        this.maxTime = maxTime;
    }

    /** One flying piece of at most tau seconds (and at most dt); returns the time it took. */
    double piece(double tau) {
        BallState b = ball;
        if (b.t >= maxTime) {
            reports.finish(Outcome.TIMEOUT, b.x, b.y, b.z);
            return 0;
        }
        boolean cut = tau > Math.min(dt, maxTime - b.t);
        if (cut) tau = Math.min(dt, maxTime - b.t);
        advance(tau);
        if (!Double.isFinite(fx + fy + fz + fvx + fvy + fvz)) throw NonFiniteMotionException.motion(b.x, b.y);
        double endTau = tau;
        boolean lands = false;
        if (fz < flight.groundAt(fx, fy)) {
            flight.from(b.x, b.y, b.z, b.vx, b.vy, b.vz);
            endTau = flight.locateLanding(tau);
            advance(endTau);
            lands = true;
        }
        boolean collided = false;
        if (scene != null) {
            double r = ballRadius;
            if (paths.sweep(b.x, b.y, b.z + r, b.vx, b.vy, b.vz, fx, fy, fz + r, fvx, fvy, fvz, endTau, false)) {
                endTau *= paths.contactAt;
                advance(endTau);
                fx = paths.contactX;
                fy = paths.contactY;
                fz = paths.contactZ - r;
                lands = false;
                collided = true;
            }
        }
        b.x = fx;
        b.y = fy;
        b.z = fz;
        b.vx = fvx;
        b.vy = fvy;
        b.vz = fvz;
        b.t += endTau;
        b.steps++;
        if (collided) {
            contact.inFlight();
            b.resume = b.outcome == null;
        } else if (lands) {
            land();
        }
        if (b.outcome == null) reports.state();
        if (cut && !b.resume && b.outcome == null) {
            // The rest of a long step that began rolling: no contact, so no count towards a wedge.
            b.resume = true;
            b.subPiece = true;
        }
        return endTau;
    }

    /**
     * The ball reaches the ground. Water or outside the bounds ends the stroke; so does the hole
     * ({@link HoleRules#dropsOnLanding}). Otherwise it bounces or settles into rolling.
     */
    private void land() {
        BallState b = ball;
        if (!area.contains(b.x, b.y)) {
            reports.finish(Outcome.OUT, b.x, b.y, b.z);
            return;
        }
        b.sampleGround();
        if (b.h < 0 || b.entersHazard()) {
            b.z = b.h < 0 ? 0 : b.h;
            reports.finish(Outcome.WATER, b.x, b.y, b.z);
            return;
        }
        b.z = b.h;
        double horizontal = Math.sqrt(b.vx * b.vx + b.vy * b.vy);
        if (hole.dropsOnLanding(b.x, b.y, horizontal)) {
            reports.finish(Outcome.HOLED, b.x, b.y, b.z);
            return;
        }
        impact.impact(b.vx, b.vy, b.vz, b.hx, b.hy);
        b.vx = impact.vx;
        b.vy = impact.vy;
        b.vz = impact.vz;
        if (impact.settles) {
            b.flying = false;
            rest.forget();
            reports.event(StrokeEvent.Type.LAND, impact.before, impact.after);
        } else {
            reports.event(StrokeEvent.Type.BOUNCE, impact.before, impact.after);
        }
        b.resume = true;
    }

    /** A flight sub-step of length tau from the ball's state into f*. */
    private void advance(double tau) {
        flight.from(ball.x, ball.y, ball.z, ball.vx, ball.vy, ball.vz);
        flight.advance(tau);
        fx = flight.fx;
        fy = flight.fy;
        fz = flight.fz;
        fvx = flight.fvx;
        fvy = flight.fvy;
        fvz = flight.fvz;
    }
}
