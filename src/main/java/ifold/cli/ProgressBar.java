package ifold.cli;

import ifold.image.FrameSink;
import java.io.PrintWriter;
import java.util.Locale;

/**
 * The progress of a frame export on stderr: a bar redrawn in place on a terminal, a line every
 * tenth of the way into a log or a pipe.
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
