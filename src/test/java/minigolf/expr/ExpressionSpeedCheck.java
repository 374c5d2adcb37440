package minigolf.expr;

/**
 * Prints nanoseconds per compiled valueAndGradient call for the lake course. Not a unit test:
 * timings depend on the machine. Run with build/classes and the ASM jar on the class path.
 */
public final class ExpressionSpeedCheck {
    private static final int POINTS = 1 << 12;

    private ExpressionSpeedCheck() {
    }

    public static void main(String[] args) {
        CompiledExpression lake = Expression.parse(TestExpressions.LAKE).compile();
        double[] xs = new double[POINTS];
        double[] ys = new double[POINTS];
        java.util.Random random = new java.util.Random(1);
        for (int i = 0; i < POINTS; i++) {
            xs[i] = -8 + 16 * random.nextDouble();
            ys[i] = -8 + 16 * random.nextDouble();
        }
        double[] out = new double[3];
        double sink = 0;
        for (int round = 0; round < 5; round++) {
            int calls = 20_000_000;
            long start = System.nanoTime();
            for (int i = 0; i < calls; i++) {
                int k = i & (POINTS - 1);
                lake.valueAndGradient(xs[k], ys[k], out);
                sink += out[0] + out[1] + out[2];
            }
            long elapsed = System.nanoTime() - start;
            System.out.printf("round %d: %.2f ns per valueAndGradient%n", round, (double) elapsed / calls);
        }
        System.out.println("(checksum " + sink + ")");
    }
}
