/**
 * The only package that talks to OpenGL (through JOGL): draws a {@link ifold.scene.Scene} with
 * the OpenGL 3.3 core profile (buffers and GLSL shaders, no immediate mode), in a window with a
 * virtual trackball or offscreen into frames. Works on Mesa's llvmpipe and on any GPU.
 */
package ifold.render;
