package minigolf;

import java.io.PrintWriter;
import minigolf.cli.MinigolfCommand;

/** Entry point: {@code minigolf} opens the game, {@code minigolf <command>} runs the command line. */
public final class Main {
    private Main() {
    }

    public static void main(String[] args) {
        int code = MinigolfCommand.execute(args, new PrintWriter(System.out, true), new PrintWriter(System.err, true));
        System.exit(code);
    }
}
