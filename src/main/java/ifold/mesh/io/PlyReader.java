package ifold.mesh.io;

import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Reads PLY (Turk's polygon file format, as the Stanford scans and most scanners write it):
 * ASCII, binary little-endian and binary big-endian. The {@code vertex} element gives x, y and
 * z, of any numeric type; the {@code face} element a list named {@code vertex_indices} (or
 * {@code vertex_index}) of any count and index type, and where it has them {@code red},
 * {@code green} and {@code blue} (and {@code alpha}) as face colours, as the OFF reader keeps
 * them. Every other element and property is read past. The soup goes to {@code MeshBuilder} as
 * every reader's does.
 *
 * <p>Hostile files end in one message naming the line (ASCII) or the byte (binary), in time and
 * memory bounded by the file's size: the header must end within its first {@link #MOST_HEADER}
 * bytes, and counts are checked against the bytes left before anything is kept.
 */
public final class PlyReader {
    /** The longest header read: real ones are a few hundred bytes. */
    static final int MOST_HEADER = 1 << 16;

    private PlyReader() {
    }

    /** How the body is written. */
    public enum Format {
        ASCII("ascii"), BINARY_LITTLE_ENDIAN("binary_little_endian"), BINARY_BIG_ENDIAN("binary_big_endian");

        final String word;

        Format(String word) {
            this.word = word;
        }

        /** The header's word for it: {@code ascii}, {@code binary_little_endian}, {@code binary_big_endian}. */
        public String word() {
            return word;
        }
    }

    /** A property's numeric type, by its byte size and whether it is an integer. */
    enum Type {
        INT8(1, true), UINT8(1, true), INT16(2, true), UINT16(2, true), INT32(4, true), UINT32(4, true), FLOAT32(4, false),
        FLOAT64(8, false);

        final int bytes;
        final boolean integer;

        Type(int bytes, boolean integer) {
            this.bytes = bytes;
            this.integer = integer;
        }

        /** The type a header names, in the old spelling (char, uchar, …, double) or the sized one (int8, …, float64); null for none. */
        static Type named(String name) {
            return switch (name) {
                case "char", "int8" -> INT8;
                case "uchar", "uint8" -> UINT8;
                case "short", "int16" -> INT16;
                case "ushort", "uint16" -> UINT16;
                case "int", "int32" -> INT32;
                case "uint", "uint32" -> UINT32;
                case "float", "float32" -> FLOAT32;
                case "double", "float64" -> FLOAT64;
                default -> null;
            };
        }
    }

    /** A property: a scalar, or a list whose count has {@code countType} (null for a scalar). */
    record Property(String name, Type type, Type countType, int line) {
    }

    record Element(String name, long count, List<Property> properties, int line) {
        /** The fewest bytes one element takes in a binary body: its scalars, and its lists' counts. */
        long leastBinaryBytes() {
            long bytes = 0;
            for (Property p : properties) {
                bytes += p.countType != null ? p.countType.bytes : p.type.bytes;
            }
            return bytes;
        }
    }

    /** What was read: the soup, the body's format, and the counts of the two elements kept. */
    public record Result(PolygonSoup soup, Format format, int vertices, int faces) {
    }

    public static PolygonSoup read(Path file) throws MeshFormatException, IOException {
        return readWithCounts(file).soup();
    }

    public static Result readWithCounts(Path file) throws MeshFormatException, IOException {
        long size = Files.size(file);
        byte[] start;
        try (InputStream in = Files.newInputStream(file)) {
            start = in.readNBytes((int) Math.min(size, MOST_HEADER));
        }
        Header header = Header.parse(file, start, size);
        Element vertex = header.element("vertex");
        Element face = header.element("face");
        if (vertex == null) {
            throw new MeshFormatException(file, 0, "no 'vertex' element in the header");
        }
        if (face == null) {
            throw new MeshFormatException(file, 0, "no 'face' element in the header: a cloud of points, not a surface");
        }
        PlyBody body = header.format == Format.ASCII ? new PlyBody.Ascii(file, header) : new PlyBody.Binary(file, header, size);
        try (body) {
            PolygonSoup soup = new PolygonSoup();
            Layout vertices = new Layout(vertex, "x", "y", "z");
            Layout faces = new Layout(face, "vertex_indices", "red", "green", "blue", "alpha");
            if (faces.at[0] < 0) {
                faces = new Layout(face, "vertex_index", "red", "green", "blue", "alpha");
            }
            checkVertexLayout(file, vertex, vertices);
            checkFaceLayout(file, face, faces);
            boolean vertexBeforeFace = header.elements.indexOf(vertex) < header.elements.indexOf(face);
            List<long[]> deferred = new ArrayList<>(); // faces read before the vertices: their index and where they were
            for (Element element : header.elements) {
                if (element == vertex) {
                    readVertices(body, vertex, vertices, soup);
                } else if (element == face) {
                    readFaces(body, face, faces, soup, vertexBeforeFace ? (int) vertex.count : -1, deferred);
                } else {
                    for (long k = 0; k < element.count; k++) {
                        for (Property p : element.properties) {
                            body.skip(p, element, k);
                        }
                    }
                }
            }
            body.end();
            for (long[] late : deferred) {
                int f = (int) late[0];
                for (int k = 0; k < soup.faceSize(f); k++) {
                    int v = soup.faceVertex(f, k);
                    if (v >= soup.vertexCount()) {
                        throw new MeshFormatException(file, header.format == Format.ASCII ? (int) late[1] : 0, String.format(Locale.ROOT,
                                "face %d%s: vertex index %d is not among the %d vertices", f + 1,
                                header.format == Format.ASCII ? "" : " (at byte " + late[1] + ")", v, soup.vertexCount()));
                    }
                }
            }
            return new Result(soup, header.format, (int) vertex.count, (int) face.count);
        }
    }

    private static void checkVertexLayout(Path file, Element vertex, Layout layout) throws MeshFormatException {
        for (int k = 0; k < 3; k++) {
            if (layout.at[k] < 0) {
                throw new MeshFormatException(file, vertex.line, "the 'vertex' element has no property '" + "xyz".charAt(k) + "'");
            }
            Property p = vertex.properties.get(layout.at[k]);
            if (p.countType != null) {
                throw new MeshFormatException(file, p.line, "vertex property '" + p.name + "' is a list, expected a number");
            }
        }
    }

    private static void checkFaceLayout(Path file, Element face, Layout layout) throws MeshFormatException {
        if (layout.at[0] < 0) {
            throw new MeshFormatException(file, face.line, "the 'face' element has no list 'vertex_indices' (or 'vertex_index')");
        }
        Property indices = face.properties.get(layout.at[0]);
        if (indices.countType == null || !indices.countType.integer || !indices.type.integer) {
            throw new MeshFormatException(file, indices.line, "'" + indices.name + "' must be a list of integers with an integer count");
        }
        for (int k = 1; k < 5; k++) {
            if (layout.at[k] >= 0 && face.properties.get(layout.at[k]).countType != null) {
                Property p = face.properties.get(layout.at[k]);
                throw new MeshFormatException(file, p.line, "face property '" + p.name + "' is a list, expected a number");
            }
        }
    }

    private static void readVertices(PlyBody body, Element element, Layout layout, PolygonSoup soup) throws MeshFormatException, IOException {
        List<Property> properties = element.properties;
        double[] xyz = new double[3];
        for (long k = 0; k < element.count; k++) {
            for (int i = 0; i < properties.size(); i++) {
                Property p = properties.get(i);
                int role = layout.roleOf[i];
                if (role < 0) {
                    body.skip(p, element, k);
                } else {
                    double value = body.number(p.type);
                    if (!Double.isFinite(value)) {
                        throw body.error(String.format(Locale.ROOT, "vertex %d: %s is not a finite number (%s)", k + 1, p.name, value));
                    }
                    xyz[role] = value;
                }
            }
            soup.addVertex(xyz[0], xyz[1], xyz[2]);
        }
    }

    private static void readFaces(PlyBody body, Element element, Layout layout, PolygonSoup soup, int vertices, List<long[]> deferred)
            throws MeshFormatException, IOException {
        List<Property> properties = element.properties;
        int[] corners = new int[16];
        int[] rgba = new int[4];
        boolean colors = layout.at[1] >= 0 && layout.at[2] >= 0 && layout.at[3] >= 0;
        for (long k = 0; k < element.count; k++) {
            long where = body.where();
            int size = 0;
            rgba[3] = 255;
            for (int i = 0; i < properties.size(); i++) {
                Property p = properties.get(i);
                int role = layout.roleOf[i];
                if (role == 0) {
                    long count = body.integer(p.countType);
                    if (count < 0 || count > body.mostItems(p.type)) {
                        throw body.error(String.format(Locale.ROOT, "face %d: a list of %d vertices, %s", k + 1, count,
                                count < 0 ? "fewer than none" : "more than the rest of the file holds"));
                    }
                    size = (int) count;
                    for (int c = 0; c < size; c++) {
                        long index = body.integer(p.type);
                        if (c == corners.length) {
                            // Grown as the indices come, not to the count: an ASCII count of 2^31 ends at the file's end.
                            corners = java.util.Arrays.copyOf(corners, 2 * c);
                        }
                        if (index < 0 || index > Integer.MAX_VALUE || (vertices >= 0 && index >= vertices)) {
                            throw body.error(String.format(Locale.ROOT, "face %d: vertex index %d is not among the %d vertices", k + 1,
                                    index, vertices >= 0 ? vertices : soup.vertexCount()));
                        }
                        corners[c] = (int) index;
                    }
                } else if (role > 0 && colors) {
                    double value = body.number(p.type);
                    // Colours as bytes, or as floats of 0 to 1 as some writers give them.
                    int channel = p.type.integer ? (int) value : (int) Math.round(value * 255);
                    if (!(channel >= 0 && channel <= 255)) {
                        throw body.error(String.format(Locale.ROOT, "face %d: %s %s is not a colour of 0 to 255", k + 1, p.name, value));
                    }
                    rgba[role - 1] = channel;
                } else {
                    body.skip(p, element, k);
                }
            }
            int line = body.lineOfLast();
            int f = soup.addFace(corners, size, line);
            if (colors) {
                soup.setFaceColor(f, rgba[3] << 24 | rgba[0] << 16 | rgba[1] << 8 | rgba[2]);
            }
            if (vertices < 0) {
                deferred.add(new long[] {f, line > 0 ? line : where});
            }
        }
    }

    /** Where each wanted property lies among an element's, and the role of each of its properties (-1: none). */
    private static final class Layout {
        final int[] at;
        final int[] roleOf;

        Layout(Element element, String... wanted) {
            at = new int[wanted.length];
            roleOf = new int[element.properties.size()];
            java.util.Arrays.fill(at, -1);
            java.util.Arrays.fill(roleOf, -1);
            for (int i = 0; i < element.properties.size(); i++) {
                for (int w = 0; w < wanted.length; w++) {
                    if (at[w] < 0 && element.properties.get(i).name.equals(wanted[w])) {
                        at[w] = i;
                        roleOf[i] = w;
                    }
                }
            }
        }
    }

    /** The header: format, elements with their properties, and where the body begins. */
    record Header(Format format, List<Element> elements, long bodyOffset, int bodyLine) {
        Element element(String name) {
            for (Element e : elements) {
                if (e.name.equals(name)) {
                    return e;
                }
            }
            return null;
        }

        static Header parse(Path file, byte[] start, long size) throws MeshFormatException {
            Format format = null;
            List<Element> elements = new ArrayList<>();
            int pos = 0;
            int line = 0;
            while (true) {
                int end = pos;
                while (end < start.length && start[end] != '\n') {
                    end++;
                }
                if (end == start.length) {
                    throw new MeshFormatException(file, line == 0 || start.length == MOST_HEADER ? 0 : line + 1, start.length == MOST_HEADER
                            ? "no 'end_header' in the first " + MOST_HEADER + " bytes"
                            : line == 0 && start.length == 0 ? "empty file" : "the file ends before 'end_header'");
                }
                line++;
                int textEnd = end > pos && start[end - 1] == '\r' ? end - 1 : end;
                String text = new String(start, pos, textEnd - pos, StandardCharsets.ISO_8859_1);
                for (int i = 0; i < text.length(); i++) {
                    char c = text.charAt(i);
                    if (c < 0x20 && c != '\t' || c >= 0x7F) {
                        throw new MeshFormatException(file, line, line == 1 ? "not a PLY file: it does not begin with the line 'ply'"
                                : "a header line holds a byte that is not text (" + (int) c + ")");
                    }
                }
                pos = end + 1;
                String[] words = text.trim().split("[ \\t]+");
                if (line == 1) {
                    if (!text.trim().equals("ply")) {
                        throw new MeshFormatException(file, 1, "not a PLY file: it does not begin with the line 'ply'");
                    }
                    continue;
                }
                switch (words[0]) {
                    case "format" -> {
                        if (words.length != 3) {
                            throw new MeshFormatException(file, line, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
                        }
                        for (Format f : Format.values()) {
                            format = f.word.equals(words[1]) ? f : format;
                        }
                        if (format == null || !words[2].equals("1.0")) {
                            throw new MeshFormatException(file, line, "unknown format '" + words[1] + " " + words[2]
                                    + "': PLY 1.0 is ascii, binary_little_endian or binary_big_endian");
                        }
                    }
                    case "comment", "obj_info", "" -> {
                    }
                    case "element" -> {
                        if (words.length != 3) {
                            throw new MeshFormatException(file, line, "expected 'element NAME COUNT'");
                        }
                        long count;
                        try {
                            count = Long.parseLong(words[2]);
                        } catch (NumberFormatException e) {
                            count = -1;
                        }
                        if (count < 0 || count > Integer.MAX_VALUE) {
                            throw new MeshFormatException(file, line, "element '" + words[1] + "' has a count of '" + words[2]
                                    + "', not one of 0 to " + Integer.MAX_VALUE);
                        }
                        elements.add(new Element(words[1], count, new ArrayList<>(), line));
                    }
                    case "property" -> {
                        if (elements.isEmpty()) {
                            throw new MeshFormatException(file, line, "a property before any element");
                        }
                        Property property;
                        if (words.length == 5 && words[1].equals("list")) {
                            Type count = Type.named(words[2]);
                            Type item = Type.named(words[3]);
                            if (count == null || item == null) {
                                throw new MeshFormatException(file, line, "unknown type '" + (count == null ? words[2] : words[3]) + "'");
                            }
                            if (!count.integer) {
                                throw new MeshFormatException(file, line, "a list's count must be an integer type, not '" + words[2] + "'");
                            }
                            property = new Property(words[4], item, count, line);
                        } else if (words.length == 3) {
                            Type type = Type.named(words[1]);
                            if (type == null) {
                                throw new MeshFormatException(file, line, "unknown type '" + words[1] + "'");
                            }
                            property = new Property(words[2], type, null, line);
                        } else {
                            throw new MeshFormatException(file, line, "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
                        }
                        elements.get(elements.size() - 1).properties.add(property);
                    }
                    case "end_header" -> {
                        if (format == null) {
                            throw new MeshFormatException(file, line, "'end_header' before any 'format' line");
                        }
                        Header header = new Header(format, elements, pos, line + 1);
                        header.checkCounts(file, size);
                        return header;
                    }
                    default -> throw new MeshFormatException(file, line, "unknown header line '" + words[0]
                            + "': a PLY header has format, comment, obj_info, element, property and end_header");
                }
            }
        }

        /**
         * Refuses counts the file cannot hold before anything is kept: a binary element takes
         * at least its scalars' and list counts' bytes, an ASCII one a character and a space
         * for each property.
         */
        void checkCounts(Path file, long size) throws MeshFormatException {
            long left = size - bodyOffset;
            long least = 0;
            for (Element e : elements) {
                long each = format == Format.ASCII ? 2L * e.properties.size() : e.leastBinaryBytes();
                if (each > 0 && e.count > (left - least) / each) {
                    throw new MeshFormatException(file, e.line, String.format(Locale.ROOT,
                            "element '%s' claims %d, which take at least %d bytes; the file has %d after its header", e.name, e.count,
                            least + each * e.count, left));
                }
                least += each * e.count;
            }
        }
    }

}
