/**
 * The scenegraph: what the viewer shows, in plain Java (JOML for the math), testable without a
 * display. After jMonkeyEngine: an abstract {@link ifold.scene.Spatial} with inner
 * {@link ifold.scene.Node}s and leaf {@link ifold.scene.Geometry}. World transforms are
 * recomputed lazily when a node above changed; every change marks the path up to the root, so
 * the renderer redraws only when something changed and re-uploads only geometry whose version
 * moved. A scene bound to a render thread refuses changes from any other thread.
 */
package ifold.scene;
