package ifold.image;

import ifold.io.AtomicFile;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Writes frames as an animated GIF that loops, in process: one palette of up to 256 colours
 * for the whole movie, chosen by median cut from frames spread over it, and each frame stored
 * as the rectangle that changed since the one before. GIF delays are whole hundredths of a
 * second; they alternate (4, 4, 5, ... at 24 frames/s) so that the movie keeps its frame rate
 * exactly over time. Written under a temporary name and renamed when whole.
 */
public final class GifWriter implements FrameSink {
    /** Above this, GIF delays (hundredths, and players round short ones up) cannot keep the rate. */
    public static final int MAX_FPS = 50;
    private static final int SAMPLES = 8;

    private final AtomicFile.Pending file;
    private final OutputStream out;
    private final int width;
    private final int height;
    private final int fps;
    private final long[] histogram = new long[1 << 15];
    private final long[][] sums = new long[3][1 << 15];
    private int[] palette;
    private final int[] nearest = new int[1 << 15];
    private byte[] previous;
    private int written;
    private boolean finished;

    public GifWriter(Path movie, int width, int height, int fps) throws IOException {
        if (fps < 1 || fps > MAX_FPS) {
            throw new IllegalArgumentException("a GIF keeps 1 to " + MAX_FPS + " frames a second, not " + fps);
        }
        this.width = width;
        this.height = height;
        this.fps = fps;
        file = AtomicFile.begin(movie);
        out = new BufferedOutputStream(Files.newOutputStream(file.path()), 1 << 16);
    }

    @Override
    public int samplesWanted() {
        return SAMPLES;
    }

    @Override
    public void sample(byte[] rgb) {
        for (int p = 0; p < rgb.length; p += 3 * 3) { // every third pixel is plenty for a palette
            int key = key(rgb, p);
            histogram[key]++;
            sums[0][key] += rgb[p] & 0xff;
            sums[1][key] += rgb[p + 1] & 0xff;
            sums[2][key] += rgb[p + 2] & 0xff;
        }
    }

    private static int key(byte[] rgb, int p) {
        return ((rgb[p] & 0xf8) << 7) | ((rgb[p + 1] & 0xf8) << 2) | ((rgb[p + 2] & 0xff) >>> 3);
    }

    @Override
    public void write(int index, int frameWidth, int frameHeight, byte[] rgb) throws IOException {
        if (palette == null) {
            if (histogram[0] == 0 && Arrays.stream(histogram).allMatch(c -> c == 0)) {
                sample(rgb); // no samples were given: the first frame has to do
            }
            palette = medianCut();
            Arrays.fill(nearest, -1);
            writeHeader();
        }
        byte[] indexed = new byte[width * height];
        for (int p = 0, b = 0; p < indexed.length; p++, b += 3) {
            int key = key(rgb, b);
            int i = nearest[key];
            if (i < 0) {
                i = closest(key);
                nearest[key] = i;
            }
            indexed[p] = (byte) i;
        }
        // Only the rectangle that changed since the last frame.
        int left = 0;
        int top = 0;
        int right = width - 1;
        int bottom = height - 1;
        if (previous != null) {
            left = width;
            top = height;
            right = -1;
            bottom = -1;
            for (int y = 0; y < height; y++) {
                int row = y * width;
                for (int x = 0; x < width; x++) {
                    if (indexed[row + x] != previous[row + x]) {
                        left = Math.min(left, x);
                        right = Math.max(right, x);
                        top = Math.min(top, y);
                        bottom = Math.max(bottom, y);
                    }
                }
            }
            if (right < 0) { // nothing changed: one pixel, to keep the frame's time
                left = 0;
                top = 0;
                right = 0;
                bottom = 0;
            }
        }
        int w = right - left + 1;
        int h = bottom - top + 1;
        byte[] region = new byte[w * h];
        for (int y = 0; y < h; y++) {
            System.arraycopy(indexed, (top + y) * width + left, region, y * w, w);
        }
        // Graphic control: leave the frame in place, its delay in hundredths.
        int delay = (int) (Math.round(100.0 * (written + 1) / fps) - Math.round(100.0 * written / fps));
        out.write(new byte[] {0x21, (byte) 0xF9, 4, 0x04});
        short16(delay);
        out.write(new byte[] {0, 0});
        out.write(0x2C);
        short16(left);
        short16(top);
        short16(w);
        short16(h);
        out.write(0); // no local colour table
        out.write(8); // LZW minimum code size
        new Lzw(out).encode(region);
        previous = indexed;
        written++;
    }

