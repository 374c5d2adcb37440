import java.lang.management.*;
import java.net.*;
import java.nio.file.*;
import java.util.*;
import java.util.stream.*;
/**
 * java tools/LoadAB.java A_LIB B_LIB REPS COURSE...: the CPU time of World.load on the loading thread
 * (not the collector's or the compiler's), alternating two builds' jars in one JVM, warm after the
 * first round; prints the median and least per course. Load on a shared machine stretches wall time,
 * not this: what `minigolf bench-limits` times cold, this compares warm between builds.
 */
public class LoadAB {
  static java.lang.reflect.Method load(Path lib) throws Exception {
    List<URL> urls = new ArrayList<>();
    try (Stream<Path> jars = Files.list(lib)) { for (Path j : (Iterable<Path>) jars::iterator) if (j.toString().endsWith(".jar")) urls.add(j.toUri().toURL()); }
    ClassLoader l = new URLClassLoader(urls.toArray(new URL[0]), ClassLoader.getPlatformClassLoader());
    return l.loadClass("minigolf.physics.World").getMethod("load", Path.class);
  }
  public static void main(String[] a) throws Exception {
    java.lang.reflect.Method[] m = {load(Path.of(a[0])), load(Path.of(a[1]))};
    int reps = Integer.parseInt(a[2]);
    ThreadMXBean t = ManagementFactory.getThreadMXBean();
    for (int c = 3; c < a.length; c++) {
      double[][] ms = new double[2][reps];
      for (int r = 0; r < reps; r++) for (int b = 0; b < 2; b++) {
        System.gc();
        long s = t.getCurrentThreadCpuTime();
        m[b].invoke(null, Path.of(a[c]));
        ms[b][r] = (t.getCurrentThreadCpuTime() - s) / 1e6;
      }
      for (int b = 0; b < 2; b++) Arrays.sort(ms[b]);
      System.out.printf("%s: A median %.0f ms (min %.0f), B median %.0f ms (min %.0f)%n", a[c], ms[0][reps/2], ms[0][0], ms[1][reps/2], ms[1][0]);
    }
  }
}
