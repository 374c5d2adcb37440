package minigolf;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.lang.ArchRule;
import com.tngtech.archunit.library.dependencies.SliceAssignment;
import com.tngtech.archunit.library.dependencies.SliceIdentifier;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The project's package rules (TEAM standards, docs/architecture in README's layout section), checked
 * on the production classes: no package depends on itself through others, and the headless core
 * (course, terrain, physics, collision, bots) uses no OpenGL/LWJGL and nothing of the game, editor,
 * command line or rendering above it.
 *
 * <p>Documented exceptions: none. Test sources are not checked: their shared helpers (e.g.
 * {@code minigolf.bot.TileCourses}, used by tests in the bot subpackages) form cycles on purpose.
 */
class ArchitectureTest {
    /** The packages that must run headless, with no window, GPU or UI. */
    static final String[] HEADLESS = {"minigolf.course..", "minigolf.terrain..", "minigolf.physics..",
            "minigolf.collision..", "minigolf.bot.."};

    private static JavaClasses production;

    @BeforeAll
    static void importProductionClasses() {
        production = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("minigolf");
        assertTrue(production.contain("minigolf.bot.Bot") && production.contain("minigolf.app.GameApp"),
                "the import must see the production classes");
    }

    /** Each package under minigolf is one slice (subpackages are slices of their own). */
    static final SliceAssignment EVERY_PACKAGE = new SliceAssignment() {
        @Override
        public SliceIdentifier getIdentifierOf(JavaClass javaClass) {
            String pkg = javaClass.getPackageName();
            return pkg.equals("minigolf") || pkg.startsWith("minigolf.") ? SliceIdentifier.of(pkg) : SliceIdentifier.ignore();
        }

        @Override
        public String getDescription() {
            return "every package under minigolf";
        }
    };

    static ArchRule noPackageCycles() {
        return slices().assignedFrom(EVERY_PACKAGE).should().beFreeOfCycles();
    }

    static ArchRule noOpenGl(String... packages) {
        return noClasses().that().resideInAnyPackage(packages)
                .should().dependOnClassesThat().resideInAnyPackage("org.lwjgl..")
                .because("course, terrain, physics, collision and bots are plain Java, tested headless");
    }

    @Test
    void noPackageDependsOnItselfThroughOthers() {
        noPackageCycles().check(production);
    }

    @Test
    void theHeadlessCoreUsesNoOpenGl() {
        noOpenGl(HEADLESS).check(production);
    }

    /** The online server runs headless on a machine without a display; the game rules it uses have no OpenGL either. */
    @Test
    void theOnlineServerAndItsRulesUseNoOpenGl() {
        noOpenGl("minigolf.online..", "minigolf.game..").check(production);
        noClasses().that().resideInAnyPackage("minigolf.online..")
                .should().dependOnClassesThat().resideInAnyPackage("minigolf.app..", "minigolf.render..", "minigolf.ui..",
                        "minigolf.editor..")
                .because("the server and the headless client run without a window").check(production);
    }

    @Test
    void theHeadlessCoreUsesNothingOfTheLayersAboveIt() {
        noClasses().that().resideInAnyPackage(HEADLESS)
                .should().dependOnClassesThat().resideInAnyPackage("minigolf.app..", "minigolf.game..",
                        "minigolf.editor..", "minigolf.cli..", "minigolf.render..", "minigolf.ui..")
                .check(production);
    }

    @Test
    void theBotContractSitsBelowTheBotsAndTheRegistryAboveThem() {
        noClasses().that().resideInAPackage("minigolf.bot")
                .should().dependOnClassesThat().resideInAnyPackage("minigolf.bot.*..")
                .check(production);
        noClasses().that().resideOutsideOfPackages("minigolf.bot.play..", "minigolf.bot.experiment..")
                .and().resideInAPackage("minigolf.bot..")
                .should().dependOnClassesThat().resideInAnyPackage("minigolf.bot.play..", "minigolf.bot.experiment..")
                .check(production);
    }

    /** The rules can fail: a deliberate cycle and an OpenGL call in test fixtures are reported. */
    @Test
    void theRulesReportACycleAndAnOpenGlCall() {
        JavaClasses fixtures = new ClassFileImporter().importPackages("minigolf.architecturefixture");
        AssertionError cycle = assertThrows(AssertionError.class, () -> noPackageCycles().check(fixtures));
        assertTrue(cycle.getMessage().contains("minigolf.architecturefixture.cycle.a")
                && cycle.getMessage().contains("minigolf.architecturefixture.cycle.b"), cycle.getMessage());
        AssertionError gl = assertThrows(AssertionError.class,
                () -> noOpenGl("minigolf.architecturefixture.gl..").check(fixtures));
        assertTrue(gl.getMessage().contains("GlUser") && gl.getMessage().contains("org.lwjgl.opengl.GL11"), gl.getMessage());
    }
}
