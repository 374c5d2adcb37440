package minigolf.app;

import java.util.List;
import java.util.Locale;
import minigolf.ui.Gui;
import minigolf.ui.GuiWindowFlags;
import minigolf.ui.Panels;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/**
 * Choosing what to play: the rounds, then the single holes for practice, each with a preview
 * rendered by the game's renderer (one a frame, so the screen stays responsive). The folders are
 * read again each time the screen opens: a course the editor saved a moment ago is listed.
 */
final class CourseSelectScreen extends GameScreen {
    private List<CourseFolders.CourseEntry> courses;
    private List<CourseFolders.RoundEntry> rounds;

    CourseSelectScreen(GameApp app) {
        super(app);
    }

    @Override
    public void show() {
        courses = null;
        rounds = null;
    }

    /** The single courses offered (read from the folders the first time after the screen opened). */
    List<CourseFolders.CourseEntry> courses() {
        if (courses == null) courses = CourseFolders.list(app.files().store());
        return courses;
    }

    List<CourseFolders.RoundEntry> rounds() {
        if (rounds == null) rounds = CourseFolders.rounds(app.files().store());
        return rounds;
    }

    @Override
    public void update(double elapsed) {
        app.thumbnails().renderNext(courses(), 200, 120);
    }

    @Override
    public void render(float w, float h) {
        Panels.centre(w, h);
        Gui.setNextWindowSize(Math.min(w - 40, 760), Math.min(h - 40, 560));
        Gui.begin("Select course", GuiWindowFlags.NoCollapse | GuiWindowFlags.NoMove | GuiWindowFlags.NoResize);
        Panels.heading("Rounds");
        for (CourseFolders.RoundEntry r : rounds()) {
            String label = String.format(Locale.ROOT, "%s  (%d holes, par %d)##%s", r.round().name(), r.round().size(),
                    r.round().par(), r.file());
            if (Gui.button(label, 420, 0)) {
                app.play().chooseRound(r.round());
                app.setScreen(app.screens().newGame());
            }
        }
        if (rounds().isEmpty()) Gui.text("(no rounds found)");
        Gui.separator();
        Panels.heading("Practice (single holes)");
        // Three previews to a row, each course's name under its preview.
        List<CourseFolders.CourseEntry> all = courses();
        for (int row = 0; row < all.size(); row += 3) {
            List<CourseFolders.CourseEntry> three = all.subList(row, Math.min(all.size(), row + 3));
            float cell = 0;
            for (int i = 0; i < three.size(); i++) {
                CourseFolders.CourseEntry c = three.get(i);
                if (i > 0) Gui.sameLine();
                int tex = app.thumbnails().texture(c.file());
                if (tex != 0) {
                    if (Gui.imageButton(tex, 200, 120)) select(c);
                } else if (Gui.button("rendering...##" + c.file(), 208, 128)) {
                    select(c);
                }
                cell = Gui.getItemRectSizeX();
            }
            for (int i = 0; i < three.size(); i++) {
                CourseFolders.CourseEntry c = three.get(i);
                if (i > 0) Gui.sameLine(i * (cell + Gui.itemSpacingX()));
                Gui.text(c.name() + (c.own() ? " (yours)" : ""));
            }
        }
        Gui.separator();
        if (Gui.button("Back")) app.setScreen(app.screens().mainMenu());
        Gui.end();
    }

    private void select(CourseFolders.CourseEntry c) {
        try {
            app.play().selectCourse(c.file());
            app.setScreen(app.screens().mainMenu());
        } catch (minigolf.course.CourseException e) {
            app.say(e.getMessage());
        }
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        app.setScreen(app.screens().mainMenu());
        return true;
    }
}
