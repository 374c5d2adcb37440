package minigolf.app;

import java.net.URI;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import minigolf.game.BotCatalog;
import minigolf.game.Player;
import minigolf.online.Protocol;
import minigolf.online.client.OnlineClient;
import minigolf.ui.Gui;
import minigolf.ui.GuiBool;
import minigolf.ui.GuiInt;
import minigolf.ui.GuiString;
import minigolf.ui.Panels;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/**
 * "Play online": the server and the player's name, then host a room (a course or round, up to four
 * seats, friends or bots in the others) or join one with its code; the seat last held is offered
 * for a resume (docs/online.md).
 */
final class OnlineScreen extends GameScreen {
    private final GuiString server = new GuiString(200);
    private final GuiString name = new GuiString(Player.MAX_NAME_LENGTH);
    /** A name the server offers, typed (the last choice of the list). */
    private final GuiString course = new GuiString("meadowbrook-9", 64);
    /** What can be hosted, by the names a player reads; the last entry is "another name", typed. */
    private List<Offer> offers;
    private final GuiInt offer = new GuiInt(0);
    private final int[] seats = {2};
    private final GuiInt[] others = new GuiInt[Protocol.MAX_SEATS];
    private final GuiBool listed = new GuiBool(true);
    private final GuiString code = new GuiString(Protocol.CODE_LENGTH);
    private OnlineMemory memory;
    private String formError;

    OnlineScreen(GameApp app) {
        super(app);
        for (int i = 0; i < others.length; i++) others[i] = new GuiInt(0);
    }

    @Override
    public void show() {
        memory = OnlineMemory.load(OnlineMemory.file(app.files().store().directory()));
        if (server.get().isEmpty()) server.set(memory.server());
        if (name.get().isEmpty()) name.set(memory.name());
        formError = null;
        if (offers == null) offers = offers(app.files().store());
    }

    /** A round or hole that can be hosted: the name a player reads, and the name the server knows it by. */
    record Offer(String label, String serverName) {
    }

    /**
     * The shipped rounds (in course select's order) and the shipped single holes, by the names a
     * player reads; the server knows each by its file name (docs/online.md). The player's own rounds
     * and courses are left out: a server offers only its own folder.
     */
    static List<Offer> offers(minigolf.game.SettingsStore store) {
        List<Offer> out = new ArrayList<>();
        Path own = store.directory().toAbsolutePath().normalize();
        for (CourseFolders.RoundEntry r : CourseFolders.rounds(store)) {
            if (r.file().toAbsolutePath().normalize().startsWith(own)) continue;
            out.add(new Offer(r.round().name() + " (" + r.round().size() + " holes)", stem(r.file())));
        }
        for (CourseFolders.CourseEntry c : CourseFolders.list(store)) {
            Path file = c.file().toAbsolutePath().normalize(), parent = file.getParent();
            if (c.own() || file.startsWith(own) || parent == null || !parent.getFileName().toString().equals("holes")) continue;
            out.add(new Offer(c.name() + " (one hole)", stem(c.file())));
        }
        return out;
    }

    private static String stem(Path file) {
        String n = file.getFileName().toString();
        return n.endsWith(".json") ? n.substring(0, n.length() - ".json".length()) : n;
    }

    @Override
    public void render(float w, float h) {
        Panels.centre(w, h);
        Gui.begin("Play online", Panels.PANEL);
        Gui.setNextItemWidth(260);
        Gui.inputText("Server (host:port)", server);
        Gui.setNextItemWidth(260);
        Gui.inputText("Your name", name);
        Gui.separator();
        Panels.heading("Host a room");
        String[] choices = new String[offers.size() + 1];
        for (int i = 0; i < offers.size(); i++) choices[i] = offers.get(i).label();
        choices[offers.size()] = "Another (type its name)";
        Gui.setNextItemWidth(260);
        Gui.combo("Round or hole", offer, choices);
        if (offer.get() >= offers.size()) {
            Gui.setNextItemWidth(260);
            Gui.inputText("Name", course);
            Gui.textDisabled("a name the server offers: lake, 01-first-tee, meadowbrook-9, ...");
        }
        Gui.sliderInt("Seats", seats, 1, Protocol.MAX_SEATS);
        List<String> levels = BotCatalog.names();
        String[] kinds = new String[levels.size() + 1];
        kinds[0] = "a friend (joins with the code)";
        for (int i = 0; i < levels.size(); i++) kinds[i + 1] = "bot: " + BotCatalog.label(levels.get(i));
        for (int i = 1; i < seats[0]; i++) {
            Gui.pushID(i);
            Gui.setNextItemWidth(260);
            Gui.combo("Seat " + (i + 1), others[i], kinds);
            Gui.popID();
        }
        Gui.checkbox("List the room on the server's web page", listed);
        if (Gui.button("Host", 160, 0)) host(levels);
        Gui.separator();
        Panels.heading("Join a room");
        Gui.setNextItemWidth(160);
        Gui.inputText("Room code", code);
        if (Gui.button("Join", 160, 0)) join();
        if (memory != null && memory.room() != null) {
            Gui.separator();
            if (Gui.button("Resume room " + memory.room(), 260, 0)) resume();
        }
        if (formError != null) Gui.textColored(1f, 0.5f, 0.4f, 1f, formError);
        Gui.separator();
        if (Gui.button("Back", 160, 0)) app.setScreen(app.screens().mainMenu());
        Gui.end();
    }

    private URI serverUri() {
        try {
            return OnlineClient.uri(server.get());
        } catch (IllegalArgumentException e) {
            formError = "Server: " + e.getMessage();
            return null;
        }
    }

    private String playerName() {
        String n = name.get().strip();
        if (n.isEmpty()) formError = "Your name: type one (1 to " + Player.MAX_NAME_LENGTH + " characters)";
        return n.isEmpty() ? null : n;
    }

    private void host(List<String> levels) {
        URI uri = serverUri();
        String n = playerName();
        if (uri == null || n == null) return;
        String c = offer.get() < offers.size() ? offers.get(offer.get()).serverName() : course.get().strip();
        if (!Protocol.COURSE_NAME.matcher(c).matches()) {
            formError = "Name: one the server offers, such as lake or meadowbrook-9";
            return;
        }
        List<String> bots = new ArrayList<>();
        for (int i = 1; i < seats[0]; i++) if (others[i].get() > 0) bots.add(levels.get(others[i].get() - 1));
        // The server seats its bots last; the friends take the seats before them.
        enter(new OnlinePlay.Entry(uri, n, c, seats[0], bots, listed.get(), null, null));
    }

    private void join() {
        URI uri = serverUri();
        String n = playerName();
        if (uri == null || n == null) return;
        String c = code.get().strip().toUpperCase(java.util.Locale.ROOT);
        if (!Protocol.CODE.matcher(c).matches()) {
            formError = "Room code: the " + Protocol.CODE_LENGTH + " letters and digits the host sees";
            return;
        }
        enter(new OnlinePlay.Entry(uri, n, null, 0, List.of(), true, c, null));
    }

    private void resume() {
        URI uri = serverUri();
        if (uri == null) return;
        enter(new OnlinePlay.Entry(uri, memory.name(), null, 0, List.of(), true, memory.room(), memory.token()));
    }

    private void enter(OnlinePlay.Entry e) {
        formError = null;
        memory = new OnlineMemory(server.get().strip(), e.name(), memory.room(), memory.token());
        memory.save(OnlineMemory.file(app.files().store().directory()));
        app.startOnline(e);
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        app.setScreen(app.screens().mainMenu());
        return true;
    }
}
