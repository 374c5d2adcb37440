package minigolf.app;

import minigolf.game.AudioSettings;
import minigolf.game.Game;
import minigolf.game.UserSettings;
import minigolf.ui.Gui;
import minigolf.ui.GuiBool;
import minigolf.ui.GuiInt;
import minigolf.ui.GuiString;
import minigolf.ui.Panels;
import minigolf.ui.Screen;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/**
 * The Settings screen: the game's rules, practice mode, window, graphics, sound and mouse; applied
 * together, checked first. Physics (integrator, step, gravity, friction) is not a player's setting:
 * it belongs to the course file, the editor and the command line. The course itself is never changed here (its values belong to
 * the course file and the editor): Apply once rebuilt the course and lost its obstacles.
 */
final class SettingsScreen extends GameScreen {
    /** Where Apply and Cancel go back to. */
    private Screen back;
    private String formError;
    private final GuiBool vsync = new GuiBool(true);
    private final GuiBool realistic = new GuiBool(false);
    private final GuiBool hideFriction = new GuiBool(false);
    private final GuiString classicFolder = new GuiString(512);
    private final GuiInt frameLimit = new GuiInt(60);
    private final GuiInt strokeLimit = new GuiInt(Game.DEFAULT_STROKE_LIMIT);
    private final float[] mouseSpeed = {1f};
    private final GuiBool aimGuide = new GuiBool(true);
    private final GuiBool antiAliasing = new GuiBool(false);
    private final GuiBool fullscreen = new GuiBool(false);
    private final GuiBool practice = new GuiBool(false);
    private final GuiInt graphics = new GuiInt(0);
    private final GuiInt windowSize = new GuiInt(0);
    /** The window sizes offered (0 x 0: the default 1280 x 720), with the player's own size added if it is another. */
    private int[][] sizes = SIZES;
    private static final int[][] SIZES = {{0, 0}, {1366, 768}, {1600, 900}, {1920, 1080}, {2560, 1440}};
    private static final String[] GRAPHICS_LABELS = {"Auto", "High", "Low"};
    private final float[] masterVolume = {0.8f}, effectsVolume = {1f}, ambienceVolume = {0.35f};

    SettingsScreen(GameApp app) {
        super(app);
    }

    /** Fills the form from the settings in use; Apply and Cancel go back to {@code returnTo}. */
    void open(Screen returnTo) {
        back = returnTo;
        formError = null;
        UserSettings s = app.settings();
        practice.set(s.practice());
        vsync.set(s.vsync());
        realistic.set(s.noisePosition() > 0 || s.noiseVelocity() > 0);
        hideFriction.set(s.hideFrictionFromBots());
        classicFolder.set(s.classicFolder());
        frameLimit.set(s.frameLimit());
        strokeLimit.set(s.strokeLimit());
        mouseSpeed[0] = (float) s.mouseSpeed();
        aimGuide.set(s.aimGuide());
        antiAliasing.set(s.antiAliasing());
        fullscreen.set(s.fullscreen());
        graphics.set(Math.max(0, UserSettings.GRAPHICS.indexOf(s.graphics())));
        sizes = SIZES;
        int at = -1;
        for (int i = 0; i < SIZES.length; i++) if (SIZES[i][0] == s.windowWidth() && SIZES[i][1] == s.windowHeight()) at = i;
        if (at < 0) { // the player's own size from the settings file stays on offer
            sizes = java.util.Arrays.copyOf(SIZES, SIZES.length + 1);
            sizes[SIZES.length] = new int[]{s.windowWidth(), s.windowHeight()};
            at = SIZES.length;
        }
        windowSize.set(at);
        AudioSettings volumes = app.files().volumes();
        masterVolume[0] = (float) volumes.master();
        effectsVolume[0] = (float) volumes.effects();
        ambienceVolume[0] = (float) volumes.ambience();
    }

