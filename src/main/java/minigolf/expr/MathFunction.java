package minigolf.expr;

import java.util.Arrays;
import java.util.stream.Collectors;

/**
 * The only functions an expression may call. Each maps to the java.lang.Math method of the same
 * name, which the compiler calls directly and the evaluator calls here, so both agree bit for bit.
 */
enum MathFunction {
    SIN(1), COS(1), TAN(1), ASIN(1), ACOS(1), ATAN(1), ATAN2(2),
    EXP(1), LOG(1), SQRT(1), ABS(1), MIN(2), MAX(2),
    /** Parsed into the {@code ^} operator so both spellings share one meaning. */
    POW(2);

    final int arity;
    /** Name in expressions, which is also the java.lang.Math method name. */
    final String functionName;

    MathFunction(int arity) {
        this.arity = arity;
        this.functionName = name().toLowerCase(java.util.Locale.ROOT);
    }

    static MathFunction byName(String name) {
        for (MathFunction function : values()) {
            if (function.functionName.equals(name)) {
                return function;
            }
        }
        return null;
    }

    static String allowedNames() {
        return Arrays.stream(values()).map(f -> f.functionName).collect(Collectors.joining(", "));
    }

    double apply(double a, double b) {
        switch (this) {
            case SIN: return Math.sin(a);
            case COS: return Math.cos(a);
            case TAN: return Math.tan(a);
            case ASIN: return Math.asin(a);
            case ACOS: return Math.acos(a);
            case ATAN: return Math.atan(a);
            case ATAN2: return Math.atan2(a, b);
            case EXP: return Math.exp(a);
            case LOG: return Math.log(a);
            case SQRT: return Math.sqrt(a);
            case ABS: return Math.abs(a);
            case MIN: return Math.min(a, b);
            case MAX: return Math.max(a, b);
            case POW: return Math.pow(a, b);
            default: throw new AssertionError(this);
        }
    }
}
