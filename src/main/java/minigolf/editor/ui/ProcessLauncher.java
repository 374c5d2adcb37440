package minigolf.editor.ui;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Starts another window of this program ({@code minigolf play FILE}, {@code minigolf edit}) as a
 * separate process with the same Java and class path: each window keeps its own GL and interface
 * context, and neither blocks the other.
 */
public final class ProcessLauncher {
    private ProcessLauncher() {
    }

    public static Process start(String... args) throws IOException {
        String java = ProcessHandle.current().info().command()
                .orElse(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        List<String> command = new ArrayList<>();
        command.add(java);
        command.add("-cp");
        command.add(System.getProperty("java.class.path"));
        command.add("minigolf.Main");
        command.addAll(List.of(args));
        return new ProcessBuilder(command).inheritIO().start();
    }
}
