package ifold.cli;

import ifold.image.FrameSink;
import ifold.wrap.Wrap;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.function.LongSupplier;

/**
 * The progress of a frame export on stderr: a bar redrawn in place on a terminal, one line at the
 * end into a log or a pipe. Also that of a long wrap ({@link #wrapping}).
 */
final class ProgressBar implements FrameSink.Progress {
    /** Whether stderr is a terminal ({@link #stderrIsTerminal}). */
    private static final boolean ON_TERMINAL = stderrIsTerminal(System.console() != null, Path.of("/proc/self/fd/2"));
    private final PrintWriter out;
    private final boolean terminal;
    private final long start = System.nanoTime();
    private int lastPrinted = -1;

    /**
     * Whether stderr is a terminal, where a bar redrawn in place can be read: on Linux, what file
     * descriptor 2 links to ({@code stderrLink}: a terminal's device, not a file, a pipe or a
     * socket); elsewhere, whether the JVM has a console ({@code console}: stdin and stdout are a
     * terminal, and stderr goes there too as a rule). The console alone drew the bar, carriage
     * returns and all, into a log that {@code 2> log} sent stderr to.
     */
    static boolean stderrIsTerminal(boolean console, Path stderrLink) {
        try {
            String target = Files.readSymbolicLink(stderrLink).toString();
            return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty") || target.equals("/dev/console");
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            // No /proc (not Linux), descriptor 2 not a link, or not ours to read: the console decides.
            return console;
        }
    }

    ProgressBar(PrintWriter out) {
        this(out, ON_TERMINAL);
    }

    /** A frame export's bar, on a terminal or (a log, a pipe) not. */
    ProgressBar(PrintWriter out, boolean terminal) {
        this.out = out;
        this.terminal = terminal;
    }

    /**
     * The progress of a long wrap, triangle by triangle, as a bar on a terminal once the wrap has
     * taken {@link #LONG_WRAP_SECONDS} (and nothing in a log or a pipe, where the wrap's one
     * summary line says it all).
     */
    static WrapBar wrapping(PrintWriter out) {
        return wrapping(out, ON_TERMINAL, System::nanoTime);
    }

    /** {@link #wrapping(PrintWriter)}, as on a terminal or not, timed by {@code nanoClock}. */
    static WrapBar wrapping(PrintWriter out, boolean terminal, LongSupplier nanoClock) {
        return new WrapBar(out, terminal, nanoClock);
    }

    /** A wrap's bar: {@link #wipe()} clears it, however the wrap ended, before anything else is printed. */
    static final class WrapBar implements Wrap.Watcher {
        private static final int WIDTH = 30;
        private final PrintWriter out;
        private final boolean terminal;
        private final LongSupplier clock;
        private final long start;
        private int lastFilled = -1;
        /** The width of the last line drawn, bar or stage, which {@link #wipe()} clears; 0 for none. */
        private int drawn;

        private WrapBar(PrintWriter out, boolean terminal, LongSupplier clock) {
            this.out = out;
            this.terminal = terminal;
            this.clock = clock;
            this.start = clock.getAsLong();
        }

        @Override
        public void wrapped(int done, int total) {
            int filled = (int) ((long) WIDTH * done / Math.max(1, total));
            if (!terminal || filled == lastFilled || (lastFilled < 0 && clock.getAsLong() - start < LONG_WRAP_SECONDS * 1_000_000_000L)) {
                return;
            }
            lastFilled = filled;
            String line = String.format(Locale.ROOT, "[%s%s] %d/%d triangles wrapped", "#".repeat(filled), " ".repeat(WIDTH - filled), done, total);
            draw(line);
        }

        /**
         * A stage after the folds (placing and measuring the paper, checking it, writing the
         * files), in place of the bar, once the run has taken {@link #LONG_WRAP_SECONDS}: after
         * the bar a big model's wrap would otherwise sit silent for as long again.
         */
        void stage(String what) {
            if (!terminal || clock.getAsLong() - start < LONG_WRAP_SECONDS * 1_000_000_000L) {
                return;
            }
            draw(what + " ...");
        }

        private void draw(String line) {
            // Spaces over what is left of a longer line before.
            out.print("\r" + line + " ".repeat(Math.max(0, drawn - line.length())));
            out.flush();
            drawn = line.length();
        }

        @Override
        public boolean stopped() {
            return false;
        }

        void wipe() {
            if (drawn > 0) {
                out.print("\r" + " ".repeat(Math.max(WIDTH + 40, drawn)) + "\r");
                out.flush();
                drawn = 0;
            }
        }
    }

    /** Seconds after which a wrap still running shows its progress. */
    static final int LONG_WRAP_SECONDS = 2;

    @Override
    public void framesDone(int done, int total) {
        if (done == lastPrinted) {
            return;
        }
        if (!terminal && done != total) {
            return; // into a log or a pipe, one line at the end: a bar's steps there are only noise
        }
        lastPrinted = done;
        int width = 30;
        int filled = total == 0 ? width : (int) ((long) width * done / total);
        double seconds = (System.nanoTime() - start) * 1e-9;
        out.printf(Locale.ROOT, "%s[%s%s] %d/%d frames, %.1f frames/s%s", terminal ? "\r" : "", "#".repeat(filled),
                " ".repeat(width - filled), done, total, seconds > 0 ? done / seconds : 0.0, terminal && done < total ? "" : "\n");
        out.flush();
    }
}
