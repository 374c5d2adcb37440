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
        try (InputStream in = VersionInfo.class.getResourceAsStream("/minigolf/version.properties")) {
            if (in == null) return "unknown";
            Properties p = new Properties();
            p.load(in);
            return p.getProperty("version", "unknown");
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
