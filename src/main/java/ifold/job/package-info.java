/**
 * What the front ends share, the command line and the window alike: a triangle read from text,
 * the figures of a result as the {@code --report} JSON holds them, the scene and animation that
 * show it, and the JSON writer. Plain Java: no AWT, no GL, no picocli; so the window's report
 * and pictures are the command line's, computed once.
 */
package ifold.job;
