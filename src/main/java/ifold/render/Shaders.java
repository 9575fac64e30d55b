package ifold.render;

/** The GLSL sources: one program for faces, one for edges. GLSL 3.30 core. */
final class Shaders {
    private Shaders() {
    }

    // Vertices are shared between triangles, so a vertex has no face normal and no face colour:
    // the fragment shader takes the normal from the screen-space derivatives of the position
    // (flat shading) and the colour from a buffer texture indexed by gl_PrimitiveID. That makes
    // six times fewer vertices to shade than unshared flat-shaded triangles, which matters on
    // a software renderer.
    static final String FACE_VERTEX = """
            #version 330 core
            layout(location = 0) in vec3 position;
            uniform mat4 modelView;
            uniform mat4 projection;
            out vec3 viewPosition;
            void main() {
                vec4 p = modelView * vec4(position, 1.0);
                viewPosition = p.xyz;
                gl_Position = projection * p;
            }
            """;

    // Paper has two sides: the back gets its own colour; both sides are lit as the side facing
    // the viewer.
    static final String FACE_FRAGMENT = """
            #version 330 core
            in vec3 viewPosition;
            uniform samplerBuffer triangleColors;
            uniform vec3 lightDirection[2];
            uniform float lightIntensity[2];
            uniform float ambient;
            uniform vec4 frontColor;
            uniform vec4 backColor;
            uniform vec4 hiddenColor;
            uniform bool useFaceColors;
            uniform int revealed;
            uniform int primitiveBase;
            out vec4 fragColor;
            void main() {
                int triangle = gl_PrimitiveID + primitiveBase; // drawn in runs of chunks
                vec3 n = normalize(cross(dFdx(viewPosition), dFdy(viewPosition)));
                if (dot(n, viewPosition) > 0.0) {
                    n = -n;
                }
                vec4 base;
                // Where the hidden colour is clear, the triangles not yet revealed are not drawn
                // at all (and revealed is then past them all). No discard: a shader that may
                // discard keeps a software renderer from testing depth before shading, and a
                // wrap is layer over layer.
                if (triangle >= revealed) {
                    // Unlit: one flat tone, so that no shading makes a triangle not yet revealed
                    // look like one of the revealed, which are shaded.
                    fragColor = hiddenColor;
                    return;
                } else if (gl_FrontFacing) {
                    base = useFaceColors ? texelFetch(triangleColors, triangle) : frontColor;
                } else {
                    base = backColor;
                }
                float light = ambient;
                for (int i = 0; i < 2; i++) {
                    light += lightIntensity[i] * max(dot(n, lightDirection[i]), 0.0);
                }
                fragColor = vec4(min(base.rgb * light, vec3(1.0)), base.a);
            }
            """;

    static final String EDGE_VERTEX = """
            #version 330 core
            layout(location = 0) in vec3 position;
            uniform mat4 modelView;
            uniform mat4 projection;
            void main() {
                gl_Position = projection * modelView * vec4(position, 1.0);
            }
            """;

    static final String EDGE_FRAGMENT = """
            #version 330 core
            uniform samplerBuffer edgeColors;
            out vec4 fragColor;
            void main() {
                fragColor = texelFetch(edgeColors, gl_PrimitiveID);
            }
            """;

    /** Writes the index of the triangle plus one into red, green and blue: 0 is the background. */
    static final String INDEX_FRAGMENT = """
            #version 330 core
            uniform int primitiveBase;
            out vec4 fragColor;
            void main() {
                int id = gl_PrimitiveID + primitiveBase + 1;
                fragColor = vec4(float((id >> 16) & 255), float((id >> 8) & 255), float(id & 255), 255.0) / 255.0;
            }
            """;

    static final String OVERLAY_VERTEX = """
            #version 330 core
            layout(location = 0) in vec2 position;
            layout(location = 1) in vec2 texCoord;
            out vec2 vTexCoord;
            void main() {
                vTexCoord = texCoord;
                gl_Position = vec4(position, 0.0, 1.0);
            }
            """;

    static final String OVERLAY_FRAGMENT = """
            #version 330 core
            in vec2 vTexCoord;
            uniform sampler2D image;
            out vec4 fragColor;
            void main() {
                fragColor = texture(image, vTexCoord);
            }
            """;
}
