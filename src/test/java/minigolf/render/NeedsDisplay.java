package minigolf.render;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.condition.EnabledIf;

/**
 * A test that opens a real (visible) window: skipped on a machine with no display, where the
 * off-screen tests still run through EGL. CI runs these under Xvfb (.ci/run).
 */
@Target({ElementType.TYPE, ElementType.METHOD})
@Retention(RetentionPolicy.RUNTIME)
@EnabledIf(value = "minigolf.render.Displays#present", disabledReason = "no display (DISPLAY is unset): run under xvfb-run")
public @interface NeedsDisplay {
}
