package minigolf.online.server;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/** The program in a process of its own (java, this test's class path, minigolf.Main), so a test can kill -9 it. */
final class Processes {
    private Processes() {
    }

    /** A running minigolf process whose standard output lines are queued. */
    static final class Run implements AutoCloseable {
        final Process process;
        final LinkedBlockingQueue<String> lines = new LinkedBlockingQueue<>();

        Run(Process process) {
            this.process = process;
            Thread t = new Thread(() -> {
                try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                    for (String line; (line = r.readLine()) != null; ) lines.add(line);
                } catch (IOException e) {
                    // the process died
                }
            }, "test-process-out");
            t.setDaemon(true);
            t.start();
        }

        String nextLine(long seconds) throws InterruptedException {
            String line = lines.poll(seconds, TimeUnit.SECONDS);
            if (line == null) throw new AssertionError("no output line within " + seconds + " s (alive: " + process.isAlive() + ")");
            return line;
        }

        /** kill -9: no shutdown hook, no flush, nothing. */
        void kill9() throws InterruptedException {
            process.destroyForcibly();
            process.waitFor(30, TimeUnit.SECONDS);
        }

        @Override
        public void close() throws InterruptedException {
            if (process.isAlive()) kill9();
        }
    }

    static Run start(Path errFile, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx512m", "-cp", System.getProperty("java.class.path"), "minigolf.Main"));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.appendTo(errFile.toFile()));
        pb.directory(Path.of(System.getProperty("minigolf.projectDir", ".")).toFile());
        return new Run(pb.start());
    }
}
