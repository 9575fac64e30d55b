package ifold.cli;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

/**
 * Standard error without JOGL's own bookkeeping: stopped by Ctrl-C or SIGTERM while it renders,
 * JOGL's shutdown prints the X display connections it still holds ("X11Util.Display: Shutdown
 * ...", "X11Util: Open ..."), which say nothing to a user, under iFold's one line; stopped while
 * JOGL is still starting, it prints that it could not register its temporary files' cleanup
 * ("Warning: Caught Exception due to initializing TmpRoot:", then the exception's trace), as
 * the JVM was already shutting down; stopped while its X11 factory sets up, that it caught and
 * handled the exception ("Caught handled GLException: ...", then its own trace). Lines that
 * begin with {@code X11Util} go, and those two with the lines of their trace after them (those
 * that begin with a tab, "java.", "Caused by", or JOGL's "    [" and "Caused[");
 * everything else passes as written, a line at a time (a progress bar's carriage returns and
 * flushes pass at once).
 */
final class JoglNoise extends OutputStream {
    /** JOGL's warning that it could not register its temporary files' cleanup: the trace after it goes too. */
    private static final byte[] WARNING = ascii("Warning: Caught Exception due to initializing TmpRoot");
    /**
     * JOGL's report of an exception it handled itself, the trace after it going too: stopped while
     * its X11 factory was setting up, it could not ("Caught handled GLException:
     * X11GLXDrawableFactory - Could not initialize shared resources ...", a signal in one run of
     * 20 of LauncherTest's, the machine busy).
     */
    private static final byte[] HANDLED = ascii("Caught handled GLException");
    /** The beginnings of JOGL's lines that go. */
    private static final byte[][] DROPPED = {ascii("X11Util"), WARNING, HANDLED};
    /** The beginnings of a trace's lines, which go after a dropped warning: Java's, and JOGL's own ("    [0]: ...", "Caused[0] by ..."). */
    private static final byte[][] TRACE = {ascii("\t"), ascii("java."), ascii("Caused by"), ascii("    ["), ascii("Caused[")};

    private final OutputStream out;
    /** The line begun and not yet passed on: held only while it may still begin as one that goes. */
    private final ByteArrayOutputStream line = new ByteArrayOutputStream();
    /** Whether the line begun is passed on as it comes (it cannot begin as one that goes), or dropped. */
    private boolean passing;
    private boolean dropping;
    /** Whether the lines just dropped were a warning's, whose trace's lines go too. */
    private boolean inTrace;

    JoglNoise(OutputStream out) {
        this.out = out;
    }

    private static byte[] ascii(String text) {
        return text.getBytes(StandardCharsets.US_ASCII);
    }

    @Override
    public synchronized void write(int b) throws IOException {
        if (dropping) {
            dropping = b != '\n';
            return;
        }
        if (passing) {
            out.write(b);
            passing = b != '\n' && b != '\r';
            return;
        }
        line.write(b);
        byte[] held = line.toByteArray();
        if (b != '\n' && b != '\r') {
            int state = Math.max(state(held, DROPPED), inTrace ? state(held, TRACE) : NO);
            if (state == WHOLE) {
                dropping = true;
                // A trace's line matches only after the warning: the trace goes on.
                inTrace = inTrace || java.util.Arrays.equals(held, WARNING) || java.util.Arrays.equals(held, HANDLED);
                line.reset();
                return;
            }
            if (state == BEGUN) {
                return; // may still be JOGL's: hold it
            }
        }
        inTrace = false;
        out.write(held);
        line.reset();
        passing = b != '\n' && b != '\r';
    }

    private static final int NO = 0;
    private static final int BEGUN = 1;
    private static final int WHOLE = 2;

    /** Whether the held bytes are one of the beginnings whole (WHOLE), the start of one (BEGUN), or neither (NO). */
    private static int state(byte[] held, byte[][] beginnings) {
        int state = NO;
        for (byte[] beginning : beginnings) {
            if (held.length <= beginning.length && java.util.Arrays.equals(held, 0, held.length, beginning, 0, held.length)) {
                state = Math.max(state, held.length == beginning.length ? WHOLE : BEGUN);
            }
        }
        return state;
    }

    @Override
    public synchronized void write(byte[] b, int off, int len) throws IOException {
        for (int i = off; i < off + len; i++) {
            write(b[i]);
        }
    }

    @Override
    public synchronized void flush() throws IOException {
        out.flush();
    }
}