    @Override
    public void render(float w, float h) {
        Panels.centre(w, h);
        Gui.begin("Settings", Panels.PANEL);
        Panels.heading("Game");
        Gui.inputInt("Stroke limit", strokeLimit);
        Gui.sameLine(); // pairs on a row: the form fits a 720-pixel-high window
        Gui.checkbox("Aim guide (off: pro)", aimGuide);
        if (Gui.isItemHovered()) Gui.setTooltip("While aiming, dots show where the putt goes until it stops or drops");
        Gui.checkbox("Realistic (every stroke strays a little, bots' too; next game)", realistic);
        Gui.checkbox("Hide friction from bots (they learn it from their strokes)", hideFriction);
        Gui.checkbox("Practice mode: type a shot's velocity, see the ball's physics (V)", practice);
        Gui.setNextItemWidth(300);
        Gui.inputText("Classic tracks folder", classicFolder);
        if (Gui.isItemHovered()) Gui.setTooltip("What minigolf import-tracks wrote; empty: <config>/classic");
        Panels.heading("Display");
        String[] sizeLabels = new String[sizes.length];
        for (int i = 0; i < sizes.length; i++) {
            sizeLabels[i] = sizes[i][0] == 0 ? "1280 x 720" : sizes[i][0] + " x " + sizes[i][1];
        }
        Gui.setNextItemWidth(170);
        Gui.combo("Window", windowSize, sizeLabels);
        Gui.sameLine();
        Gui.checkbox("Full screen (F11)", fullscreen);
        Gui.setNextItemWidth(170);
        Gui.combo("Graphics", graphics, GRAPHICS_LABELS);
        if (Gui.isItemHovered()) Gui.setTooltip("Auto: high on a graphics card, low on software rendering; multisampling changes at the next start");
        Gui.sameLine();
        Gui.checkbox("Smooth edges (FXAA)", antiAliasing);
        if (Gui.isItemHovered()) Gui.setTooltip("Anti-aliasing where there is no MSAA; costs about 8 ms a frame with software rendering");
        Gui.inputInt("Frame limit (0 = none)", frameLimit);
        Gui.sameLine();
        Gui.checkbox("Vsync", vsync);
        Panels.heading("Sound and mouse");
        Gui.sliderFloat("Volume", masterVolume, 0f, 1f);
        Gui.sliderFloat("Effects", effectsVolume, 0f, 1f);
        Gui.sliderFloat("Ambience", ambienceVolume, 0f, 1f);
        Gui.sliderFloat("Mouse speed", mouseSpeed, 0.2f, 5f);
        Gui.separator();
        if (formError != null) Gui.textColored(1f, 0.5f, 0.4f, 1f, formError);
        if (Gui.button("Apply")) apply();
        Gui.sameLine();
        if (Gui.button("Cancel")) app.setScreen(back);
        Gui.end();
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        app.setScreen(back);
        return true;
    }

    /** What "Apply" does: the form checked, applied and saved, and back to where Settings was opened. */
    void apply() {
        try {
            UserSettings s = app.settings().withPractice(practice.get()).withVsync(vsync.get()).withFrameLimit(frameLimit.get())
                    .withStrokeLimit(strokeLimit.get()).withMouseSpeed(mouseSpeed[0])
                    .withHideFrictionFromBots(hideFriction.get()).withClassicFolder(classicFolder.get().strip())
                    .withAimGuide(aimGuide.get()).withAntiAliasing(antiAliasing.get())
                    .withFullscreen(fullscreen.get()).withGraphics(UserSettings.GRAPHICS.get(graphics.get()))
                    .withWindowSize(sizes[windowSize.get()][0], sizes[windowSize.get()][1]);
            // Keeps noise levels set in the settings file; the box turns the default levels on or all noise off.
            boolean wasOn = s.noisePosition() > 0 || s.noiseVelocity() > 0;
            if (realistic.get() != wasOn) {
                s = realistic.get() ? s.withNoise(UserSettings.REALISTIC_POSITION, UserSettings.REALISTIC_VELOCITY)
                        : s.withNoise(0, 0);
            }
            app.applySettings(s);
            app.applyVolumes(new AudioSettings(masterVolume[0], effectsVolume[0], ambienceVolume[0]));
            formError = null;
            app.setScreen(back);
        } catch (UserSettings.InvalidSetting e) {
            formError = e.forPlayer();
        } catch (IllegalArgumentException e) {
            formError = e.getMessage();
        }
    }
}
