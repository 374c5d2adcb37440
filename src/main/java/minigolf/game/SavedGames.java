package minigolf.game;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.bot.NoiseModel;
import minigolf.course.CourseException;
import minigolf.course.Limits;
import minigolf.io.AtomicFile;
import minigolf.physics.Integrator;
import minigolf.physics.Outcome;
import minigolf.physics.SimulationSettings;
import minigolf.physics.World;

/**
 * Saves a game in progress and loads it back. The file embeds the course itself, so a saved game
 * resumes exactly even if the course file changed or moved. Numbers are written with full
 * double precision (Jackson writes the shortest decimal that reads back to the same double).
 * Writing is atomic ({@link AtomicFile}); reading checks every field and fails with one line.
 */
public final class SavedGames {
    public static final int FORMAT = 1;
    static final String KIND = "minigolf-saved-game";
    private static final List<String> TOP = List.of("format", "kind", "course", "simulation", "strokeLimit",
            "players", "history", "pendingShot", "noise", "clock", "botSeed");
    private static final List<String> SIMULATION = List.of("integrator", "dt", "maxTime");
    private static final List<String> PLAYER = List.of("name", "kind", "bot", "ball", "strokes", "penalties", "status");
    private static final List<String> SHOT = List.of("player", "start", "velocity", "outcome", "end", "clock");
    private static final List<String> PENDING = List.of("velocity");
    /** The "realistic" noise and its seed; absent in a game without noise (and in files from before it). */
    private static final List<String> NOISE = List.of("position", "velocity", "seed");

    private SavedGames() {
    }

    /** A loaded game: its world (built from the embedded course) and its state. */
    public record Loaded(World world, GameState state) {
        public Game resume() {
            return Game.restore(world, state);
        }
    }

