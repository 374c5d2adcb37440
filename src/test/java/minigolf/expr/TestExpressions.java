package minigolf.expr;

import java.util.List;
import java.util.Random;

/** The expressions several tests check, each with a box of (x, y) where it is smooth. */
final class TestExpressions {
    static final String LAKE = "0.4*(0.9-exp(-(x^2+y^2)/8))";

    record Case(String source, double minX, double maxX, double minY, double maxY) {
        double[] randomPoint(Random random) {
            return new double[] {minX + (maxX - minX) * random.nextDouble(), minY + (maxY - minY) * random.nextDouble()};
        }

        @Override
        public String toString() {
            return source;
        }
    }

    static final List<Case> SMOOTH = List.of(
            new Case(LAKE, -6, 6, -6, 6),
            new Case("0.1*sin(x)*cos(y)", -5, 5, -5, 5),
            new Case("atan2(y,x+10)", -5, 5, -5, 5),
            new Case("abs(x-0.3)", -3, 3, -3, 3),
            new Case("max(x,y)", -3, 3, -3, 3),
            new Case("min(x*y,1)", -3, 3, -3, 3),
            new Case("pow(x+5,1.5)", -3, 3, -3, 3),
            new Case("sqrt(x^2+y^2+1)", -3, 3, -3, 3),
            new Case("log(x^2+2)", -3, 3, -3, 3),
            new Case("tan(0.2*x)", -3, 3, -3, 3),
            new Case("asin(0.1*x)", -3, 3, -3, 3),
            new Case("acos(0.1*y)", -3, 3, -3, 3),
            new Case("atan(x*y)", -3, 3, -3, 3),
            new Case("x^y", 0.2, 3, -2, 2),
            new Case("2^(x*y) - 3^-y", -2, 2, -2, 2),
            new Case("x^3 - 2*x*y^2 + y^4/(1+x^2)", -2, 2, -2, 2),
            new Case("x^-2 + y^-1", 0.5, 3, 0.5, 3),
            new Case("exp(sin(x)*cos(y)) / (2 + cos(x*y))", -3, 3, -3, 3),
            new Case("-(x-1)^2 + -y", -3, 3, -3, 3),
            new Case("0.05*(x^2 - y^2) + 0.01*x*y", -6, 6, -6, 6));

    /** Points kept this far from abs/min/max kinks, where the derivative jumps. */
    static boolean nearKink(Case c, double x, double y) {
        switch (c.source()) {
            case "abs(x-0.3)":
                return Math.abs(x - 0.3) < 1e-3;
            case "max(x,y)":
                return Math.abs(x - y) < 1e-3;
            case "min(x*y,1)":
                return Math.abs(x * y - 1) < 1e-3;
            default:
                return false;
        }
    }

    private TestExpressions() {
    }
}
