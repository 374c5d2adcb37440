package minigolf.app;

import java.util.List;
import minigolf.online.client.RoomMirror;
import minigolf.ui.Gui;
import minigolf.ui.Panels;

/**
 * An online room before its round starts: the code to give to friends, who has taken a seat, the
 * chat. The round starts when every seat is taken; then play begins as in hot seat.
 */
final class LobbyScreen extends GameScreen {
    private final OnlinePanel panel = new OnlinePanel();

    LobbyScreen(GameApp app) {
        super(app);
    }

    @Override
    public void update(double elapsed) {
        OnlinePlay room = app.play().online();
        if (room == null) return;
        app.play().advance(elapsed, app.timeScale(), false);
        if (app.play().round() != null) {
            app.scene().resetCamera();
            app.setScreen(app.screens().playing());
        } else if (room.failure() != null && room.mirror().seat() < 0) {
            app.say(room.failure());
            app.play().end();
            app.setScreen(app.screens().online());
        }
    }

    @Override
    public void render(float w, float h) {
        OnlinePlay room = app.play().online();
        if (room == null) return;
        RoomMirror m = room.mirror();
        Panels.centre(w, h);
        Gui.begin("Online room###lobby", Panels.PANEL);
        if (m.room() == null) {
            Gui.text("Connecting to " + room.entry().server().getHost() + ":" + room.entry().server().getPort() + " ...");
        } else {
            Panels.heading("Room code: " + m.room());
            Gui.text(m.title() != null && !m.title().isEmpty() ? m.title() : "");
            List<RoomMirror.SeatInfo> seats = m.seats();
            long free = seats.stream().filter(RoomMirror.SeatInfo::free).count();
            Gui.text(free == 0 ? "Everyone is here: the round starts ..." : "Waiting for " + free + " more player"
                    + (free == 1 ? "" : "s") + ": give them the code");
            for (int i = 0; i < seats.size(); i++) {
                RoomMirror.SeatInfo s = seats.get(i);
                String who = s.free() ? "(free seat)" : s.name() + (s.bot() ? " (bot " + s.level() + ")" : "")
                        + (i == m.seat() ? " (you)" : "") + (!s.free() && !s.connected() ? " (away)" : "");
                Gui.text((i + 1) + ". " + who);
            }
        }
        if (Gui.button("Leave", 160, 0)) {
            room.leave();
            app.toMainMenu();
        }
        Gui.end();
        panel.render(room, w, h);
    }
}
