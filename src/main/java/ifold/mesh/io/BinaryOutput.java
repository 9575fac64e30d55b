package ifold.mesh.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/** Numbers as bytes of a given order into a 1 MiB buffer, for the binary writers (PLY, STL). */
final class BinaryOutput {
    private final OutputStream out;
    private final ByteBuffer buffer;

    BinaryOutput(OutputStream out, ByteOrder order) {
        this.out = out;
        buffer = ByteBuffer.allocate(1 << 20).order(order);
    }

    private void room(int bytes) throws IOException {
        if (buffer.remaining() < bytes) {
            flush();
        }
    }

    void writeAscii(String text) throws IOException {
        byte[] bytes = text.getBytes(StandardCharsets.US_ASCII);
        for (byte b : bytes) {
            room(1);
            buffer.put(b);
        }
    }

    void writeByte(int b) throws IOException {
        room(1);
        buffer.put((byte) b);
    }

    void writeShort(int s) throws IOException {
        room(2);
        buffer.putShort((short) s);
    }

    void writeInt(int i) throws IOException {
        room(4);
        buffer.putInt(i);
    }

    void writeFloat(float f) throws IOException {
        room(4);
        buffer.putFloat(f);
    }

    void writeDouble(double d) throws IOException {
        room(8);
        buffer.putDouble(d);
    }

    void flush() throws IOException {
        out.write(buffer.array(), 0, buffer.position());
        buffer.clear();
    }
}
