package minigolf.cli;

import java.io.IOException;
import java.io.InputStream;
import java.util.Properties;
import picocli.CommandLine.IVersionProvider;

/**
 * {@code minigolf --version}: the version the build wrote into {@code minigolf/version.properties}
 * (from build.gradle's {@code version}, so it cannot drift), and the Java and OS it runs on, which is
 * what a bug report needs.
 */
public final class VersionInfo implements IVersionProvider {

    /** The build's version, or "unknown" when the classes run without the build's resources. */
    public static String version() {
        return property("version");
    }

    /** The git commit the classes were built from ("-dirty" with uncommitted changes), or "unknown". */
    public static String commit() {
        return property("commit");
    }

    private static String property(String key) {
        try (InputStream in = VersionInfo.class.getResourceAsStream("/minigolf/version.properties")) {
            if (in == null) return "unknown";
            Properties p = new Properties();
            p.load(in);
            return p.getProperty(key, "unknown");
        } catch (IOException e) {
            return "unknown";
        }
    }

    @Override
    public String[] getVersion() {
        return new String[]{
                "minigolf " + version(),
                "Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vm.name") + "), "
                        + System.getProperty("os.name") + " " + System.getProperty("os.arch")};
    }
}
