package minigolf.expr;

/**
 * Semantics of a power whose exponent is a constant. Small integer exponents are multiplications:
 * several times faster than Math.pow, correctly rounded for squares, and they keep x^2 well
 * defined for negative x. The evaluator and the compiled code both follow these rules.
 */
final class Powers {
    private Powers() {
    }

    /** True when {@link #constantPower} multiplies instead of calling Math.pow. */
    static boolean isMultiplication(double exponent) {
        return exponent == 2 || exponent == 3 || exponent == 4 || exponent == -1 || exponent == -2;
    }

    static double constantPower(double base, double exponent) {
        if (exponent == 2) {
            return base * base;
        }
        if (exponent == 3) {
            return base * base * base;
        }
        if (exponent == 4) {
            double square = base * base;
            return square * square;
        }
        if (exponent == -1) {
            return 1 / base;
        }
        if (exponent == -2) {
            return 1 / (base * base);
        }
        return Math.pow(base, exponent);
    }
}