    public static void save(Game game, Path file) throws SaveGameException {
        String json = toJson(game);
        try {
            AtomicFile.write(file, json.getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new SaveGameException(String.valueOf(file), null, e.getMessage(), e);
        }
    }

    public static Loaded load(Path file) throws SaveGameException {
        return parse(JsonFields.readText(file, Limits.SAVE_FILE_BYTES), String.valueOf(file));
    }

    public static String toJson(Game game) {
        try {
            return JsonFields.MAPPER.writerWithDefaultPrettyPrinter().writeValueAsString(tree(game)) + "\n";
        } catch (IOException e) {
            throw new IllegalStateException("cannot write JSON", e);
        }
    }

    /** The save of {@code game} as a JSON tree (a saved round embeds it as its current hole). */
    static ObjectNode tree(Game game) {
        GameState s = game.state();
        ObjectNode root = JsonFields.MAPPER.createObjectNode();
        root.put("format", FORMAT);
        root.put("kind", KIND);
        try {
            root.set("course", CourseTrees.of(game.world()));
        } catch (IOException e) {
            throw new IllegalStateException("the course writer produced invalid JSON", e);
        }
        ObjectNode sim = root.putObject("simulation");
        sim.put("integrator", s.settings().integrator().cliName());
        sim.put("dt", s.settings().dt());
        sim.put("maxTime", s.settings().maxTime());
        root.put("strokeLimit", s.strokeLimit());
        ArrayNode players = root.putArray("players");
        for (int i = 0; i < s.players().size(); i++) {
            Player p = s.players().get(i);
            PlayerState st = s.states().get(i);
            ObjectNode o = players.addObject();
            o.put("name", p.name());
            o.put("kind", p.kind().jsonName());
            if (p.bot() != null) o.put("bot", p.bot());
            o.putArray("ball").add(st.x()).add(st.y());
            o.put("strokes", st.strokes());
            o.put("penalties", st.penalties());
            o.put("status", st.status().jsonName());
        }
        // The course clock only where it is not 0, so saves from before it (and of still courses) stay as they were.
        if (s.clock() != 0) root.put("clock", s.clock());
        // The bots' seed likewise (0 in a game without bots, and the default for saves from before it).
        if (s.botSeed() != 0) root.put("botSeed", s.botSeed());
        writeHistory(root.putArray("history"), s.history());
        if (s.pendingShot() != null) {
            PendingShot p = s.pendingShot();
            velocity(root.putObject("pendingShot"), p.vx(), p.vy(), p.vz());
        }
        if (!s.noise().isNone()) {
            ObjectNode noise = root.putObject("noise");
            noise.put("position", s.noise().position());
            noise.put("velocity", s.noise().velocity());
            noise.put("seed", s.noiseSeed());
        }
        return root;
    }

    /** A putt is written [vx, vy], as before chips (older versions read it); a chip [vx, vy, vz]. */
    private static void velocity(ObjectNode o, double vx, double vy, double vz) {
        ArrayNode v = o.putArray("velocity").add(vx).add(vy);
        if (vz != 0) v.add(vz);
    }

    public static Loaded parse(String json, String source) throws SaveGameException {
        try {
            return parseChecked(json, source);
        } catch (OutOfMemoryError e) {
            throw new SaveGameException(source, null, "too large to load: the Java heap ran out of memory");
        } catch (StackOverflowError e) {
            throw new SaveGameException(source, null, "too deeply nested to load");
        }
    }

    private static Loaded parseChecked(String json, String source) throws SaveGameException {
        if (json.length() > Limits.SAVE_FILE_BYTES) {
            throw new SaveGameException(source, null, "too large: " + json.length() + " characters (the limit is "
                    + Limits.SAVE_FILE_BYTES + ")");
        }
        JsonFields f = new JsonFields(source);
        JsonNode root = f.parse(json);
        f.onlyFields(root, null, TOP);
        int format = f.integer(root, null, "format", 0, Integer.MAX_VALUE);
        if (format != FORMAT) throw f.error("format", "this game reads saved games of format " + FORMAT + ", got " + format);
        if (!KIND.equals(f.text(root, null, "kind"))) throw f.error("kind", "must be \"" + KIND + "\" (is this a saved game?)");
        World world;
        try {
            String courseJson = JsonFields.MAPPER.writeValueAsString(f.object(f.field(root, null, "course"), "course"));
            world = World.parse(courseJson, source + " (course)");
        } catch (CourseException e) {
            throw new SaveGameException(source, "course" + (e.path() == null ? "" : "." + e.path()), e.problem(), e);
        } catch (IOException e) {
            throw f.error("course", "cannot be read: " + e.getMessage());
        }
        JsonNode sim = f.object(f.field(root, null, "simulation"), "simulation");
        f.onlyFields(sim, "simulation", SIMULATION);
        Integrator integrator = Integrator.fromName(f.text(sim, "simulation", "integrator"));
        if (integrator == null) throw f.error("simulation.integrator", "must be euler, rk2 or rk4");
        // The rules of the settings file (UserSettings), which is where a game's step comes from.
        double dt = f.number(sim, "simulation", "dt");
        if (SimulationSettings.dtProblem(dt) != null) {
            throw f.error("simulation.dt", SimulationSettings.dtProblem(dt));
        }
        double maxTime = f.number(sim, "simulation", "maxTime");
        if (!(maxTime >= 1 && maxTime <= SimulationSettings.DEFAULT_MAX_TIME)) {
            throw f.error("simulation.maxTime", "must be 1 to " + SimulationSettings.DEFAULT_MAX_TIME + " s, got " + maxTime);
        }
        SimulationSettings settings = new SimulationSettings(integrator, dt, maxTime);
        int strokeLimit = f.integer(root, null, "strokeLimit", 1, Game.MAX_STROKE_LIMIT);

        JsonNode playersNode = f.array(root, null, "players");
        if (playersNode.size() < 1 || playersNode.size() > Game.MAX_PLAYERS) {
            throw f.error("players", "a game has 1 to " + Game.MAX_PLAYERS + " players, got " + playersNode.size());
        }
        List<Player> players = new ArrayList<>();
        List<PlayerState> states = new ArrayList<>();
        for (int i = 0; i < playersNode.size(); i++) {
            String p = "players[" + i + "]";
            JsonNode o = f.object(playersNode.get(i), p);
            f.onlyFields(o, p, PLAYER);
            PlayerKind kind = PlayerKind.fromJsonName(f.text(o, p, "kind"));
            if (kind == null) throw f.error(p + ".kind", "must be human or bot");
            String bot = kind == PlayerKind.BOT ? f.text(o, p, "bot") : null;
            if (bot != null && !BotCatalog.names().contains(bot)) {
                throw f.error(p + ".bot", "no bot named " + JsonFields.shown(bot) + " (known: "
                        + String.join(", ", BotCatalog.names()) + ")");
            }
            try {
                players.add(new Player(f.text(o, p, "name"), kind, bot));
            } catch (IllegalArgumentException e) {
                throw f.error(p, e.getMessage());
            }
            double[] ball = f.vec(o, p, "ball");
            if (!world.playArea().contains(ball[0], ball[1])) throw f.error(p + ".ball", "lies outside the course (its bounds or a deleted cell)");
            double h = world.terrain().height(ball[0], ball[1]);
            if (!(h >= 0)) throw f.error(p + ".ball", "lies in water (h = " + (float) h + "), where no ball can rest");
            int strokes = f.integer(o, p, "strokes", 0, 10_000);
            int penalties = f.integer(o, p, "penalties", 0, strokes);
            PlayerStatus status = PlayerStatus.fromJsonName(f.text(o, p, "status"));
            if (status == null) throw f.error(p + ".status", "must be playing, holed or picked-up");
            states.add(new PlayerState(ball[0], ball[1], strokes, penalties, status));
        }

        List<ShotRecord> history = readHistory(f, f.array(root, null, "history"), "history", players.size());

        PendingShot pending = null;
        JsonNode pendingNode = root.get("pendingShot");
        if (pendingNode != null && !pendingNode.isNull()) {
            f.object(pendingNode, "pendingShot");
            f.onlyFields(pendingNode, "pendingShot", PENDING);
            double[] v = f.velocity(pendingNode, "pendingShot", "velocity");
            if (Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) > world.physics().maxSpeed() * (1 + 1e-12)) {
                throw f.error("pendingShot.velocity", "is faster than the course's maxSpeed " + world.physics().maxSpeed() + " m/s");
            }
            if (states.stream().noneMatch(PlayerState::isPlaying)) {
                throw f.error("pendingShot", "a shot is in flight but every player has finished");
            }
            pending = new PendingShot(v[0], v[1], v[2]);
        }
        NoiseModel noise = NoiseModel.NONE;
        long noiseSeed = 0;
        JsonNode noiseNode = root.get("noise");
        if (noiseNode != null && !noiseNode.isNull()) {
            f.object(noiseNode, "noise");
            f.onlyFields(noiseNode, "noise", NOISE);
            try {
                noise = new NoiseModel(f.number(noiseNode, "noise", "position"), f.number(noiseNode, "noise", "velocity"));
            } catch (IllegalArgumentException e) {
                throw f.error("noise", e.getMessage());
            }
            JsonNode seed = noiseNode.get("seed");
            if (seed == null || !seed.canConvertToLong() || !seed.isIntegralNumber()) {
                throw f.error("noise.seed", "must be a whole number");
            }
            noiseSeed = seed.longValue();
        }
        double clock = root.has("clock") ? clock(f, root, null) : 0;
        long botSeed = 0; // absent (saves from before it, games without bots): 0
        JsonNode botSeedNode = root.get("botSeed");
        if (botSeedNode != null && !botSeedNode.isNull()) {
            if (!botSeedNode.isIntegralNumber() || !botSeedNode.canConvertToLong()) throw f.error("botSeed", "must be a whole number");
            botSeed = botSeedNode.longValue();
        }
        return new Loaded(world, new GameState(settings, players, strokeLimit, states, history, pending, noise, noiseSeed, clock,
                botSeed));
    }

