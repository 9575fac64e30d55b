/**
 * The desktop window ({@code ifold}, {@code ifold app [FILE]}): Swing with FlatLaf's look, a
 * thin shell over {@link ifold.ui.model} as the command line is over the core. The event
 * thread only edits and shows: planning and exports run on {@link ifold.ui.model.Worker}s,
 * and the 3D view renders on a thread of its own ({@link ifold.ui.SceneView}).
 */
package ifold.ui;
