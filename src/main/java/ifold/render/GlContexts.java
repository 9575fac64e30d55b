package ifold.render;

import com.jogamp.opengl.GLCapabilities;
import com.jogamp.opengl.GLException;
import com.jogamp.opengl.GLProfile;

/** Finds an OpenGL 3.3 core profile, or explains in one line why there is none. */
final class GlContexts {
    private GlContexts() {
    }

    static GLCapabilities capabilities() throws RenderUnavailableException {
        String display = System.getenv("DISPLAY");
        if ((display == null || display.isEmpty()) && isLinux()) {
            throw new RenderUnavailableException("no display: run under Xvfb (xvfb-run -a ifold ...), "
                    + "or install it (apt-get install xvfb) so that the launcher can start it", null);
        }
        try {
            GLProfile profile = GLProfile.get(GLProfile.GL3);
            GLCapabilities caps = new GLCapabilities(profile);
            caps.setDepthBits(24);
            caps.setDoubleBuffered(true);
            return caps;
        } catch (GLException | UnsatisfiedLinkError | NoClassDefFoundError e) {
            throw new RenderUnavailableException("no OpenGL 3.3 core profile on display " + display + ": " + firstLine(e)
                    + " (install Mesa: apt-get install libgl1-mesa-dri)", e);
        }
    }

    private static boolean isLinux() {
        return System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux");
    }

    static String firstLine(Throwable e) {
        String message = String.valueOf(e.getMessage());
        int newline = message.indexOf('\n');
        return newline < 0 ? message : message.substring(0, newline);
    }
}
