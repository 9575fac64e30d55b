package ifold.image;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.Random;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/** The encoder's pictures decode, pixel for pixel, with the JDK's own PNG reader. */
class PngEncoderTest {

    @Test
    void decodesToTheSamePixels() throws Exception {
        check(37, 23);
    }

    @Test
    void bigNoisyPictureSpansSeveralDataChunks() throws Exception {
        check(400, 300); // 360 kB of noise compresses to more than one 256 kB chunk
    }

    private static void check(int width, int height) throws Exception {
        byte[] rgb = new byte[3 * width * height];
        new Random(7).nextBytes(rgb);
        for (int i = 0; i < 3 * width * 5; i++) {
            rgb[i] = (byte) 200; // some flat rows too
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PngEncoder.encode(width, height, rgb, out);
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(out.toByteArray()));
        assertEquals(width, image.getWidth());
        assertEquals(height, image.getHeight());
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int i = 3 * (y * width + x);
                int expected = (rgb[i] & 0xFF) << 16 | (rgb[i + 1] & 0xFF) << 8 | (rgb[i + 2] & 0xFF);
                assertEquals(expected, image.getRGB(x, y) & 0xFFFFFF, "pixel " + x + "," + y);
            }
        }
    }
}
