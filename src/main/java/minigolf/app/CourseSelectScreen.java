package minigolf.app;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import minigolf.classic.ClassicIndex;
import minigolf.game.HighScores;
import minigolf.game.Round;
import minigolf.ui.Gui;
import minigolf.ui.GuiInt;
import minigolf.ui.GuiString;
import minigolf.ui.GuiTableFlags;
import minigolf.ui.GuiWindowFlags;
import minigolf.ui.Panels;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_ESCAPE;

/**
 * Choosing what to play: the rounds (holes, par, the best round anyone played), then the single
 * holes for practice, each with a preview rendered by the game's renderer (one a frame, so the
 * screen stays responsive), its par where it is a hole of a round, and the best score on it, then
 * the classic tracks imported with {@code minigolf import-tracks} (searched by name and category,
 * the human average and best beside the players' own best). The folders are read again each time
 * the screen opens: a course the editor saved a moment ago is listed.
 */
final class CourseSelectScreen extends GameScreen {
    /** Classic tracks listed a page at a time. */
    static final int CLASSIC_PAGE = 12;
    static final String[] CATEGORIES = {"all", "basic", "traditional", "modern", "hio", "short", "long"};
    private List<CourseFolders.CourseEntry> courses;
    private List<CourseFolders.RoundEntry> rounds;
    /** Each course file that is a hole of a round: the round and the hole's number (0-based) and par. */
    private Map<Path, List<RoundHole>> holes;

    private record RoundHole(Round round, int hole) {
    }
    private ClassicIndex.Index classic;
    private String classicProblem;
    private final GuiString classicSearch = new GuiString(64);
    private final GuiInt classicCategory = new GuiInt(0);
    private int classicPage;

    CourseSelectScreen(GameApp app) {
        super(app);
    }

    @Override
    public void show() {
        courses = null;
        rounds = null;
        holes = null;
        classic = null;
        classicProblem = null;
    }

    /** The imported classic tracks (read the first time after the screen opened); an empty index if there are none. */
    ClassicIndex.Index classic() {
        if (classic == null) {
            Path folder = CourseFolders.classicFolder(app.files().store(), app.settings());
            classicProblem = null;
            try {
                classic = java.nio.file.Files.isRegularFile(folder.resolve("index.json")) ? ClassicIndex.read(folder)
                        : new ClassicIndex.Index(List.of(), List.of());
            } catch (IOException e) {
                classic = new ClassicIndex.Index(List.of(), List.of());
                classicProblem = e.getMessage();
            }
        }
        return classic;
    }

    /** The classic tracks the search and the category let through. */
    List<ClassicIndex.Entry> classicMatches() {
        String category = classicCategory.get() == 0 ? null : CATEGORIES[classicCategory.get()];
        List<ClassicIndex.Entry> out = new ArrayList<>();
        for (ClassicIndex.Entry e : classic().tracks()) if (e.matches(classicSearch.get(), category)) out.add(e);
        return out;
    }

    /** The key under which the players' scores on a classic track are kept (high scores, hole 0). */
    static String scoreKey(ClassicIndex.Entry e) {
        return "classic: " + e.folder();
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
        // The rounds' previews (their first hole) first, then the single courses'; one a frame.
        List<CourseFolders.CourseEntry> previews = new ArrayList<>();
        for (CourseFolders.RoundEntry r : rounds()) previews.add(new CourseFolders.CourseEntry(r.round().name(), firstHole(r), false));
        previews.addAll(courses());
        app.thumbnails().renderNext(previews, 200, 120);
    }

    /** The file of a round's first hole (its preview stands for the round). */
    private static Path firstHole(CourseFolders.RoundEntry r) {
        return r.file().toAbsolutePath().getParent().resolve(r.round().hole(0).course()).normalize();
    }

