package ifold.cli;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

/**
 * Standard error without JOGL's own bookkeeping: stopped by Ctrl-C or SIGTERM while it renders,
 * JOGL's shutdown prints the X display connections it still holds ("X11Util.Display: Shutdown
 * ...", "X11Util: Open ..."), which say nothing to a user, under iFold's one line. Lines that
 * begin with {@code X11Util} go; everything else passes as written, a line at a time (a
 * progress bar's carriage returns and flushes pass at once).
 */
final class JoglNoise extends OutputStream {
    private static final byte[] PREFIX = "X11Util".getBytes(StandardCharsets.US_ASCII);

    private final OutputStream out;
    /** The line begun and not yet passed on: held only while it may still begin with the prefix. */
    private final ByteArrayOutputStream line = new ByteArrayOutputStream();
    /** Whether the line begun is passed on as it comes (it cannot begin with the prefix), or dropped. */
    private boolean passing;
    private boolean dropping;

    JoglNoise(OutputStream out) {
        this.out = out;
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
        int n = held.length;
        if (n <= PREFIX.length && held[n - 1] == PREFIX[n - 1] && b != '\n') {
            if (n == PREFIX.length) {
                dropping = true;
                line.reset();
            }
            return; // may still be JOGL's: hold it
        }
        out.write(held);
        line.reset();
        passing = b != '\n' && b != '\r';
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
