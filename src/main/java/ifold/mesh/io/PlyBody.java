package ifold.mesh.io;

import static ifold.mesh.io.ByteTokenizer.EOF;

import ifold.mesh.io.PlyReader.Element;
import ifold.mesh.io.PlyReader.Format;
import ifold.mesh.io.PlyReader.Header;
import ifold.mesh.io.PlyReader.Property;
import ifold.mesh.io.PlyReader.Type;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * A PLY file's body, read value by value, binary (either byte order) or ASCII: it says where it
 * is for messages ({@link PlyReader} reads the header and builds the soup).
 */
abstract class PlyBody implements AutoCloseable {
    final Path file;

    PlyBody(Path file) {
        this.file = file;
    }

    abstract double number(Type type) throws MeshFormatException, IOException;

    abstract long integer(Type type) throws MeshFormatException, IOException;

    /** The most items of a type that the rest of the file could hold. */
    abstract long mostItems(Type type) throws IOException;

    /** Reads past one property of element number k (from 0). */
    void skip(Property p, Element element, long k) throws MeshFormatException, IOException {
        if (p.countType() == null) {
            number(p.type());
            return;
        }
        long count = integer(p.countType());
        if (count < 0 || count > mostItems(p.type())) {
            throw error(String.format(Locale.ROOT, "%s %d: a list '%s' of %d items, %s", element.name(), k + 1, p.name(), count,
                    count < 0 ? "fewer than none" : "more than the rest of the file holds"));
        }
        for (long i = 0; i < count; i++) {
            number(p.type());
        }
    }

    /** The byte about to be read (binary); the line of the last token (ASCII). */
    abstract long where() throws IOException, MeshFormatException;

    /** The line of the last value read (ASCII), or 0 (binary, which has no lines). */
    abstract int lineOfLast();

    abstract MeshFormatException error(String problem);

    /** Refuses anything after the last element. */
    abstract void end() throws MeshFormatException, IOException;

    @Override
    public abstract void close() throws IOException;

    static final class Binary extends PlyBody {
        private static final int CHUNK = 1 << 16;
        private final InputStream in;
        private final ByteBuffer buffer;
        private final long size;
        /** The file offset of buffer[0]. */
        private long offset;
        /** Where the value being read began, for messages. */
        private long valueAt;

        Binary(Path file, Header header, long size) throws IOException {
            super(file);
            this.size = size;
            in = Files.newInputStream(file);
            in.skipNBytes(header.bodyOffset());
            offset = header.bodyOffset();
            buffer = ByteBuffer.allocate(CHUNK)
                    .order(header.format() == Format.BINARY_BIG_ENDIAN ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN);
            buffer.limit(0);
        }

        private void need(int bytes) throws MeshFormatException, IOException {
            valueAt = offset + buffer.position();
            if (buffer.remaining() >= bytes) {
                return;
            }
            offset += buffer.position();
            buffer.compact();
            int read = in.readNBytes(buffer.array(), buffer.position(), buffer.capacity() - buffer.position());
            buffer.limit(buffer.position() + read);
            buffer.position(0);
            if (buffer.remaining() < bytes) {
                throw new MeshFormatException(file, 0, buffer.remaining() == 0
                        ? String.format(Locale.ROOT, "the file ends at byte %d, where a value of %d byte%s goes: it is cut short", valueAt, bytes,
                                bytes == 1 ? "" : "s")
                        : String.format(Locale.ROOT, "the file ends at byte %d, inside a value begun at byte %d: it is cut short",
                                offset + buffer.remaining(), valueAt));
            }
        }

        @Override
        double number(Type type) throws MeshFormatException, IOException {
            need(type.bytes);
            return switch (type) {
                case FLOAT32 -> buffer.getFloat();
                case FLOAT64 -> buffer.getDouble();
                default -> read(type);
            };
        }

        @Override
        long integer(Type type) throws MeshFormatException, IOException {
            need(type.bytes);
            return read(type);
        }

        private long read(Type type) {
            return switch (type) {
                case INT8 -> buffer.get();
                case UINT8 -> buffer.get() & 0xFF;
                case INT16 -> buffer.getShort();
                case UINT16 -> buffer.getShort() & 0xFFFF;
                case INT32 -> buffer.getInt();
                case UINT32 -> buffer.getInt() & 0xFFFFFFFFL;
                // A float where an integer goes: its whole part, as other readers take it.
                case FLOAT32 -> (long) buffer.getFloat();
                case FLOAT64 -> (long) buffer.getDouble();
            };
        }

        @Override
        long mostItems(Type type) {
            return (size - offset - buffer.position()) / type.bytes;
        }

        @Override
        long where() {
            return offset + buffer.position();
        }

        @Override
        int lineOfLast() {
            return 0;
        }

        @Override
        MeshFormatException error(String problem) {
            return new MeshFormatException(file, 0, problem + " (at byte " + valueAt + ")");
        }

        @Override
        void end() throws MeshFormatException, IOException {
            long at = offset + buffer.position();
            if (at < size) {
                throw new MeshFormatException(file, 0, String.format(Locale.ROOT, "%d byte%s after the last element, from byte %d:"
                        + " the header's counts do not match the body", size - at, size - at == 1 ? "" : "s", at));
            }
        }

        @Override
        public void close() throws IOException {
            in.close();
        }
    }

    static final class Ascii extends PlyBody {
        private final ByteTokenizer tokens;

        Ascii(Path file, Header header) throws IOException {
            super(file);
            InputStream in = Files.newInputStream(file);
            in.skipNBytes(header.bodyOffset());
            tokens = ByteTokenizer.region(file, in, header.bodyOffset(), header.bodyLine(), false);
        }

        private void next(String what) throws MeshFormatException, IOException {
            if (tokens.advanceAcrossLines() == EOF) {
                throw tokens.error(tokens.lastTokenLine(), "the file ends where " + what + " goes: the header's counts are more than the body holds");
            }
        }

        @Override
        double number(Type type) throws MeshFormatException, IOException {
            next("a number");
            return type.integer ? checkedInteger() : tokens.finiteDouble("number");
        }

        @Override
        long integer(Type type) throws MeshFormatException, IOException {
            next("an integer");
            return checkedInteger();
        }

        private long checkedInteger() throws MeshFormatException {
            long value = tokens.tokenLong();
            if (value == DecimalParser.NOT_AN_INTEGER || value == DecimalParser.TOO_LARGE) {
                throw tokens.error(tokens.tokenLine(), "expected an integer, found '" + tokens.tokenText() + "'");
            }
            return value;
        }

        @Override
        long mostItems(Type type) {
            return Long.MAX_VALUE; // each item is a token read as it comes: the file's end stops a list too long
        }

        @Override
        long where() {
            return tokens.lastTokenLine();
        }

        @Override
        int lineOfLast() {
            return tokens.tokenLine();
        }

        @Override
        MeshFormatException error(String problem) {
            return tokens.error(tokens.tokenLine(), problem);
        }

        @Override
        void end() throws MeshFormatException, IOException {
            if (tokens.advanceAcrossLines() != EOF) {
                throw tokens.error(tokens.tokenLine(), "'" + tokens.tokenText() + "' after the last element: the header's counts do"
                        + " not match the body");
            }
        }

        @Override
        public void close() throws IOException {
            tokens.close();
        }
    }
}
