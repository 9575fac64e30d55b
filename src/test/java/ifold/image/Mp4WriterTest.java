package ifold.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The MP4 writer, checked with ffprobe: codec, pixel format, frames, duration = frames / fps. */
class Mp4WriterTest {
    @TempDir
    Path dir;

    @Test
    void theMovieDecodesWithItsFramesAndRate() throws Exception {
        assumeTrue(Mp4Writer.available(), "no ffmpeg here (scripts/setup installs it)");
        Path movie = dir.resolve("m.mp4");
        int frames = 36;
        try (Mp4Writer writer = new Mp4Writer(movie, 64, 48, 12)) {
            for (int k = 0; k < frames; k++) {
                byte[] rgb = new byte[3 * 64 * 48];
                for (int p = 0; p < rgb.length; p += 3) {
                    rgb[p] = (byte) (4 * k);
                    rgb[p + 1] = (byte) (p % 251);
                }
                writer.write(k, 64, 48, rgb);
            }
            writer.finish();
        }
        Process probe = new ProcessBuilder("ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                "stream=codec_name,pix_fmt,nb_read_frames,r_frame_rate:format=duration", "-of", "default=nw=1", movie.toString())
                .redirectErrorStream(true).start();
        String said = new String(probe.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        probe.waitFor(60, TimeUnit.SECONDS);
        assertEquals(true, said.contains("codec_name=h264"), said);
        assertEquals(true, said.contains("pix_fmt=yuv420p"), said);
        assertEquals(true, said.contains("nb_read_frames=" + frames), said);
        assertEquals(true, said.contains("r_frame_rate=12/1"), said);
        assertEquals(true, said.contains("duration=3.0"), said);
        try (var files = Files.list(dir)) {
            assertEquals(1, files.count(), "the movie and nothing else");
        }
    }

    @Test
    void anUnfinishedMovieLeavesNothing() throws Exception {
        assumeTrue(Mp4Writer.available(), "no ffmpeg here (scripts/setup installs it)");
        Path movie = dir.resolve("half.mp4");
        try (Mp4Writer writer = new Mp4Writer(movie, 64, 48, 12)) {
            writer.write(0, 64, 48, new byte[3 * 64 * 48]);
        }
        assertFalse(Files.exists(movie));
        try (var files = Files.list(dir)) {
            assertEquals(0, files.count(), "nor a temporary file");
        }
        assertThrows(IllegalArgumentException.class, () -> new Mp4Writer(dir.resolve("odd.mp4"), 63, 48, 12));
    }

    /** Top-level MP4 boxes, each given as type then size (the size written, 0 for none), filled with zeros to their size. */
    private Path boxes(String name, Object... typeAndSize) throws Exception {
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        for (int i = 0; i < typeAndSize.length; i += 2) {
            int size = (Integer) typeAndSize[i + 1];
            java.nio.ByteBuffer box = java.nio.ByteBuffer.allocate(Math.max(size, 8));
            box.putInt(size).put(((String) typeAndSize[i]).getBytes(StandardCharsets.ISO_8859_1));
            bytes.write(box.array());
        }
        Path file = dir.resolve(name);
        Files.write(file, bytes.toByteArray());
        return file;
    }

    @Test
    void aMovieIsWholeOnlyWithItsFramesAndIndexAndEveryBoxToItsEnd() throws Exception {
        assertEquals(null, Mp4Writer.incomplete(boxes("whole.mp4", "ftyp", 32, "moov", 100, "mdat", 400)));
        // What ffmpeg 5.1 left on a full disk, exiting 0: the frames' box never closed, no index.
        assertEquals("its 'mdat' box was never closed", Mp4Writer.incomplete(boxes("open.mp4", "ftyp", 32, "free", 8, "mdat", 0)));
        assertEquals("no index (moov box)", Mp4Writer.incomplete(boxes("noindex.mp4", "ftyp", 32, "mdat", 400)));
        Path cut = boxes("cut.mp4", "ftyp", 32, "mdat", 400, "moov", 100);
        Files.write(cut, java.util.Arrays.copyOf(Files.readAllBytes(cut), 480));
        assertEquals("its 'moov' box is cut short: 48 of its 100 bytes written", Mp4Writer.incomplete(cut));
        assertEquals("no frames (mdat box)", Mp4Writer.incomplete(boxes("empty.mp4")));
    }
}
