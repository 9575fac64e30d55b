package ifold.check;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.util.Arrays;

/**
 * The folded state a FOLD file holds, read for the layer-order check: each vertex in space,
 * each face's vertices, and the file's {@code faceOrders}. The state is the file's first frame
 * whose {@code frame_classes} name {@code foldedForm} (the key frame or one of
 * {@code file_frames}, which takes the faces it lacks from the key frame), or else the key frame
 * if its vertices are in 3D. Only the keys needed are kept, in flat arrays.
 */
final class FoldedState {
    /** x, y, z of each vertex. */
    final double[] coords;
    final int vertexCount;
    /** Face f's vertices are {@code faceVertices[faceStart[f] .. faceStart[f + 1])}. */
    final int[] faceStart;
    final int[] faceVertices;
    final int faceCount;
    /** faceOrders as triples f, g, s: s = +1 where f lies on the side g's normal points to. */
    final int[] orders;

    private FoldedState(double[] coords, int[] faceStart, int[] faceVertices, int[] orders) {
        this.coords = coords;
        this.vertexCount = coords.length / 3;
        this.faceStart = faceStart;
        this.faceVertices = faceVertices;
        this.faceCount = faceStart.length - 1;
        this.orders = orders;
    }

    /** One frame's keys, as read. */
    private static final class Frame {
        double[] coords;
        int dimensions;
        int[] faceStart;
        int[] faceVertices;
        int[] orders;
        boolean folded;
    }

    static FoldedState read(CharSequence text) throws IOException {
        return read(new StringReader(text.toString()));
    }

    /** @throws IllegalArgumentException where the text is not a FOLD file with a folded state */
    static FoldedState read(Reader reader) throws IOException {
        try (JsonParser parser = new JsonFactory().createParser(reader)) {
            if (parser.nextToken() != JsonToken.START_OBJECT) {
                throw new IllegalArgumentException("not a FOLD file: it does not begin with a JSON object");
            }
            Frame key = new Frame();
            Frame chosen = null;
            while (parser.nextToken() == JsonToken.FIELD_NAME) {
                String name = parser.currentName();
                parser.nextToken();
                if (name.equals("file_frames") && parser.currentToken() == JsonToken.START_ARRAY) {
                    while (parser.nextToken() == JsonToken.START_OBJECT) {
                        Frame frame = new Frame();
                        while (parser.nextToken() == JsonToken.FIELD_NAME) {
                            String field = parser.currentName();
                            parser.nextToken();
                            field(parser, field, frame);
                        }
                        if (chosen == null && frame.folded) {
                            chosen = frame;
                        }
                    }
                } else {
                    field(parser, name, key);
                }
            }
            if (chosen == null) {
                if (!key.folded && key.dimensions != 3) {
                    throw new IllegalArgumentException("the FOLD file holds no folded state (no frame of class foldedForm)");
                }
                chosen = key;
            }
            double[] coords = chosen.coords != null ? chosen.coords : key.coords;
            int[] faceStart = chosen.faceStart != null ? chosen.faceStart : key.faceStart;
            int[] faceVertices = chosen.faceVertices != null ? chosen.faceVertices : key.faceVertices;
            int[] orders = chosen.orders != null ? chosen.orders : key.orders;
            if (coords == null || faceStart == null) {
                throw new IllegalArgumentException("the FOLD file's folded state has no vertices_coords or faces_vertices");
            }
            if ((chosen.coords != null ? chosen.dimensions : key.dimensions) != 3) {
                throw new IllegalArgumentException("the FOLD file's folded state is not in 3D");
            }
            int vertices = coords.length / 3;
            for (int v : faceVertices) {
                if (v < 0 || v >= vertices) {
                    throw new IllegalArgumentException("faces_vertices names vertex " + v + " of " + vertices);
                }
            }
            int faces = faceStart.length - 1;
            orders = orders == null ? new int[0] : orders;
            for (int i = 0; i < orders.length; i += 3) {
                if (orders[i] < 0 || orders[i] >= faces || orders[i + 1] < 0 || orders[i + 1] >= faces
                        || Math.abs(orders[i + 2]) != 1) {
                    throw new IllegalArgumentException("faceOrders entry " + i / 3 + " is not [face, face, ±1]");
                }
            }
            return new FoldedState(coords, faceStart, faceVertices, orders);
        }
    }

