package ifold.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Node;

/** The GIF writer, read back by the JDK's own GIF reader: frames, delays, the loop, the pixels. */
class GifWriterTest {
    @TempDir
    Path dir;

    private static final int W = 40;
    private static final int H = 30;

    /** A frame of a few flat colours, a square moving across it, and some noise in a corner. */
    private static byte[] frame(int k, Random random) {
        byte[] rgb = new byte[3 * W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int colour = x >= 2 * k && x < 2 * k + 8 && y >= 10 && y < 18 ? 0xF4F1EA : y < 5 ? 0x7D8A99 : 0xD3DAE2;
                if (x < 4 && y < 4) {
                    colour = random.nextInt(1 << 24); // many colours: the palette must choose
                }
                int p = 3 * (y * W + x);
                rgb[p] = (byte) (colour >>> 16);
                rgb[p + 1] = (byte) (colour >>> 8);
                rgb[p + 2] = (byte) colour;
            }
        }
        return rgb;
    }

    @Test
    void framesDelaysLoopAndColoursReadBack() throws Exception {
        Path gif = dir.resolve("m.gif");
        Random random = new Random(3);
        int frames = 12;
        try (GifWriter writer = new GifWriter(gif, W, H, 24)) {
            for (int k = 0; k < writer.samplesWanted(); k++) {
                writer.sample(frame(k * frames / writer.samplesWanted(), random));
            }
            for (int k = 0; k < frames; k++) {
                writer.write(k, W, H, frame(k, random));
            }
            writer.finish();
        }
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            assertEquals(frames, reader.getNumImages(true));
            int hundredths = 0;
            for (int k = 0; k < frames; k++) {
                IIOMetadataNode root = (IIOMetadataNode) reader.getImageMetadata(k).getAsTree("javax_imageio_gif_image_1.0");
                IIOMetadataNode control = (IIOMetadataNode) root.getElementsByTagName("GraphicControlExtension").item(0);
                hundredths += Integer.parseInt(control.getAttribute("delayTime"));
            }
            // 12 frames at 24 a second: half a second, kept exactly by alternating 4 and 5.
            assertEquals(50, hundredths);
            IIOMetadataNode stream = (IIOMetadataNode) reader.getStreamMetadata().getAsTree("javax_imageio_gif_stream_1.0");
            assertEquals(256, Integer.parseInt(((IIOMetadataNode) stream.getElementsByTagName("GlobalColorTable").item(0))
                    .getAttribute("sizeOfGlobalColorTable")));
            IIOMetadataNode first = (IIOMetadataNode) reader.getImageMetadata(0).getAsTree("javax_imageio_gif_image_1.0");
            Node applications = first.getElementsByTagName("ApplicationExtensions").item(0);
            assertTrue(applications != null && ((IIOMetadataNode) applications.getFirstChild()).getAttribute("applicationID")
                    .equals("NETSCAPE"), "it loops");
            // The flat colours come back exactly; the noise nearly.
            BufferedImage image = reader.read(0);
            assertEquals(0xD3DAE2, image.getRGB(20, 25) & 0xFFFFFF);
            assertEquals(0x7D8A99, image.getRGB(20, 2) & 0xFFFFFF);
            assertEquals(0xF4F1EA, image.getRGB(3, 12) & 0xFFFFFF);
            // A later frame holds only the rectangle that changed: the square's move.
            IIOMetadataNode later = (IIOMetadataNode) reader.getImageMetadata(5).getAsTree("javax_imageio_gif_image_1.0");
            IIOMetadataNode descriptor = (IIOMetadataNode) later.getElementsByTagName("ImageDescriptor").item(0);
            int width = Integer.parseInt(descriptor.getAttribute("imageWidth"));
            assertTrue(width < W, "a part of the frame: " + width);
        }
        assertFalse(Files.list(dir).anyMatch(p -> p.getFileName().toString().endsWith(".tmp")), "no temporary file left");
    }

    @Test
    void anUnfinishedGifLeavesNothing() throws Exception {
        Path gif = dir.resolve("half.gif");
        try (GifWriter writer = new GifWriter(gif, W, H, 10)) {
            writer.write(0, W, H, frame(0, new Random(1)));
        }
        assertFalse(Files.exists(gif));
        try (var files = Files.list(dir)) {
            assertEquals(0, files.count(), "nor a temporary file");
        }
        assertThrows(IllegalArgumentException.class, () -> new GifWriter(dir.resolve("fast.gif"), W, H, 60));
    }
}