    /** The course clock field of {@code o} (s): a finite number, 0 or more. */
    private static double clock(JsonFields f, JsonNode o, String path) throws SaveGameException {
        double c = f.number(o, path, "clock");
        if (!(c >= 0) || !Double.isFinite(c)) throw f.error(path == null ? "clock" : path + ".clock", "must be 0 or more, got " + c);
        return c;
    }

    private static Outcome outcomeNamed(String name) {
        for (Outcome o : Outcome.values()) if (o.jsonName().equals(name)) return o;
        return null;
    }

    /** Writes strokes as a saved game's {@code history} holds them (a putt's velocity as [vx, vy]). */
    static void writeHistory(ArrayNode out, List<ShotRecord> strokes) {
        for (ShotRecord r : strokes) {
            ObjectNode o = out.addObject();
            o.put("player", r.player());
            o.putArray("start").add(r.startX()).add(r.startY());
            velocity(o, r.vx(), r.vy(), r.vz());
            o.put("outcome", r.outcome().jsonName());
            o.putArray("end").add(r.endX()).add(r.endY());
            if (r.clock() != 0) o.put("clock", r.clock());
        }
    }

    /** Reads strokes written by {@link #writeHistory}; {@code path} names the array in messages. */
    static List<ShotRecord> readHistory(JsonFields f, JsonNode historyNode, String path, int players) throws SaveGameException {
        List<ShotRecord> history = new ArrayList<>();
        for (int i = 0; i < historyNode.size(); i++) {
            String p = path + "[" + i + "]";
            JsonNode o = f.object(historyNode.get(i), p);
            f.onlyFields(o, p, SHOT);
            int who = f.integer(o, p, "player", 0, players - 1);
            double[] start = f.vec(o, p, "start"), v = f.velocity(o, p, "velocity"), end = f.vec(o, p, "end");
            Outcome outcome = outcomeNamed(f.text(o, p, "outcome"));
            if (outcome == null) throw f.error(p + ".outcome", "must be holed, stopped, water, out or timeout");
            double clock = o.has("clock") ? clock(f, o, p) : 0;
            history.add(new ShotRecord(who, start[0], start[1], v[0], v[1], v[2], outcome, end[0], end[1], clock));
        }
        return history;
    }
}
