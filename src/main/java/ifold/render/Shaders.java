package ifold.render;

/** The GLSL sources: one program for faces, one for edges. GLSL 3.30 core. */
final class Shaders {
    private Shaders() {
    }

    static final String FACE_VERTEX = """
            #version 330 core
            layout(location = 0) in vec3 position;
            layout(location = 1) in vec3 normal;
            layout(location = 2) in vec4 color;
            layout(location = 3) in float order;
            uniform mat4 modelView;
            uniform mat4 projection;
            uniform mat3 normalMatrix;
            out vec3 vNormal;
            out vec4 vColor;
            flat out float vOrder;
            void main() {
                vNormal = normalMatrix * normal;
                vColor = color;
                vOrder = order;
                gl_Position = projection * modelView * vec4(position, 1.0);
            }
            """;

    // Paper has two sides: the back gets its own colour, and its normal is turned round so that
    // it is lit as the side facing the viewer.
    static final String FACE_FRAGMENT = """
            #version 330 core
            in vec3 vNormal;
            in vec4 vColor;
            flat in float vOrder;
            uniform vec3 lightDirection[2];
            uniform float lightIntensity[2];
            uniform float ambient;
            uniform vec4 frontColor;
            uniform vec4 backColor;
            uniform vec4 hiddenColor;
            uniform bool useFaceColors;
            uniform float revealed;
            out vec4 fragColor;
            void main() {
                vec3 n = normalize(vNormal);
                vec4 base;
                if (vOrder >= revealed) {
                    base = hiddenColor;
                } else if (gl_FrontFacing) {
                    base = useFaceColors ? vColor : frontColor;
                } else {
                    base = backColor;
                }
                if (!gl_FrontFacing) {
                    n = -n;
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
            layout(location = 1) in vec4 color;
            uniform mat4 modelView;
            uniform mat4 projection;
            out vec4 vColor;
            void main() {
                vColor = color;
                gl_Position = projection * modelView * vec4(position, 1.0);
            }
            """;

    static final String EDGE_FRAGMENT = """
            #version 330 core
            in vec4 vColor;
            out vec4 fragColor;
            void main() {
                fragColor = vColor;
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
