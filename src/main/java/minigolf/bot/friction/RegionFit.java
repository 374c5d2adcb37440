package minigolf.bot.friction;

import java.util.function.Function;

/**
 * Least squares over the log friction scales of several regions at once (Levenberg-Marquardt with a
 * forward-difference Jacobian). One stroke often crosses two regions, and then only a joint move
 * fits it: on a long putt across a sand band, slowing the green must be paid for by speeding the
 * sand, which one region at a time can never find. A region whose scale moves no stroke's end (no
 * stroke crossed it) is left where it started. A step is taken only when it lowers the misfit, so
 * a jump in the physics (a ball that now reaches the water) cannot make the fit worse.
 */
final class RegionFit {
    /** Iterations at most, and the attempts at a step (raising the damping) in one iteration. */
    static final int ITERATIONS = 40, ATTEMPTS = 12;
    /** The finite-difference step of a log scale (0.01% of the scale). */
    static final double H = 1e-4;
    /** The longest step of one log scale in one iteration (a factor of 4). */
    static final double MAX_STEP = Math.log(4);
    /** Stop when an accepted step lowers the misfit by less than this share. */
    static final double TOLERANCE = 1e-10;

    private RegionFit() {
    }

    /**
     * @param residuals the residual vector (simulated minus observed ends) for given scales
     * @param start the scales to start from (every region at the common fit)
     * @param lo the smallest log scale allowed
     * @param hi the largest log scale allowed
     * @return the refined scales
     */
    static double[] refine(Function<double[], double[]> residuals, double[] start, double lo, double hi) {
        int m = start.length;
        double[] p = new double[m];
        for (int j = 0; j < m; j++) p[j] = Math.log(start[j]);
        double[] r = residuals.apply(exp(p));
        double f = sumOfSquares(r);
        double lambda = 1e-3;
        for (int it = 0; it < ITERATIONS && f > 0; it++) {
            double[][] jac = new double[r.length][m];
            boolean[] felt = new boolean[m];
            for (int j = 0; j < m; j++) {
                double[] q = p.clone();
                q[j] = p[j] + H <= hi ? p[j] + H : p[j] - H;
                double[] rq = residuals.apply(exp(q));
                for (int i = 0; i < r.length; i++) {
                    jac[i][j] = (rq[i] - r[i]) / (q[j] - p[j]);
                    if (jac[i][j] != 0) felt[j] = true;
                }
            }
            double[][] a = new double[m][m];
            double[] g = new double[m];
            for (int j = 0; j < m; j++) {
                for (int i = 0; i < r.length; i++) g[j] += jac[i][j] * r[i];
                for (int k = 0; k < m; k++) for (int i = 0; i < r.length; i++) a[j][k] += jac[i][j] * jac[i][k];
            }
            boolean accepted = false;
            for (int attempt = 0; attempt < ATTEMPTS && !accepted; attempt++) {
                double[] step = solveDamped(a, g, felt, lambda);
                double[] q = p.clone();
                for (int j = 0; j < m; j++) {
                    q[j] = Math.max(lo, Math.min(hi, p[j] + Math.max(-MAX_STEP, Math.min(MAX_STEP, step[j]))));
                }
                double[] rq = residuals.apply(exp(q));
                double fq = sumOfSquares(rq);
                if (fq < f) {
                    boolean converged = f - fq < TOLERANCE * f;
                    p = q;
                    r = rq;
                    f = fq;
                    lambda = Math.max(1e-9, lambda / 3);
                    accepted = true;
                    if (converged) return exp(p);
                } else {
                    lambda *= 4;
                }
            }
            if (!accepted) break;
        }
        return exp(p);
    }

    /** Solves (A + λ·diag(A)) δ = −g over the felt regions (Gaussian elimination); δ = 0 elsewhere. */
    static double[] solveDamped(double[][] a, double[] g, boolean[] felt, double lambda) {
        int m = g.length;
        int[] idx = new int[m];
        int n = 0;
        for (int j = 0; j < m; j++) if (felt[j]) idx[n++] = j;
        double[][] s = new double[n][n + 1];
        for (int u = 0; u < n; u++) {
            for (int v = 0; v < n; v++) s[u][v] = a[idx[u]][idx[v]];
            s[u][u] += lambda * a[idx[u]][idx[u]] + 1e-12;
            s[u][n] = -g[idx[u]];
        }
        for (int c = 0; c < n; c++) {
            int pivot = c;
            for (int u = c + 1; u < n; u++) if (Math.abs(s[u][c]) > Math.abs(s[pivot][c])) pivot = u;
            double[] t = s[c];
            s[c] = s[pivot];
            s[pivot] = t;
            if (s[c][c] == 0) continue;
            for (int u = c + 1; u < n; u++) {
                double factor = s[u][c] / s[c][c];
                for (int v = c; v <= n; v++) s[u][v] -= factor * s[c][v];
            }
        }
        double[] x = new double[n];
        for (int u = n - 1; u >= 0; u--) {
            double sum = s[u][n];
            for (int v = u + 1; v < n; v++) sum -= s[u][v] * x[v];
            x[u] = s[u][u] == 0 ? 0 : sum / s[u][u];
        }
        double[] step = new double[m];
        for (int u = 0; u < n; u++) step[idx[u]] = x[u];
        return step;
    }

    private static double[] exp(double[] p) {
        double[] s = new double[p.length];
        for (int j = 0; j < p.length; j++) s[j] = Math.exp(p[j]);
        return s;
    }

    private static double sumOfSquares(double[] r) {
        double f = 0;
        for (double v : r) f += v * v;
        return f;
    }
}
