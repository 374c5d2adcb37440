package minigolf.cli;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import minigolf.app.GameApp;
import minigolf.app.GameLauncher;
import minigolf.course.CourseException;
import minigolf.game.BotCatalog;
import minigolf.game.Game;
import minigolf.game.Round;
import minigolf.game.RoundLoader;
import minigolf.game.Player;
import minigolf.game.SettingsStore;
import minigolf.physics.World;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

@Command(name = "play", description = {"Opens the game on a course (default: the lake).",
        "With --frames N it runs the real game N frames (with --players, straight into a game) and exits;"
                + " --screenshot saves what the window shows at the last frame."})
final class PlayCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "COURSE", description = "The course file (JSON).")
    Path course;

    @Option(names = "--screenshot", paramLabel = "FILE.png", description = "Saves the last frame's window as PNG (needs --frames; default: none).")
    Path screenshot;

    @Option(names = "--frames", paramLabel = "N", description = "Runs the game N frames, then exits (default: ${DEFAULT-VALUE}, until the window is closed).")
    int frames;

    @Option(names = "--round", paramLabel = "ROUND.json",
            description = "Plays a round (a round file, docs/course-format.md) instead of one course (default: none).")
    Path round;

    @Option(names = "--players", paramLabel = "NAME", split = ",",
            description = {"Starts a game at once with these players (1 to 4), e.g. --players Ann,Bob;",
                    "Bot:NAME seats a bot (e.g. Bot:planner) (default: none, the main menu opens)."})
    List<String> players;

    @Option(names = "--shots", paramLabel = "VX:VY[:VZ]", split = ",",
            description = {"Scripted shots for the human players, through the game's HIT input, in m/s, e.g. 1.5:0.2,2:0;",
                    "a third number VZ > 0 makes it a chip, e.g. 2:0:1.5 (default: none)."})
    List<String> shots;

    @Option(names = "--aim", paramLabel = "VX:VY",
            description = "Shows this aim (m/s) as if the first human player were dragging it, with the aim guide if it is on (for screenshots; default: none).")
    String aim;

    @Option(names = "--loft", paramLabel = "DEG",
            description = "With --aim: the loft of the shown aim, 0 (a putt) to 60 degrees, as the player sets it with the wheel (default: ${DEFAULT-VALUE}).")
    int loft;

    @Option(names = "--time-scale", paramLabel = "K", description = "Animation speed as a multiple of real time (default: ${DEFAULT-VALUE}).")
    double timeScale = 1;

    @Option(names = "--timing", description = {"With --frames: prints the real game loop's frame time as JSON"
            + " (window, scene, minimap, HUD; the first quarter of the frames is warm-up) instead of the scorecard"
            + " (default: off)."})
    boolean timing;

    @Option(names = "--online", paramLabel = "HOST:PORT", description = "Plays in a room on this game server (with "
            + "--create or --room; docs/online.md; default: none).")
    String online;

    @Option(names = "--create", paramLabel = "COURSE_OR_ROUND", description = "With --online: hosts a room on this course "
            + "or round and prints {\"room\": CODE} first (default: none).")
    String create;

    @Option(names = "--seats", paramLabel = "N", description = "With --create: the room's seats, 1 to 4 (default: ${DEFAULT-VALUE}).")
    int onlineSeats = 2;

    @Option(names = "--room", paramLabel = "CODE", description = "With --online: takes a seat in this room (default: none).")
    String room;

    @Option(names = "--name", paramLabel = "NAME", description = "With --online: the player's name (default: ${DEFAULT-VALUE}).")
    String name = "Player";

    @Override
    public Integer call() {
        if (online != null) return playOnline();
        if (create != null || room != null) throw new UserError("--create and --room need --online HOST:PORT");
        if (round != null && course != null) throw new UserError("give either a COURSE or --round, not both");
        Round theRound = null;
        if (round != null) {
            try {
                theRound = RoundLoader.load(round);
            } catch (CourseException e) {
                throw new UserError(e.getMessage());
            }
        }
        World world = theRound != null ? theRound.hole(0).world()
                : course == null ? GameLauncher.loadBundled(GameLauncher.DEFAULT_COURSE) : CourseArgument.load(course);
        if (frames < 0) throw new UserError("--frames: must be >= 0, got " + frames);
        if (screenshot != null && frames == 0) throw new UserError("--screenshot needs --frames N (N >= 1)");
        if (timing && frames < 8) throw new UserError("--timing needs --frames N (N >= 8)");
        if (!(timeScale > 0 && timeScale <= 1000)) throw new UserError("--time-scale: must be in (0, 1000], got " + timeScale);
        List<Player> seats = null;
        if (players != null) {
            if (players.isEmpty() || players.size() > Game.MAX_PLAYERS) {
                throw new UserError("--players: 1 to " + Game.MAX_PLAYERS + " names, got " + players.size());
            }
            try {
                seats = seats(players);
            } catch (IllegalArgumentException e) {
                throw new UserError("--players: " + e.getMessage());
            }
        }
        List<double[]> script = shots == null ? List.of() : shots.stream().map(PlayCommand::parseShot).toList();
        if (!script.isEmpty() && seats == null) throw new UserError("--shots needs --players");
        GameApp.Options options = new GameApp.Options(course, screenshot, frames, seats, script, timeScale,
                SettingsStore.forUser(), true, theRound != null);
        GameApp app = new GameApp(world, options);
        if (aim != null) {
            if (seats == null) throw new UserError("--aim needs --players");
            double[] v = parseVelocity("--aim", aim);
            if (v.length != 2) throw new UserError("--aim: expected VX:VY (the loft is --loft), got '" + aim + "'");
            if (loft < 0 || loft > minigolf.game.Loft.MAX_DEGREES) {
                throw new UserError("--loft: must be 0 to " + minigolf.game.Loft.MAX_DEGREES + " degrees, got " + loft);
            }
            app.showAim(v[0], v[1], loft);
        }
        if (theRound != null) app.playRound(theRound);
        FrameClock clock = timing ? new FrameClock(frames / 4) : null;
        if (clock != null) app.onLoopPass((pass, window) -> clock.pass(pass, window));
        Game game = app.run();
        java.io.PrintWriter out = spec.commandLine().getOut();
        if (clock != null) out.println(clock.json(world.course().name()));
        else if (frames > 0 && app.roundGame() != null) out.print(app.roundGame().scorecard().toText());
        else if (frames > 0 && game != null) out.print(game.scorecard().toText());
        out.flush();
        return 0;
    }

    /** The game window in an online room: its lobby, then play, scripted shots sent on this seat's turns. */
    private int playOnline() {
        if ((create == null) == (room == null)) throw new UserError("--online needs either --create COURSE_OR_ROUND or --room CODE");
        if (players != null || round != null || course != null) throw new UserError("--online plays the server's course: no COURSE, --round or --players");
        java.net.URI uri;
        try {
            uri = minigolf.online.client.OnlineClient.uri(online);
        } catch (IllegalArgumentException e) {
            throw new UserError("--online: " + e.getMessage());
        }
        if (create != null && !minigolf.online.Protocol.COURSE_NAME.matcher(create).matches()) throw new UserError("--create: not a course or round name: " + create);
        if (room != null && !minigolf.online.Protocol.CODE.matcher(room).matches()) throw new UserError("--room: a room code is 8 letters and digits, got " + room);
        if (onlineSeats < 1 || onlineSeats > 4) throw new UserError("--seats: must be 1 to 4");
        if (name.isBlank() || name.strip().length() > Player.MAX_NAME_LENGTH) throw new UserError("--name: 1 to " + Player.MAX_NAME_LENGTH + " characters");
        if (frames < 0) throw new UserError("--frames: must be >= 0, got " + frames);
        if (screenshot != null && frames == 0) throw new UserError("--screenshot needs --frames N (N >= 1)");
        if (!(timeScale > 0 && timeScale <= 1000)) throw new UserError("--time-scale: must be in (0, 1000], got " + timeScale);
        List<double[]> script = shots == null ? List.of() : shots.stream().map(PlayCommand::parseShot).toList();
        GameApp app = new GameApp(GameLauncher.loadBundled(GameLauncher.DEFAULT_COURSE), new GameApp.Options(null, screenshot,
                frames, null, script, timeScale, SettingsStore.forUser(), true, true));
        java.io.PrintWriter out = spec.commandLine().getOut();
        app.playOnline(uri, name.strip(), create, onlineSeats, List.of(), room, code -> {
            if (create != null) {
                out.println("{\"room\": \"" + code + "\"}");
                out.flush();
            }
        });
        app.run();
        if (frames > 0 && app.roundGame() != null) out.print(app.roundGame().scorecard().toText());
        out.flush();
        return 0;
    }

    /** "Ann" is a human; "Bot:planner" the bot planner, named "Bot (planner)" ("Bot 2 (planner)" for the second). */
    static List<Player> seats(List<String> specs) {
        List<Player> out = new java.util.ArrayList<>();
        int bots = 0;
        for (String spec : specs) {
            String n = spec.trim();
            if (n.regionMatches(true, 0, "bot:", 0, 4)) {
                String bot = n.substring(4).trim();
                if (BotCatalog.planner(bot) == null) {
                    throw new IllegalArgumentException("no bot named '" + bot + "' (bots: " + String.join(", ", BotCatalog.names()) + ")");
                }
                bots++;
                out.add(Player.bot("Bot" + (bots > 1 ? " " + bots : "") + " (" + BotCatalog.label(bot) + ")", bot));
            } else {
                out.add(Player.human(n));
            }
        }
        return out;
    }

    private static double[] parseShot(String s) {
        return parseVelocity("--shots", s);
    }

    private static double[] parseVelocity(String option, String s) {
        String[] p = s.split(":");
        try {
            if (p.length != 2 && p.length != 3) throw new NumberFormatException();
            double[] v = new double[p.length];
            for (int i = 0; i < p.length; i++) v[i] = Double.parseDouble(p[i]);
            if (v.length == 3 && !(v[2] >= 0)) throw new UserError(option + ": VZ must be 0 or more, got '" + s + "'");
            return v;
        } catch (NumberFormatException e) {
            throw new UserError(option + ": expected VX:VY or VX:VY:VZ such as 1.5:-0.2 or 2:0:1.2, got '" + s + "'");
        }
    }
}
