package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** Standard error without JOGL's X11Util lines, and everything else as written. */
class JoglNoiseTest {
    @Test
    void joglsShutdownLinesGoAndEverythingElsePasses() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(new JoglNoise(bytes), true, StandardCharsets.UTF_8);
        err.println("ifold: interrupted: nothing written");
        err.println("X11Util.Display: Shutdown (JVM shutdown: true, open (no close attempt): 1/1)");
        err.println("X11Util: Open X11 Display Connections: 1");
        err.println("X11 is not X11Util");
        err.println("X1");
        err.println("");
        assertEquals("ifold: interrupted: nothing written\nX11 is not X11Util\nX1\n\n", bytes.toString(StandardCharsets.UTF_8));
    }

    @Test
    void joglsWarningOfAShutdownWhileItStartsGoesWithItsTrace() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(new JoglNoise(bytes), true, StandardCharsets.UTF_8);
        err.println("java.lang.Error: before any warning, a trace's first line passes");
        err.println("Warning: Caught Exception due to initializing TmpRoot:");
        err.println("java.lang.IllegalStateException: Shutdown in progress");
        err.println("\tat java.base/java.lang.ApplicationShutdownHooks.add(ApplicationShutdownHooks.java:66)");
        err.println("\tat com.jogamp.common.util.cache.TempFileCache.initTmpRoot(TempFileCache.java:242)");
        err.println("Caused by: nothing");
        err.println("ifold: interrupted: nothing written");
        err.println("\tan indented line after the trace passes");
        err.println("Warning: something else");
        assertEquals("java.lang.Error: before any warning, a trace's first line passes\nifold: interrupted: nothing written\n"
                + "\tan indented line after the trace passes\nWarning: something else\n", bytes.toString(StandardCharsets.UTF_8));
    }

    @Test
    void joglsHandledExceptionOfAShutdownWhileItSetsUpGoesWithItsTrace() {
        // As LauncherTest's signal at a random moment met it once (the machine busy, 2026-12-05).
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(new JoglNoise(bytes), true, StandardCharsets.UTF_8);
        err.println("ifold: interrupted: nothing written");
        err.println("Caught handled GLException: X11GLXDrawableFactory - Could not initialize shared resources for "
                + "X11GraphicsDevice[type .x11, connection :0, unitID 0, handle 0x0, owner false] on thread main-SharedResourceRunner");
        err.println("    [0]: jogamp.opengl.x11.glx.X11GLXDrawableFactory$SharedResourceImplementation.createSharedResource(X11GLXDrawableFactory.java:306)");
        err.println("    [1]: jogamp.opengl.SharedResourceRunner.run(SharedResourceRunner.java:353)");
        err.println("Caused[0] by NullPointerException: Cannot invoke \"jogamp.opengl.SharedResourceRunner.getOrCreateShared\" on thread main-SharedResourceRunner");
        err.println("    [0]: jogamp.opengl.x11.glx.X11GLXDrawableFactory.isGLXVersionGreaterEqualOneThree(X11GLXDrawableFactory.java:496)");
        err.println("a line of iFold's ends the trace");
        err.println("    [1]: an indented line after it passes");
        assertEquals("ifold: interrupted: nothing written\na line of iFold's ends the trace\n    [1]: an indented line after it passes\n",
                bytes.toString(StandardCharsets.UTF_8));
    }

    @Test
    void aProgressBarsCarriageReturnsPassAtOnce() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream err = new PrintStream(new JoglNoise(bytes), true, StandardCharsets.UTF_8);
        err.print("[###   ] 1/2\r");
        err.flush();
        assertEquals("[###   ] 1/2\r", bytes.toString(StandardCharsets.UTF_8));
        err.print("[######] 2/2\r");
        err.flush();
        assertEquals("[###   ] 1/2\r[######] 2/2\r", bytes.toString(StandardCharsets.UTF_8));
    }
}
