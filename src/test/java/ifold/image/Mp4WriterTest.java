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
}
