package minigolf.app;

import java.util.Locale;
import minigolf.game.BallReadout;
import minigolf.game.BotTurn;
import minigolf.game.Game;
import minigolf.game.Loft;
import minigolf.game.Player;
import minigolf.game.PlayerState;
import minigolf.game.PlayerStatus;
import minigolf.game.RoundGame;
import minigolf.game.StrokeAnimator;
import minigolf.physics.World;
import minigolf.ui.Gui;
import minigolf.ui.GuiBool;
import minigolf.ui.GuiCond;
import minigolf.ui.GuiTableFlags;
import minigolf.ui.GuiWindowFlags;
import minigolf.ui.PlanOverlay;
import minigolf.ui.PlayerColors;

/**
 * The HUD while a game is on, over the playing screen and the screens opened from it: the round,
 * hole and par, whose turn, every player's strokes, the power while aiming, the loft, in practice
 * mode a details readout (position, velocity, acceleration, slope, friction), and a bot's progress
 * with Cancel.
 */
final class Hud {
    private final GameApp app;
    /** The physics readout: off unless asked for. */
    private final GuiBool details = new GuiBool(false);
    /** Where the bot's panel was drawn in the last frame ({x, y, w, h}), or null (tests). */
    private float[] botPanel;

    Hud(GameApp app) {
        this.app = app;
    }

    /** Draws the HUD; {@code aimSpeed} in m/s while an aim is dragged, else negative. */
    void render(float w, float h, double aimSpeed, int loftDegrees) {
        botPanel = null;
        PlaySession play = app.play();
        Game g = play.game();
        Gui.setNextWindowPos(12, 12, GuiCond.Always);
        Gui.begin("##hud", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
        RoundGame rg = play.round();
        if (rg != null) {
            Gui.textColored(0.6f, 0.9f, 1f, 1f, String.format(Locale.ROOT, "%s  -  hole %d of %d  -  par %d",
                    rg.round().name(), rg.holeIndex() + 1, rg.round().size(), rg.hole().par()));
        }
        if (g != null) {
            int cur = g.currentPlayer();
            if (cur >= 0) {
                Gui.textColored(1f, 0.85f, 0.3f, 1f, turnLine(g.players().get(cur)));
            }
            Gui.beginTable("##players", 2, GuiTableFlags.SizingFixedFit); // names of any width line up
            for (int i = 0; i < g.players().size(); i++) {
                PlayerState s = g.player(i);
                float[] c = PlayerColors.of(i);
                Gui.tableNextRow();
                Gui.tableSetColumnIndex(0);
                Gui.textColored(c[0], c[1], c[2], 1f, g.players().get(i).name());
                Gui.tableSetColumnIndex(1);
                Gui.text(String.format(Locale.ROOT, "strokes %d%s%s%s", s.total(),
                        rg != null ? " (par " + rg.hole().par() + ")" : "",
                        s.penalties() > 0 ? " (" + s.penalties() + " penalty)" : "",
                        s.status() == PlayerStatus.PLAYING ? "" : ", " + words(s.status())));
            }
            Gui.endTable();
        }
        if (aimSpeed >= 0 && g != null) {
            double max = play.world().physics().maxSpeed();
            Gui.progressBar((float) (aimSpeed / max), 260, 0, String.format(Locale.ROOT, "power %.0f%%", 100 * aimSpeed / max));
        }
        // The stroke being set up, on a person's turn only (a bot chooses its own).
        if (g != null && !g.isOver() && g.currentPlayer() >= 0 && !g.players().get(g.currentPlayer()).isBot()) {
            Gui.text(Loft.describe(loftDegrees) + "  -  mouse wheel or Up / Down to " + (loftDegrees == 0 ? "chip" : "change"));
        }
        // The physics readout is for practice (expert) mode: a player's HUD shows no coordinates.
        boolean practice = app.settings().practice();
        if (g != null && practice) Gui.checkbox("details", details);
        BallReadout r = practice && details.get() ? readout() : null;
        if (r != null) {
            Gui.separator();
            Gui.text(String.format(Locale.ROOT, "position  (%.3f, %.3f, %.3f) m", r.x(), r.y(), r.z()));
            Gui.text(String.format(Locale.ROOT, "velocity  (%.3f, %.3f) m/s  |v| %.3f", r.vx(), r.vy(), r.speed()));
            Gui.text(String.format(Locale.ROOT, "accel.    (%.3f, %.3f) m/s^2  |a| %.3f", r.ax(), r.ay(), r.acceleration()));
            Gui.text(String.format(Locale.ROOT, "slope     %.3f (%.1f deg)", r.slope(), r.slopeDegrees()));
            Gui.text(String.format(Locale.ROOT, "friction  mu_k %.3f  mu_s %.3f", r.kineticFriction(), r.staticFriction()));
        }
        Gui.end();

        BotTurn bot = play.botTurn();
        if (bot != null) {
            PlanOverlay.draw(Gui.getBackgroundDrawList(), bot.plan(), p -> app.toScreen(p[0], p[1]));
            // At the top (at the bottom it hid the bot's own ball at the tee), below a notice if one is shown.
            float notice = app.noticeBottom();
            Gui.setNextWindowPos(w * 0.5f, notice > 0 ? notice + 8 : 12, GuiCond.Always, 0.5f, 0f);
            Gui.begin("##bot", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize);
            botPanel = Gui.windowRect();
            Game game = play.game();
            String who = game != null && game.currentPlayer() >= 0 ? game.players().get(game.currentPlayer()).name() : "The bot";
            // The bot's phase and simulations are for practice mode; a player sees that it is thinking.
            Gui.text(who + " is thinking" + (app.settings().practice() ? ": " + bot.message() : "\u2026"));
            Gui.progressBar((float) play.botProgress(), 320, 0);
            Gui.sameLine();
            if (Gui.button("Cancel")) play.cancelBot();
            Gui.end();
        }
        double waitLeft = play.botWaitLeft();
        if (!Double.isNaN(waitLeft)) {
            // A bot timing its shot to the moving obstacles: the planned moment, counting down.
            Gui.setNextWindowPos(w * 0.5f, h - 60, GuiCond.Always, 0.5f, 1f);
            Gui.begin("##botwait", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize);
            Gui.text(String.format(Locale.ROOT, "Bot waits for its moment: hits in %.1f s", waitLeft));
            Gui.end();
        }
    }

    float[] botPanel() {
        return botPanel;
    }

    /** "Ann to play"; a bot says it is one once ("Robo to play (computer)"; "Bot (planner) to play" as it is). */
    static String turnLine(Player p) {
        boolean named = p.name().toLowerCase(java.util.Locale.ROOT).contains("bot");
        return p.name() + " to play" + (p.isBot() && !named ? " (computer)" : "");
    }

    /** A player's status in words: "holed", "picked up". */
    static String words(PlayerStatus s) {
        return s.jsonName().replace('-', ' ');
    }

    /** The ball under the HUD: the rolling one, else the current player's. */
    private BallReadout readout() {
        Game game = app.play().game();
        if (game == null || game.currentPlayer() < 0) return null;
        World world = app.play().world();
        StrokeAnimator a = app.play().animator();
        if (a != null) return BallReadout.of(world, a.x(), a.y(), a.vx(), a.vy(), a.ax(), a.ay());
        PlayerState s = game.player(game.currentPlayer());
        return BallReadout.of(world, s.x(), s.y(), 0, 0, 0, 0);
    }
}