    @Override
    public void render(float w, float h) {
        Panels.centre(w, h);
        Gui.setNextWindowSize(Math.min(w - 40, 760), Math.min(h - 40, 560));
        Gui.begin("Select course", GuiWindowFlags.NoCollapse | GuiWindowFlags.NoMove | GuiWindowFlags.NoResize);
        Panels.heading("Rounds");
        HighScores scores = app.files().highScores();
        for (CourseFolders.RoundEntry r : rounds()) {
            HighScores.Best best = scores == null ? null : scores.bestRound(r.round().name());
            String label = String.format(Locale.ROOT, "%s  -  %d holes, par %d  -  %s##%s", r.round().name(), r.round().size(),
                    r.round().par(), best == null ? "not played yet" : "best " + best.score() + " (" + best.name() + ")", r.file());
            int tex = app.thumbnails().texture(firstHole(r));
            boolean chosen = tex != 0 ? Gui.imageButton(tex, 100, 60) : Gui.button("...##" + r.file(), 108, 68);
            Gui.sameLine();
            chosen |= Gui.button(label, 520, 68);
            if (chosen) {
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
            for (int i = 0; i < three.size(); i++) {
                if (i > 0) Gui.sameLine(i * (cell + Gui.itemSpacingX()));
                Gui.textDisabled(parAndBest(three.get(i), scores));
            }
        }
        Gui.separator();
        classicSection();
        Gui.separator();
        if (Gui.button("Back")) app.setScreen(app.screens().mainMenu());
        Gui.end();
    }

    /** "par 3  -  best 2 (Ann)": the par where the course is a hole of a round, the best anyone scored on it (in a round or alone). */
    String parAndBest(CourseFolders.CourseEntry c, HighScores scores) {
        List<RoundHole> in = holesByFile().getOrDefault(c.file().toAbsolutePath().normalize(), List.of());
        String par = in.isEmpty() ? "no par" : "par " + in.get(0).round().hole(in.get(0).hole()).par();
        HighScores.Best best = scores == null ? null : scores.bestOnHole(HighScores.practiceKey(c.name()), 0);
        for (RoundHole h : in) {
            HighScores.Best b = scores == null ? null : scores.bestOnHole(h.round().name(), h.hole());
            if (b != null && (best == null || b.score() < best.score())) best = b;
        }
        return par + "  -  " + (best == null ? "not played yet" : "best " + best.score() + " (" + best.name() + ")");
    }

    private Map<Path, List<RoundHole>> holesByFile() {
        if (holes != null) return holes;
        holes = new HashMap<>();
        for (CourseFolders.RoundEntry r : rounds()) {
            Path folder = r.file().toAbsolutePath().getParent();
            for (int i = 0; i < r.round().size(); i++) {
                Path course = folder.resolve(r.round().hole(i).course()).normalize();
                holes.computeIfAbsent(course, k -> new ArrayList<>()).add(new RoundHole(r.round(), i));
            }
        }
        return holes;
    }

    private void classicSection() {
        ClassicIndex.Index index = classic();
        Panels.heading("Classic tracks");
        if (classicProblem != null) {
            Gui.textWrapped(classicProblem);
            return;
        }
        if (index.tracks().isEmpty()) {
            // No folder named here: a player's view shows no file paths (where they go: docs/classic-tracks.md).
            Gui.textWrapped("None imported yet: the command minigolf import-tracks reads the classic game's track files"
                    + " (see docs/classic-tracks.md).");
            return;
        }
        Gui.setNextItemWidth(220);
        if (Gui.inputText("Search name or author", classicSearch)) classicPage = 0;
        Gui.sameLine();
        Gui.setNextItemWidth(130);
        if (Gui.combo("Category", classicCategory, CATEGORIES)) classicPage = 0;
        List<ClassicIndex.Entry> matches = classicMatches();
        int pages = Math.max(1, (matches.size() + CLASSIC_PAGE - 1) / CLASSIC_PAGE);
        classicPage = Math.min(classicPage, pages - 1);
        List<String> names = app.settings().playerNames();
        if (Gui.beginTable("##classic", 5, GuiTableFlags.RowBg | GuiTableFlags.SizingFixedFit)) {
            Gui.tableSetupColumn("Track");
            Gui.tableSetupColumn("Author");
            Gui.tableSetupColumn("Human average");
            Gui.tableSetupColumn("Human best");
            Gui.tableSetupColumn("Your best");
            Gui.tableHeadersRow();
            for (ClassicIndex.Entry e : matches.subList(classicPage * CLASSIC_PAGE, Math.min(matches.size(), (classicPage + 1) * CLASSIC_PAGE))) {
                Gui.tableNextRow();
                Gui.tableSetColumnIndex(0);
                if (Gui.selectable(e.name() + "##" + e.folder(), false)) selectClassic(e);
                Gui.tableSetColumnIndex(1);
                Gui.text(e.author());
                Gui.tableSetColumnIndex(2);
                Gui.text(Double.isNaN(e.averageStrokes()) ? "-" : String.format(Locale.ROOT, "%.1f", e.averageStrokes()));
                Gui.tableSetColumnIndex(3);
                Gui.text(e.bestStrokes() > 0 ? String.valueOf(e.bestStrokes()) : "-");
                Gui.tableSetColumnIndex(4);
                Integer mine = app.files().classicBest(scoreKey(e), names);
                Gui.text(mine == null ? "-" : String.valueOf(mine));
            }
            Gui.endTable();
        }
        Gui.text(String.format(Locale.ROOT, "%d of %d tracks, page %d of %d", matches.size(), index.tracks().size(),
                classicPage + 1, pages));
        Gui.sameLine();
        if (Gui.button("Previous page") && classicPage > 0) classicPage--;
        Gui.sameLine();
        if (Gui.button("Next page") && classicPage + 1 < pages) classicPage++;
    }

    void selectClassic(ClassicIndex.Entry e) {
        try {
            app.play().selectCourse(e.course(), scoreKey(e));
            app.setScreen(app.screens().mainMenu());
        } catch (minigolf.course.CourseException ex) {
            app.say("That track could not be loaded: " + ex.problem());
        }
    }

    private void select(CourseFolders.CourseEntry c) {
        try {
            app.play().selectCourse(c.file());
            app.setScreen(app.screens().mainMenu());
        } catch (minigolf.course.CourseException e) {
            app.say("That course could not be loaded: " + e.problem());
        }
    }

    @Override
    public boolean keyPressed(int key, int mods) {
        if (key != GLFW_KEY_ESCAPE) return false;
        app.setScreen(app.screens().mainMenu());
        return true;
    }
}
