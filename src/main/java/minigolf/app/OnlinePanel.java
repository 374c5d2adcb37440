package minigolf.app;

import minigolf.ui.Gui;
import minigolf.ui.GuiCond;
import minigolf.ui.GuiString;
import minigolf.ui.GuiWindowFlags;
import minigolf.online.Protocol;

/** The online room's chat line, quick messages and connection state, at the lower left of the lobby and of play. */
final class OnlinePanel {
    static final String[] QUICK = {"Nice shot!", "Good game", "Oops!", "Your turn", "Be right back"};
    private final GuiString line = new GuiString(Protocol.MAX_CHAT_CHARS);

    void render(OnlinePlay room, float w, float h) {
        Gui.setNextWindowPos(12, h - 12, GuiCond.Always, 0f, 1f);
        Gui.begin("Room " + (room.mirror().room() != null ? room.mirror().room() : "...") + "###onlinechat",
                GuiWindowFlags.NoCollapse | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
        if (!room.connected()) Gui.textColored(1f, 0.6f, 0.3f, 1f, room.failure() != null ? room.failure() : "Connecting ...");
        for (String s : room.chat()) Gui.text(s.length() > 70 ? s.substring(0, 67) + "..." : s);
        Gui.setNextItemWidth(260);
        Gui.inputText("##chat", line);
        Gui.sameLine();
        if (Gui.button("Send") && !line.get().isBlank()) {
            room.sendChat(line.get());
            line.set("");
        }
        for (int i = 0; i < QUICK.length; i++) {
            if (i > 0) Gui.sameLine();
            if (Gui.button(QUICK[i])) room.sendChat(QUICK[i]);
        }
        Gui.end();
    }
}
