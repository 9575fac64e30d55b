package ifold.cli;

import ifold.image.FrameSink;
import ifold.wrap.Wrap;
import java.io.PrintWriter;
import java.util.Locale;

/**
 * The progress of a frame export on stderr: a bar redrawn in place on a terminal, a line every
 * tenth of the way into a log or a pipe. Also that of a long wrap ({@link #wrapping}).
 */
final class ProgressBar implements FrameSink.Progress {
    /** Whether stderr is a terminal: the JVM has a console (stdin and stdout are one), and stderr goes there too as a rule. */
    private static final boolean ON_TERMINAL = System.console() != null;
    private final PrintWriter out;
    private final long start = System.nanoTime();
    private int lastPrinted = -1;

    ProgressBar(PrintWriter out) {
        this.out = out;
    }

    /**
     * The progress of a long wrap, triangle by triangle, as a bar on a terminal (and nothing in
     * a log or a pipe, where the wrap's one summary line says it all).
     */
    static WrapBar wrapping(PrintWriter out, int triangles) {
        return wrapping(out, triangles, ON_TERMINAL);
    }

    /** {@link #wrapping(PrintWriter, int)}, as on a terminal or not. */
    static WrapBar wrapping(PrintWriter out, int triangles, boolean terminal) {
        return new WrapBar(out, terminal && triangles >= LONG_WRAP);
    }

    /** A wrap's bar: {@link #wipe()} clears it, however the wrap ended, before anything else is printed. */
    static final class WrapBar implements Wrap.Watcher {
        private static final int WIDTH = 30;
        private final PrintWriter out;
        private final boolean shown;
        private int lastFilled = -1;

        private WrapBar(PrintWriter out, boolean shown) {
            this.out = out;
            this.shown = shown;
        }

        @Override
        public void wrapped(int done, int total) {
            int filled = (int) ((long) WIDTH * done / Math.max(1, total));
            if (!shown || filled == lastFilled) {
                return;
            }
            lastFilled = filled;
            out.printf(Locale.ROOT, "\r[%s%s] %d/%d triangles wrapped", "#".repeat(filled), " ".repeat(WIDTH - filled), done, total);
            out.flush();
        }

        @Override
        public boolean stopped() {
            return false;
        }

        void wipe() {
            if (shown && lastFilled >= 0) {
                out.print("\r" + " ".repeat(WIDTH + 40) + "\r");
                out.flush();
            }
        }
    }

    /** Triangles on the path from which a wrap takes long enough (a second or more) to show its progress. */
    static final int LONG_WRAP = 1000;

    @Override
    public void framesDone(int done, int total) {
        if (done == lastPrinted) {
            return;
        }
        if (!ON_TERMINAL && done != total && (long) done * 10 / Math.max(1, total) == (long) lastPrinted * 10 / Math.max(1, total)) {
            return;
        }
        lastPrinted = done;
        int width = 30;
        int filled = total == 0 ? width : (int) ((long) width * done / total);
        double seconds = (System.nanoTime() - start) * 1e-9;
        out.printf(Locale.ROOT, "%s[%s%s] %d/%d frames, %.1f frames/s%s", ON_TERMINAL ? "\r" : "", "#".repeat(filled),
                " ".repeat(width - filled), done, total, seconds > 0 ? done / seconds : 0.0, ON_TERMINAL && done < total ? "" : "\n");
        out.flush();
    }
}
