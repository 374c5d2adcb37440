package minigolf.ui;

import java.util.Locale;
import minigolf.game.BallReadout;
import minigolf.game.BotTurn;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.PlayerState;

/**
 * The HUD while a game is on (the round and hole, par, whose turn, strokes, the loft, a details
 * readout) and the Shot panel for typed velocities.
 */
final class Hud {
    private final Screens screens;
    // Typed shot.
    private final GuiDouble typedVx = new GuiDouble(1.0);
    private final GuiDouble typedVy = new GuiDouble(0.0);
    private final GuiDouble typedVz = new GuiDouble(0.0);
    /** The HUD's physics readout (position, velocity, acceleration, slope, friction): off unless asked for. */
    private final GuiBool details = new GuiBool(false);

    Hud(Screens screens) {
        this.screens = screens;
    }

    void hud(UiView view, float w, float h, boolean interactive) {
        Game g = view.game();
        Gui.setNextWindowPos(12, 12, GuiCond.Always);
        Gui.begin("##hud", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
        minigolf.game.RoundGame rg = view.round();
        if (rg != null) {
            Gui.textColored(0.6f, 0.9f, 1f, 1f, String.format(Locale.ROOT, "%s  -  hole %d of %d  -  par %d",
                    rg.round().name(), rg.holeIndex() + 1, rg.round().size(), rg.hole().par()));
        }
        if (g != null) {
            int cur = g.currentPlayer();
            if (cur >= 0) {
                Player p = g.players().get(cur);
                Gui.textColored(1f, 0.85f, 0.3f, 1f, p.name() + (p.isBot() ? " (bot: " + p.bot() + ")" : "") + " to play");
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
                        view.round() != null ? " (par " + view.round().hole().par() + ")" : "",
                        s.penalties() > 0 ? " (" + s.penalties() + " penalty)" : "",
                        s.status() == minigolf.game.PlayerStatus.PLAYING ? "" : ", " + s.status().jsonName()));
            }
            Gui.endTable();
        }
        double aim = view.aimSpeed();
        if (aim >= 0 && g != null) {
            double max = view.world().physics().maxSpeed();
            Gui.progressBar((float) (aim / max), 260, 0, String.format(Locale.ROOT, "power %.0f%%", 100 * aim / max));
        }
        if (g != null && !g.isOver()) Gui.text(minigolf.game.Loft.describe(view.loftDegrees()) + "   (wheel while aiming, Up/Down)");
        if (g != null) Gui.checkbox("details", details);
        BallReadout r = details.get() ? view.readout() : null;
        if (r != null) {
            Gui.separator();
            Gui.text(String.format(Locale.ROOT, "position  (%.3f, %.3f, %.3f) m", r.x(), r.y(), r.z()));
            Gui.text(String.format(Locale.ROOT, "velocity  (%.3f, %.3f) m/s  |v| %.3f", r.vx(), r.vy(), r.speed()));
            Gui.text(String.format(Locale.ROOT, "accel.    (%.3f, %.3f) m/s^2  |a| %.3f", r.ax(), r.ay(), r.acceleration()));
            Gui.text(String.format(Locale.ROOT, "slope     %.3f (%.1f deg)", r.slope(), r.slopeDegrees()));
            Gui.text(String.format(Locale.ROOT, "friction  mu_k %.3f  mu_s %.3f", r.kineticFriction(), r.staticFriction()));
        }
        Gui.end();

        BotTurn bot = view.botTurn();
        if (bot != null) {
            PlanOverlay.draw(Gui.getBackgroundDrawList(), bot.plan(), p -> view.toScreen(p[0], p[1]));
            Gui.setNextWindowPos(w * 0.5f, h - 60, GuiCond.Always, 0.5f, 1f);
            Gui.begin("##bot", GuiWindowFlags.NoDecoration | GuiWindowFlags.AlwaysAutoResize);
            Gui.text("Bot thinking: " + bot.message());
            Gui.progressBar((float) bot.progress(), 320, 0);
            Gui.sameLine();
            if (Gui.button("Cancel")) screens.actions.cancelBot();
            Gui.end();
        }
        boolean humanToPlay = g != null && !g.isShotInFlight() && g.currentPlayer() >= 0
                && !g.players().get(g.currentPlayer()).isBot() && bot == null;
        if (interactive && humanToPlay) shotPanel(view, w, h);
    }

    void shotPanel(UiView view, float w, float h) {
        double max = view.world().physics().maxSpeed();
        Gui.setNextWindowPos(w - 12, h - 12, GuiCond.Always, 1f, 1f);
        Gui.begin("Shot", GuiWindowFlags.NoCollapse | GuiWindowFlags.AlwaysAutoResize | GuiWindowFlags.NoMove);
        Gui.text("Drag back from the ball to aim, release to hit,");
        Gui.text("or type the velocity (max " + max + " m/s):");
        Gui.setNextItemWidth(120);
        Gui.inputDouble("vx", typedVx, 0.1, 0.5, "%.3f");
        Gui.setNextItemWidth(120);
        Gui.inputDouble("vy", typedVy, 0.1, 0.5, "%.3f");
        Gui.setNextItemWidth(120);
        Gui.inputDouble("vz (0 = putt)", typedVz, 0.1, 0.5, "%.3f");
        double speed = Math.sqrt(typedVx.get() * typedVx.get() + typedVy.get() * typedVy.get() + typedVz.get() * typedVz.get());
        Gui.progressBar((float) Math.min(1, speed / max), 240, 0, String.format(Locale.ROOT, "%.2f m/s", speed));
        String problem = minigolf.game.AimModel.checkTyped(typedVx.get(), typedVy.get(), typedVz.get(), max);
        if (problem != null) Gui.textColored(1f, 0.5f, 0.4f, 1f, problem);
        if (problem != null) Gui.beginDisabled();
        if (Gui.button("HIT", 120, 0)) screens.actions.hit(typedVx.get(), typedVy.get(), typedVz.get());
        if (problem != null) Gui.endDisabled();
        double aim = view.aimSpeed();
        if (aim >= 0) {
            Gui.progressBar((float) (aim / max), 240, 0, String.format(Locale.ROOT, "power %.2f m/s", aim));
        }
        Gui.end();
    }
}
