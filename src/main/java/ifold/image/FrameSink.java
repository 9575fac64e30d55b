package ifold.image;

import java.io.IOException;

/**
 * Where rendered frames go, in order: a folder of PNGs, a movie, or several at once. Frames are
 * rows top first, 3 bytes (R, G, B) a pixel.
 */
public interface FrameSink extends AutoCloseable {
    /** A picture of {@code size} bytes to draw the next frame into; the sink may hand back one it is done with. */
    default byte[] buffer(int size) {
        return new byte[size];
    }

    /**
     * How many frames, spread over the whole animation, the sink would see before the first is
     * written (a GIF chooses its palette from them); 0 for none.
     */
    default int samplesWanted() {
        return 0;
    }

    /** One of the frames asked for by {@link #samplesWanted()}, before any is written. */
    default void sample(byte[] rgb) {
    }

    /** Frame {@code index}; the sink owns {@code rgb} from now on. */
    void write(int index, int width, int height, byte[] rgb) throws IOException;

    /** Every frame is written: finish the output, whole. */
    void finish() throws IOException;

    /** Releases what the sink holds; an output not finished is discarded. */
    @Override
    void close();

    /** Reports frames as they are done: the command line draws a progress bar with it. */
    interface Progress {
        void framesDone(int done, int total);
    }

    /** Every frame to each of {@code sinks}. */
    static FrameSink all(java.util.List<FrameSink> sinks) {
        if (sinks.size() == 1) {
            return sinks.get(0);
        }
        return new FrameSink() {
            @Override
            public int samplesWanted() {
                return sinks.stream().mapToInt(FrameSink::samplesWanted).max().orElse(0);
            }

            @Override
            public void sample(byte[] rgb) {
                for (FrameSink sink : sinks) {
                    sink.sample(rgb);
                }
            }

            @Override
            public void write(int index, int width, int height, byte[] rgb) throws IOException {
                for (int i = 0; i < sinks.size(); i++) {
                    // Each sink owns what it is given: all but the last get a copy.
                    sinks.get(i).write(index, width, height, i + 1 < sinks.size() ? rgb.clone() : rgb);
                }
            }

            @Override
            public void finish() throws IOException {
                for (FrameSink sink : sinks) {
                    sink.finish();
                }
            }

            @Override
            public void close() {
                for (FrameSink sink : sinks) {
                    sink.close();
                }
            }
        };
    }
}