    private void writeHeader() throws IOException {
        out.write("GIF89a".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        short16(width);
        short16(height);
        out.write(0xF7); // a global colour table of 256 entries, 8 bits a channel
        out.write(0);
        out.write(0);
        for (int i = 0; i < 256; i++) {
            int colour = i < palette.length ? palette[i] : 0;
            out.write((colour >>> 16) & 0xff);
            out.write((colour >>> 8) & 0xff);
            out.write(colour & 0xff);
        }
        // Loop for ever (the NETSCAPE2.0 extension).
        out.write(new byte[] {0x21, (byte) 0xFF, 11});
        out.write("NETSCAPE2.0".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        out.write(new byte[] {3, 1, 0, 0, 0});
    }

    private void short16(int value) throws IOException {
        out.write(value & 0xff);
        out.write((value >>> 8) & 0xff);
    }

    /** Up to 256 colours for the sampled bins: each box of bins split at its median along its longest side. */
    private int[] medianCut() {
        List<int[]> boxes = new ArrayList<>();
        int[] bins = java.util.stream.IntStream.range(0, histogram.length).filter(k -> histogram[k] > 0).toArray();
        boxes.add(bins);
        while (boxes.size() < 256) {
            int best = -1;
            long bestScore = 0;
            int bestAxis = 0;
            for (int b = 0; b < boxes.size(); b++) {
                int[] box = boxes.get(b);
                if (box.length < 2) {
                    continue;
                }
                int[] range = new int[3];
                for (int axis = 0; axis < 3; axis++) {
                    int lo = 31;
                    int hi = 0;
                    for (int k : box) {
                        int v = channel(k, axis);
                        lo = Math.min(lo, v);
                        hi = Math.max(hi, v);
                    }
                    range[axis] = hi - lo;
                }
                int axis = range[0] >= range[1] && range[0] >= range[2] ? 0 : range[1] >= range[2] ? 1 : 2;
                long count = 0;
                for (int k : box) {
                    count += histogram[k];
                }
                long score = count * (range[axis] + 1);
                if (score > bestScore) {
                    bestScore = score;
                    best = b;
                    bestAxis = axis;
                }
            }
            if (best < 0) {
                break; // every box is a single bin
            }
            int[] box = boxes.remove(best);
            int axis = bestAxis;
            Integer[] sorted = Arrays.stream(box).boxed().toArray(Integer[]::new);
            Arrays.sort(sorted, (a, b) -> Integer.compare(channel(a, axis), channel(b, axis)));
            long total = 0;
            for (int k : box) {
                total += histogram[k];
            }
            long half = 0;
            int cut = 0;
            while (cut < sorted.length - 1 && half + histogram[sorted[cut]] <= total / 2) {
                half += histogram[sorted[cut++]];
            }
            cut = Math.max(1, cut);
            boxes.add(Arrays.stream(sorted, 0, cut).mapToInt(Integer::intValue).toArray());
            boxes.add(Arrays.stream(sorted, cut, sorted.length).mapToInt(Integer::intValue).toArray());
        }
        int[] colours = new int[boxes.size()];
        for (int b = 0; b < boxes.size(); b++) {
            long n = 0;
            long[] c = new long[3];
            for (int k : boxes.get(b)) {
                n += histogram[k];
                for (int axis = 0; axis < 3; axis++) {
                    c[axis] += sums[axis][k];
                }
            }
            n = Math.max(1, n);
            colours[b] = (int) (c[0] / n) << 16 | (int) (c[1] / n) << 8 | (int) (c[2] / n);
        }
        return colours.length == 0 ? new int[] {0} : colours;
    }

    private static int channel(int key, int axis) {
        return (key >>> (10 - 5 * axis)) & 31;
    }

    private int closest(int key) {
        int r = (channel(key, 0) << 3) | 4;
        int g = (channel(key, 1) << 3) | 4;
        int b = (channel(key, 2) << 3) | 4;
        int best = 0;
        int bestDistance = Integer.MAX_VALUE;
        for (int i = 0; i < palette.length; i++) {
            int dr = ((palette[i] >>> 16) & 0xff) - r;
            int dg = ((palette[i] >>> 8) & 0xff) - g;
            int db = (palette[i] & 0xff) - b;
            int d = 3 * dr * dr + 4 * dg * dg + 2 * db * db;
            if (d < bestDistance) {
                bestDistance = d;
                best = i;
            }
        }
        return best;
    }

    @Override
    public void finish() throws IOException {
        if (palette == null) {
            throw new IOException("no frames to write");
        }
        out.write(0x3B);
        out.close();
        file.commit();
        finished = true;
    }

    @Override
    public void close() {
        if (!finished) {
            try {
                out.close();
            } catch (IOException e) {
                // Discarded anyway.
            }
        }
        file.close();
    }

    /** GIF's variable-length LZW, codes packed from the low bit, in sub-blocks of at most 255 bytes. */
    private static final class Lzw {
        private static final int CLEAR = 256;
        private static final int END = 257;
        private static final int MAX_CODES = 4096;
        private static final int TABLE = 1 << 13;
        private final OutputStream out;
        private final int[] keys = new int[TABLE];
        private final int[] codes = new int[TABLE];
        private final byte[] block = new byte[255];
        private int blockSize;
        private int bits;
        private int bitCount;
        private int codeSize;
        private int maxCode;
        private int next;
        private boolean cleared;

        Lzw(OutputStream out) {
            this.out = out;
        }

        void encode(byte[] pixels) throws IOException {
            reset();
            codeSize = 9;
            maxCode = (1 << codeSize) - 1;
            output(CLEAR);
            int prefix = pixels[0] & 0xff;
            for (int i = 1; i < pixels.length; i++) {
                int c = pixels[i] & 0xff;
                int key = (c << 12) | prefix;
                int slot = find(key);
                if (keys[slot] == key) {
                    prefix = codes[slot];
                    continue;
                }
                output(prefix);
                prefix = c;
                if (next < MAX_CODES) {
                    keys[slot] = key;
                    codes[slot] = next++;
                } else {
                    reset();
                    cleared = true;
                    output(CLEAR);
                }
            }
            output(prefix);
            output(END);
            if (bitCount > 0) {
                put(bits & 0xff);
            }
            if (blockSize > 0) {
                flushBlock();
            }
            out.write(0); // the end of the image's data
        }

        private void reset() {
            Arrays.fill(keys, -1);
            next = END + 1;
        }

        private int find(int key) {
            int slot = (key * 0x9E3779B1) >>> (32 - 13);
            while (keys[slot] != -1 && keys[slot] != key) {
                slot = (slot + 1) & (TABLE - 1);
            }
            return slot;
        }

        private void output(int code) throws IOException {
            bits |= code << bitCount;
            bitCount += codeSize;
            while (bitCount >= 8) {
                put(bits & 0xff);
                bits >>>= 8;
                bitCount -= 8;
            }
            // Widen the codes once the next one to be made no longer fits (as the decoder does).
            if (next > maxCode || cleared) {
                if (cleared) {
                    codeSize = 9;
                    cleared = false;
                } else {
                    codeSize++;
                }
                maxCode = codeSize == 12 ? MAX_CODES : (1 << codeSize) - 1;
            }
        }

        private void put(int b) throws IOException {
            block[blockSize++] = (byte) b;
            if (blockSize == 255) {
                flushBlock();
            }
        }

        private void flushBlock() throws IOException {
            out.write(blockSize);
            out.write(block, 0, blockSize);
            blockSize = 0;
        }
    }
}