    private static void field(JsonParser parser, String name, Frame frame) throws IOException {
        switch (name) {
            case "vertices_coords" -> readCoords(parser, frame);
            case "faces_vertices" -> readFaces(parser, frame);
            case "faceOrders" -> frame.orders = readTriples(parser);
            case "frame_classes" -> {
                if (parser.currentToken() == JsonToken.START_ARRAY) {
                    while (parser.nextToken() != JsonToken.END_ARRAY) {
                        frame.folded |= parser.currentToken() == JsonToken.VALUE_STRING && parser.getText().equals("foldedForm");
                        parser.skipChildren();
                    }
                }
            }
            default -> parser.skipChildren();
        }
    }

    private static void readCoords(JsonParser parser, Frame frame) throws IOException {
        expect(parser, JsonToken.START_ARRAY, "vertices_coords");
        double[] values = new double[3 * 64];
        int n = 0;
        int dimensions = -1;
        while (parser.nextToken() == JsonToken.START_ARRAY) {
            int d = 0;
            while (parser.nextToken() != JsonToken.END_ARRAY) {
                if (!parser.currentToken().isNumeric()) {
                    throw new IllegalArgumentException("vertices_coords holds something other than numbers");
                }
                if (d < 3) {
                    if (n + 3 > values.length) {
                        values = Arrays.copyOf(values, 2 * values.length);
                    }
                    values[n + d] = parser.getDoubleValue();
                }
                d++;
            }
            if (dimensions >= 0 && d != dimensions) {
                throw new IllegalArgumentException("vertices_coords mixes points of " + dimensions + " and " + d + " coordinates");
            }
            dimensions = d;
            n += 3;
        }
        frame.coords = Arrays.copyOf(values, n);
        frame.dimensions = dimensions < 0 ? 3 : dimensions;
    }

    private static void readFaces(JsonParser parser, Frame frame) throws IOException {
        expect(parser, JsonToken.START_ARRAY, "faces_vertices");
        int[] start = new int[65];
        int[] vertices = new int[256];
        int faces = 0;
        int n = 0;
        while (parser.nextToken() == JsonToken.START_ARRAY) {
            int corners = 0;
            while (parser.nextToken() != JsonToken.END_ARRAY) {
                if (parser.currentToken() != JsonToken.VALUE_NUMBER_INT) {
                    throw new IllegalArgumentException("faces_vertices holds something other than vertex numbers");
                }
                if (n == vertices.length) {
                    vertices = Arrays.copyOf(vertices, 2 * n);
                }
                vertices[n++] = parser.getIntValue();
                corners++;
            }
            if (corners < 3) {
                throw new IllegalArgumentException("face " + faces + " of faces_vertices has " + corners + " vertices");
            }
            if (faces + 2 > start.length) {
                start = Arrays.copyOf(start, 2 * start.length);
            }
            start[++faces] = n;
        }
        frame.faceStart = Arrays.copyOf(start, faces + 1);
        frame.faceVertices = Arrays.copyOf(vertices, n);
    }

    private static int[] readTriples(JsonParser parser) throws IOException {
        expect(parser, JsonToken.START_ARRAY, "faceOrders");
        int[] values = new int[3 * 64];
        int n = 0;
        while (parser.nextToken() == JsonToken.START_ARRAY) {
            int d = 0;
            while (parser.nextToken() != JsonToken.END_ARRAY) {
                if (parser.currentToken() != JsonToken.VALUE_NUMBER_INT || d >= 3) {
                    throw new IllegalArgumentException("faceOrders entry " + n / 3 + " is not [face, face, ±1]");
                }
                if (n + 3 > values.length) {
                    values = Arrays.copyOf(values, 2 * values.length);
                }
                values[n + d++] = parser.getIntValue();
            }
            if (d != 3) {
                throw new IllegalArgumentException("faceOrders entry " + n / 3 + " is not [face, face, ±1]");
            }
            n += 3;
        }
        return Arrays.copyOf(values, n);
    }

    private static void expect(JsonParser parser, JsonToken token, String what) {
        if (parser.currentToken() != token) {
            throw new IllegalArgumentException(what + " is not a list");
        }
    }

    double x(int v) {
        return coords[3 * v];
    }

    double y(int v) {
        return coords[3 * v + 1];
    }

    double z(int v) {
        return coords[3 * v + 2];
    }
}
