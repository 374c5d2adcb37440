package minigolf.cli;

import java.io.PrintWriter;
import java.net.URI;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import minigolf.game.BotCatalog;
import minigolf.online.Protocol;
import minigolf.online.client.HeadlessPlayer;
import minigolf.online.client.OnlineClient;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

@Command(name = "join",
        description = "Plays one seat of an online room with a bot, without a window: --create opens a room and prints "
                + "{\"room\": CODE} first; --room takes a seat. At the end prints the scorecard as one JSON line "
                + "(players, each with name, strokes per hole and total).")
final class JoinCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "HOST:PORT", description = "The server.")
    String server;

    @Option(names = "--create", paramLabel = "COURSE_OR_ROUND", description = "Open a room on this course or round "
            + "(a name the server offers, e.g. lake or meadowbrook-9; default: none, give this or --room).")
    String create;

    @Option(names = "--room", paramLabel = "CODE", description = "Take a seat in this room (default: none, give this or --create).")
    String room;

    @Option(names = "--seats", paramLabel = "N", description = "Seats in a new room, 1 to 4, server bots included "
            + "(default: ${DEFAULT-VALUE}).")
    int seats = 2;

    @Option(names = "--server-bot", paramLabel = "LEVEL", description = "Fill one of the new room's seats with a bot "
            + "the server plays (repeatable; default: none).")
    List<String> serverBots = new ArrayList<>();

    @Option(names = "--private", description = "Leave the new room off the server's web page (default: off, the room is listed).")
    boolean unlisted;

    @Option(names = "--name", paramLabel = "NAME", required = true, description = "The player's name (1 to 24 characters).")
    String name;

    @Option(names = "--bot", paramLabel = "LEVEL", required = true, description = "The bot that plays this seat.")
    String bot;

    @Option(names = "--seat-file", paramLabel = "FILE", description = "Keep the seat's token in FILE; when FILE holds a "
            + "seat, resume it instead (a client restarted after a crash; default: none).")
    Path seatFile;

    @Override
    public Integer call() throws Exception {
        if ((create == null) == (room == null) && seatFile == null) throw new UserError("give either --create or --room");
        if (create != null && room != null) throw new UserError("give either --create or --room, not both");
        URI uri;
        try {
            uri = OnlineClient.uri(server);
        } catch (IllegalArgumentException e) {
            throw new UserError("HOST:PORT: " + e.getMessage());
        }
        if (room != null && !Protocol.CODE.matcher(room).matches()) {
            throw new UserError("--room: a room code is " + Protocol.CODE_LENGTH + " letters and digits, got " + room);
        }
        if (create != null && !Protocol.COURSE_NAME.matcher(create).matches()) {
            throw new UserError("--create: not a course or round name: " + create);
        }
        if (seats < 1 || seats > Protocol.MAX_SEATS) throw new UserError("--seats: must be 1 to " + Protocol.MAX_SEATS);
        if (serverBots.size() > seats - 1) throw new UserError("--server-bot: at most seats - 1 (" + (seats - 1) + ")");
        String n = name.strip();
        if (n.isEmpty() || n.length() > minigolf.game.Player.MAX_NAME_LENGTH || n.chars().anyMatch(Character::isISOControl)) {
            throw new UserError("--name: 1 to " + minigolf.game.Player.MAX_NAME_LENGTH + " characters, no control characters");
        }
        List<String> known = BotCatalog.names();
        for (String level : concat(bot, serverBots)) {
            if (!known.contains(level)) throw new UserError("unknown bot level '" + level + "'; known: " + String.join(", ", known));
        }
        PrintWriter out = spec.commandLine().getOut(), err = spec.commandLine().getErr();
        HeadlessPlayer player = new HeadlessPlayer(new HeadlessPlayer.Options(uri, create, seats, serverBots, !unlisted, room,
                n, bot, seatFile, 0), line -> {
                    out.println(line);
                    out.flush();
                }, line -> {
                    err.println("minigolf join: " + line);
                    err.flush();
                }, null);
        try {
            player.run();
        } catch (HeadlessPlayer.Failure e) {
            throw new UserError(e.getMessage());
        }
        return 0;
    }

    private static List<String> concat(String one, List<String> more) {
        List<String> all = new ArrayList<>(more);
        all.add(one);
        return all;
    }
}
